// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Where a point of the (u, v) plane lies on a discrete face whose (u, v)
// image is not convex. Gmsh's planar meshers mesh the polygon of the face's
// boundary nodes; on the free boundary of a conformal map that polygon's
// chords cut across concave stretches of the image, so the mesher asks for
// points, normals and derivatives just outside the parametrized triangles.
// Gmsh's discreteFace answered "not found" (with an arbitrary normal), which
// made Frontal-Delaunay's mesh invalid and Gmsh throw it away for MeshAdapt
// (camelhead: 35 s, 27 elements against the input). The hook
// (patches/0007) takes such points on the closest triangle instead.

#ifndef REPARAM_UV_LOCATE_H
#define REPARAM_UV_LOCATE_H

#include <vector>

class MTriangle;

// The triangle of t2d (a discrete face's (u, v) triangles) closest to
// (u, v), which is moved onto it; null if t2d is empty. Meant for points
// outside every triangle: it only searches the triangles on the boundary.
MTriangle *reparamClosestUvTriangle(const std::vector<MTriangle> &t2d,
                                    double &u, double &v);

#endif
