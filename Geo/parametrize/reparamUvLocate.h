// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Where a point of the (u, v) plane lies on a discrete face whose (u, v)
// image is not convex. Gmsh's planar meshers mesh the polygon of the face's
// boundary nodes; on the free boundary of a conformal map that polygon's
// chords cut across concave stretches of the image, so the mesher asks for
// points, normals and derivatives just outside the parametrized triangles.
// Gmsh's discreteFace answered "not found" (with an arbitrary normal), which
// made Frontal-Delaunay's mesh invalid and Gmsh throw it away for MeshAdapt
// (bench/README.md, Points just outside the (u, v) triangles). The hook
// (patches/0007) takes such points on the closest triangle instead.
//
// The points inside are located by a tree of the (u, v) triangles' boxes
// (Mesh/core/uvTriangleTree.h) in place of Gmsh's octree (patches/0021), built
// with the face's parametrization when Reparam's maps are on; Gmsh's own
// map (Mesh.CompoundParametrization = 0) keeps the octree.

#ifndef REPARAM_UV_LOCATE_H
#define REPARAM_UV_LOCATE_H

#include <functional>
#include <vector>

class MElement;
class MElementOctree;
class MTriangle;
class reparamUvLocator;

class SPoint2;
class SPoint3;

namespace reparam {

// discreteFace::parFromPoint's answer for p: search(p) (its closest point
// on the face), kept per point by the locator, as it does not change and
// the mesher asks it again for every curve node next to a node it smooths;
// search(p) every time without a locator (Gmsh's own map)
} // namespace reparam

SPoint2

#endif
