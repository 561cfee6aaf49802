// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A face whose Delaunay or Frontal-Delaunay mesh leaves a hole, or keeps
// triangles against the input after the local repairs, gets a mesh from the
// other of the two, kept when it has fewer defects. Gmsh remeshes every
// such face with MeshAdapt, some 10 times slower and no better there; where
// Gmsh would still remesh with MeshAdapt, its mesh is compared too, not
// taken blindly (bench/README.md, Elements against the input).
// A face the planar mesher left nearly empty (edges longer than twice the
// size) is compared with MeshAdapt's mesh (Geo/planar/reparamMeshValidity.h).
// Quadrangle meshes too: the other mesher's is recombined the same way.

#ifndef REPARAM_MESHER_FALLBACK_H
#define REPARAM_MESHER_FALLBACK_H

#include <cstddef>
#include <string>

class GFace;

namespace reparam {

// What is wrong with a face's mesh, worst first
struct meshDefects {
  std::size_t unusedCurveSegments = 0; // holes
  std::size_t againstInput = 0;
  std::size_t longEdges = 0; // a face the mesher did not fill
  bool operator<(const meshDefects &o) const
  {
    if(unusedCurveSegments != o.unusedCurveSegments)
      return unusedCurveSegments < o.unusedCurveSegments;
    if(againstInput != o.againstInput) return againstInput < o.againstInput;
    return longEdges < o.longEdges;
  }
};

// "1 segment of its curves unused, 2 triangles against the input" (with
// `element` for the elements' name)
std::string meshDefectsText(const meshDefects &d,
                            const char *element = "triangle");

// gf's elements (triangles, or quadrangles and the triangles Blossom
// left) against its input, counted against the orientation most of them
// have: the optimizer's count when it optimized the current triangle mesh,
// else searched
std::size_t countTrianglesAgainstInput(GFace *gf);

// Meshes gf (Reparam parametrized, its current mesh with the defects
// `current`) with `algorithm` (Mesh.Algorithm's values; 0: Delaunay, or
// Frontal-Delaunay if that was gf's), then optimizes it
// (Mesh.CompoundOptimize); keeps that mesh and returns true if it has fewer
// defects, else puts the current mesh back (both logged)
bool reparamTryOtherMesher(GFace *gf, const meshDefects &current,
                           int algorithm = 0);

// Whether this thread is meshing a face for reparamTryOtherMesher: the
// validity hook leaves the comparison to it
bool reparamTryingOtherMesher();

} // namespace reparam

#endif
