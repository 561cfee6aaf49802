// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Repair of the few triangles of a face's new mesh that point against the
// input under them: on scans they lie across folds thinner than the mesh
// size (lips, ridges), their corners on both sides of the fold
// (bench/README.md, Elements against the input). Each of their inner edges is tried split at its
// midpoint in (u, v), whose image lies on the surface, on the fold (the
// four triangles stay valid in (u, v): the midpoint of an edge of two valid
// triangles always gives four), and flipped (if both new triangles keep
// their (u, v) orientation); the change that leaves the fewest triangles
// against the input is kept, if fewer than before. Boundary edges are never
// changed: they belong to the curve's mesh, shared with the next face.
// Then their inner corners are tried at the (u, v) centroid of their
// neighbours, kept there if fewer of their triangles point against the
// input and all stay valid in (u, v).

#ifndef INVERTED_ELEMENT_REPAIR_H
#define INVERTED_ELEMENT_REPAIR_H

#include <cstddef>
#include <functional>

class GFace;
class MTriangle;

namespace reparam {

struct invertedRepair {
  std::size_t before = 0, after = 0; // triangles against the input
  std::size_t changes = 0, passes = 0; // edge splits and flips kept
  std::size_t moves = 0; // inner nodes moved
};

// Splits or flips edges of the triangles `against` says point against the
// input,
// pass after pass, until none is left or a pass keeps no change (at most
// maxPasses). `against` sees the mesh in the orientation most of its
// triangles have along the input.
invertedRepair
splitInvertedTriangles(GFace *gf, const std::function<bool(MTriangle *)> &against,
                       int maxPasses = 6);

} // namespace reparam

#endif
