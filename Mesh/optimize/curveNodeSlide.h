// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A node of a curve's 1D mesh slid along the curve's input polyline. The
// optimization on the input moves inner nodes only: the nodes of the
// feature curves and borders stay where the 1D mesher put them, and most
// triangles below kappa 0.3 on the shared meshes have a node on a curve
// (a short segment next to a long one, a corner's fan). Sliding such a node
// between its two neighbours along the curve keeps the curve where it is
// and can lift the worst triangle around it.

#ifndef CURVE_NODE_SLIDE_H
#define CURVE_NODE_SLIDE_H

#include <array>
#include <vector>
#include "SPoint3.h"

namespace reparam {

struct curveNodeRing {
  // the curve's input polyline (node i at parameter i)
  std::vector<SPoint3> polyline;
  // the node's parameter and its neighbours' along the curve
  double t = 0., before = 0., after = 0.;
  // the triangles around the node, as their two other corners in the
  // triangle's order (node, a, b)
  std::vector<std::array<SPoint3, 2> > opposite;
};

struct curveNodeSlide {
  double t = 0.; // the new parameter (the old one if no slide is better)
  double worstBefore = 1., worstAfter = 1.; // kappa of the ring
};

// The parameter strictly between the neighbours' where the worst kappa of
// the ring is highest, among an eighth of the way between them steps and
// the polyline's nodes there: taken if it beats the worst kappa now by
// `gain`, the ring's kappa summed falls by no more than its worst gains
// unless that is below 0.3 (either rule alone lost a mesh its kappa mean or
// its worst: bench/README.md, Curve nodes slid along their curves), no
// triangle's normal turns by more than `maxTurn` (radians; 0:
// none turns over), and the polyline between the node and each neighbour
// stays within `sag` times the segment's length of it (or no farther than
// it was: a node on a corner of the polyline stays there)
curveNodeSlide slideCurveNode(const curveNodeRing &ring, double gain = 1e-3,
                              double maxTurn = 0.5, double sag = 0.05);

// The same, for the ring's mean kappa: the parameter among the same
// candidates where it is highest, taken if it beats the mean now by `gain`
// and neither the worst kappa of the ring nor any of its triangles below
// `target` gets worse (the rows of triangles along the curves, which the
// moves of inner nodes leave uneven: on the CAD parts most of what keeps
// kappa mean from 1 is in triangles with a corner on a curve)
curveNodeSlide slideCurveNodeForMean(const curveNodeRing &ring,
                                     double target = 0.6, double gain = 1e-3,
                                     double maxTurn = 0.5, double sag = 0.05);

// For fidelity: the polyline's node strictly between the neighbours'
// farthest from the node's chords to them, where farther than `share`
// times that chord's length (the 1D mesh cuts a tip or a crease of the
// curve off; the optimization inserts the input nodes a face's mesh cuts
// off, but a curve's are on no face's inside), taken if the chords then
// pass closer to the polyline, the worst kappa of the ring stays at or
// above the lower of its worst now and `floor`, and no triangle's normal
// turns by more than maxTurn
curveNodeSlide slideCurveNodeToFarthest(const curveNodeRing &ring,
                                        double share = 0.25,
                                        double floor = 0.5,
                                        double maxTurn = 0.5);

// Whether the chords from a node at parameter t of the polyline to its
// neighbours at `before` and `after` follow the polyline within sag times
// their length, or no worse than from where it was (a node on a corner of
// the polyline stays there)
bool chordsFollowPolyline(const std::vector<SPoint3> &polyline, double was,
                          double t, double before, double after, double sag);

// The point of the polyline at parameter t (node i at i)
SPoint3 pointOnPolyline(const std::vector<SPoint3> &polyline, double t);

} // namespace reparam

#endif
