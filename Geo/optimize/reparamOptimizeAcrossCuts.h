// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The meshes of the faces a patch was cut into, optimized as one
// (Mesh.CompoundOptimize; hook in GenerateMesh after the 2D meshes,
// patches/0013). The layout cuts a closed, pinched or too distorted patch
// into disks along input edges, and Gmsh meshes each disk on its own: the
// cut curves' zig-zag nodes and segments are frozen in the final mesh, and
// the per-face optimization (Geo/optimize/reparamOptimizeFace.h) cannot move a node
// of them or flip an edge along them, where the conformal maps are most
// distorted. Here the faces joined by smooth cuts (curves along no sharp,
// border nor non-manifold input edge, Geo/curves/reparamCurveMesh.h) are optimized
// together on their input: cut nodes move off the cut (becoming nodes of the
// face whose input they land on), edges along it flip, and each triangle goes
// to the face whose input is under its centroid. A cut curve the mesh no longer
// follows keeps no 1D elements: the surface there is the feature patch the
// cut parts came from.

#ifndef REPARAM_OPTIMIZE_ACROSS_CUTS_H
#define REPARAM_OPTIMIZE_ACROSS_CUTS_H

#include <functional>
#include <set>
#include <vector>

class GEdge;
class GFace;
class GModel;

namespace reparam {

// Faces joined by smooth cut curves, with those curves
struct cutGroup {
  std::vector<GFace *> faces;
  std::vector<GEdge *> cuts;
};

// The faces of m that `member` accepts, joined into groups by the curves
// between two of them that `joins` accepts; each group with those of its
// curves that `crossable` accepts (the mesh may cross them: smooth cuts,
// Geo/curves/reparamCurveMesh.h). A face joined to none is a group of its own if
// `alone`, else in no group
std::vector<cutGroup>
facesJoinedBy(GModel *m, const std::function<bool(GFace *)> &member,
              const std::function<bool(GEdge *)> &joins, bool alone,
              const std::function<bool(GEdge *)> &crossable);

// The groups of m's triangle-meshed discrete faces Reparam parametrized
// joined by smooth cut curves or by noiseCurves, the curves of faces that
// are noise at the mesh scale (Geo/layout/reparamNoiseFaces.h); each group has a
// crossable curve and two faces or more
std::vector<cutGroup> facesJoinedByCuts(GModel *m,
                                        const std::set<GEdge *> &noiseCurves);

} // namespace reparam

#endif
