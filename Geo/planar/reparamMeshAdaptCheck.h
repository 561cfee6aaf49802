// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A MeshAdapt mesh of a face Reparam parametrized, checked as the
// Delaunay-based meshers' are (Geo/planar/reparamMeshValidity.h). Gmsh tests only
// those (and remeshes a failed one with MeshAdapt); a mesh the user asked
// MeshAdapt for was kept whatever it was, with dozens of triangles against
// the input where a hole runs close along a border, while Delaunay's mesh
// of that face has none (bench/README.md, MeshAdapt's meshes checked).

#ifndef REPARAM_MESHADAPT_CHECK_H
#define REPARAM_MESHADAPT_CHECK_H

class GFace;

#endif
