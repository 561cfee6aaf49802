// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The quadrangles of the faces Reparam parametrized, squared up on their
// input after the 2D mesh (Mesh.CompoundOptimize; from
// reparamOptimizeMeshedModel, Geo/optimize/reparamOptimizeAcrossCuts.h): the faces
// joined by curves together, the nodes of their smooth cut curves moving
// across the cuts, those of their feature curves and borders sliding along
// the curves' input polylines (Mesh/quad/quadNodeSmoothing.h). A cut node moved
// off its cut becomes a node of the face whose input it lands on, and the
// cut keeps no 1D element; the elements stay in their faces.

#ifndef REPARAM_SMOOTH_QUADS_H
#define REPARAM_SMOOTH_QUADS_H

class GModel;

namespace reparam {

// Returns the number of groups of faces changed (logged, reports updated)
int reparamSmoothQuadMeshes(GModel *m);

} // namespace reparam

#endif
