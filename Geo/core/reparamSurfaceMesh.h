// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A face of Gmsh's model as the plain arrays Mesh/ works on: its new mesh,
// or the input triangulation it was parametrized from.

#ifndef REPARAM_SURFACE_MESH_H
#define REPARAM_SURFACE_MESH_H

#include "surfaceMesh.h"

class GFace;

namespace reparam {

// The triangles and quadrangles of a meshed face, on its nodes numbered in
// the order its elements first use them
surfaceMesh surfaceMeshOf(const GFace *gf);

// The input triangulation a discrete face was parametrized from (Gmsh keeps
// it in GFace::stl_vertices_xyz / stl_triangles)
surfaceMesh inputTriangulationOf(const GFace *gf);

} // namespace reparam

#endif
