// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Sharp edges that are sharp at the input's own scale only: the terraces of
// a voxel mask surfaced by marching cubes, the ridges of scan noise. Each
// step of a staircase turns the surface one way and the next step turns it
// back within a voxel or two, so ClassifySurfaces' dihedral test cuts such
// inputs into thousands of feature patches whose curves force the mesh to
// the voxel's size. Seen from farther away, the surface's normal on either
// side of such an edge is the same; on either side of a CAD edge it is not,
// at any distance. An edge stays a feature when the normals averaged over a
// disk on each side of it still make at least half its own angle.

#ifndef FEATURE_SCALE_H
#define FEATURE_SCALE_H

#include <vector>
#include "patchLayout.h"

namespace reparam {

struct triangleAdjacency;

// The angle (radians) between the area-weighted mean normals of the
// triangles on either side of manifold edge e whose centroids lie within
// `radius` of its middle (reached from its two triangles across manifold
// edges; the two always counted), the sides parted by the plane through the
// edge along the bisector of its two triangles' normals; -1 when the sides
// are not defined (a boundary or non-manifold edge, a fin whose triangles
// nearly fold onto each other, a degenerate triangle)
double dihedralAtScale(const layoutMesh &mesh,
                       const triangleAdjacency &adjacency, int e,
                       double radius);

// Clears featureEdge[e] for every manifold edge e whose dihedral angle at
// `radius` is less than half its own; returns how many were cleared
std::size_t dropFeaturesBelowScale(const layoutMesh &mesh,
                                   const triangleAdjacency &adjacency,
                                   double radius,
                                   std::vector<char> &featureEdge);

} // namespace reparam

#endif
