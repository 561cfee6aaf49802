// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Faces that are noise at the mesh scale. The patch layout merges the
// feature patches narrower than an eighth of its noise size into a
// neighbour (Mesh/layout/patchLayout.h), but it runs before the mesh size is
// known and takes the input's own edge for it: on a scan remeshed coarser
// than its input, a patch a few input triangles wide between sharp edges
// stays a face of its own, and its curves' nodes leave it slivers no
// optimizer may change (bench/README.md, Faces that are noise at the mesh
// scale). Once the faces are meshed the size h is
// known. A strip of width w crossed by triangles of edge h along it has
// kappa at best 2 sqrt(3) w h / (1.5 h^2 + 2 w^2): below 0.5 for w < h / 4
// (0.53 at h / 4, 0.28 at h / 8). The curves of a face narrower than that
// become crossable, like the layout's cuts, so that the optimization across
// cuts (Geo/optimize/reparamOptimizeAcrossCuts.h) flips and moves across them: the
// face is then the sharp edges' noise at the size of the mesh, and the
// mesh passes within its width of them.

#ifndef REPARAM_NOISE_FACES_H
#define REPARAM_NOISE_FACES_H

#include <set>

class GEdge;
class GFace;
class GModel;

namespace reparam {
struct surfaceMesh;

// Twice the area of a triangulation over the length of its boundary (its
// width, as the layout's noise test measures it); 0 for none, a huge value
// when closed
double triangulationWidth(const surfaceMesh &mesh);

// The curves between two faces the optimizers may change of which one is
// noise at the scale of its mesh: narrower (triangulationWidth of its
// input) than a quarter of the mean edge of the meshes of the faces it
// shares a curve with; logged. A curve with a third side (a face on both
// sides of it and a fin on it) is non-manifold and never crossed
std::set<GEdge *> reparamNoiseFaceCurves(GModel *m);

} // namespace reparam

#endif
