// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The hook Gmsh's meshGEdge calls on a curve's new 1D nodes (patches/0010):
// on the discrete curves of a classified triangulation, nodes are moved
// onto the input polyline's corners (Mesh/curves/curveCornerSnap.h) so that
// neither the curve's segments nor the surface meshes on both sides cut
// them.

#ifndef REPARAM_CURVE_MESH_H
#define REPARAM_CURVE_MESH_H

#include <array>
#include <vector>
#include "SPoint3.h"

class GEdge;
class MVertex;

namespace reparam {

// The cuts of the last patch layout across smooth parts of the surface
// (node pairs, by their coordinates): a curve made of them follows the
// input's edges where nothing is sharp, so its turns are no corners of the
// surface and its nodes are left where Gmsh puts them
void reparamRecordSmoothCuts(const std::vector<std::array<SPoint3, 2> > &edges);

// The input edges of the last patch layout that no mesh may cross: its
// sharp edges (Gmsh's classification lines), borders and non-manifold
// edges (node pairs, by their coordinates)
void reparamRecordFixedEdges(const std::vector<std::array<SPoint3, 2> > &edges);

// Whether discrete curve ge runs along none of those edges: a cut of the
// layout across a smooth part of the surface, that the mesh may cross once
// the faces are meshed (Geo/optimize/reparamOptimizeAcrossCuts.h). It is not always
// the layout's own cut: Gmsh's classification may end the patches a
// triangle off it
bool reparamIsCrossableCurve(GEdge *ge);

// The input polyline of a discrete curve, whose parameter runs over its
// nodes (node i at i); false for another kind of curve
bool reparamInputPolyline(GEdge *ge, std::vector<SPoint3> &polyline);

} // namespace reparam

#endif
