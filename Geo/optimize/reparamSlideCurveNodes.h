// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The last step of the optimization on the input (Mesh.CompoundOptimize,
// called at the end of reparamOptimizeMeshedModel, after the faces and the
// groups joined by cuts were optimized): nodes of the discrete feature
// curves and borders slid along their input polylines
// (Mesh/optimize/curveNodeSlide.h) where a triangle around them, in any of the faces
// the curve bounds, is below kappa 0.6. The optimizers before never move a
// node of such a curve, and the 1D mesher places them without looking at
// the faces: a segment next to a much shorter one of the next curve at a
// corner, a node a hair off the line of its neighbours.

#ifndef REPARAM_SLIDE_CURVE_NODES_H
#define REPARAM_SLIDE_CURVE_NODES_H

class GModel;

namespace reparam {

// Slides the nodes of m's discrete curves: first onto the polyline's
// nodes their chords pass farther than a quarter of their length from
// (Mesh/optimize/curveNodeSlide.h, slideCurveNodeToFarthest), then, in two sweeps,
// those whose worst triangle around is below kappa 0.6 where it raises
// that worst kappa, then, in two more, every node where the ring's mean
// kappa rises; each where no triangle turns over (nor by more than 30
// degrees, 57 onto a polyline's node), none changes sides with the input
// (against it or not) and the curve's segments follow its polyline; only
// between faces Reparam parametrized, meshed with triangles, not kept as
// their input. Logs what it did; returns how many nodes moved
int reparamSlideCurveNodes(GModel *m);

} // namespace reparam

#endif
