// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// How faithful a new surface mesh is to the triangulation it was made from:
// two-sided distances (sampled Hausdorff and mean) and the elements whose
// orientation disagrees with the input normals (SPEC.md sec. 5).

#ifndef MESH_FIDELITY_H
#define MESH_FIDELITY_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "surfaceMesh.h"

namespace reparam {

struct meshFidelity {
  std::size_t elements = 0;
  // elements whose normal points against the input under them: the sum of
  // the unit normals of the input triangles closest to their centroid and to
  // the points halfway from it to their corners
  std::size_t inverted = 0;
  // two-sided distances over samples (nodes and element centroids of both
  // meshes), absolute; diagonal of the input's bounding box to relate them
  double hausdorff = 0., meanDistance = 0., diagonal = 0.;
  // where the Hausdorff distance is reached, and on which side: a sample of
  // the input far from the mesh (a corner or tip cut off) or of the mesh far
  // from the input (a chord across a crease, a fold)
  SPoint3 farthest;
  bool farthestOnInput = false;
};

// The meshes as one (nodes repeated where faces meet: harmless for
// distances and orientation), quadrangles cut in two triangles; the mesh
// each node and element came from in `pointPart` and `elementPart`
surfaceMesh unionAsTriangles(const std::vector<surfaceMesh> &meshes,
                             std::vector<int> *pointPart = nullptr,
                             std::vector<int> *elementPart = nullptr);

// (knownInverted: meshFidelity::inverted as already counted, not searched)
meshFidelity compareToInput(const surfaceMesh &input, const surfaceMesh &output,
                            const std::size_t *knownInverted = nullptr);

// Only the two-sided distances (no inverted count) of several meshed faces
// against their inputs taken together: the whole model's Hausdorff
// distance. Face by face, an input node on a curve between two faces is as
// far from its own face's mesh as the curve's chords are from the input's
// zig-zag along it, while the neighbour's mesh covers it (bench/README.md,
// "Report"). With perMesh, also each face's
// samples (its nodes and centroids, its input's) against the whole, in one
// search.
meshFidelity
compareDistancesToInput(const std::vector<surfaceMesh> &inputs,
                        const std::vector<surfaceMesh> &outputs,
                        std::vector<meshFidelity> *perMesh = nullptr);

// Whether the triangle (a, b, c) points against the input under it (the
// test meshFidelity::inverted counts with)
class closestTriangleSearch;
bool triangleAgainstInput(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c,
                          const surfaceMesh &input,
                          const closestTriangleSearch &onInput);
// The same, given the input's closest point to the triangle's centroid (a
// caller measuring the triangle's distance to the input has it)
struct closestTriangleHit;
bool triangleAgainstInput(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c,
                          const surfaceMesh &input,
                          const closestTriangleSearch &onInput,
                          const closestTriangleHit &atCentroid);

// The same for the quadrangle (a, b, c, d), its normal its diagonals'
// cross product
bool quadrangleAgainstInput(const SPoint3 &a, const SPoint3 &b,
                            const SPoint3 &c, const SPoint3 &d,
                            const surfaceMesh &input,
                            const closestTriangleSearch &onInput);

// Only meshFidelity::inverted (N + 1 closest-triangle searches per element
// of N corners)
std::size_t countInverted(const surfaceMesh &input, const surfaceMesh &output);

// The elements meshFidelity::inverted counts, by index (triangles first,
// then quadrangles)
std::vector<std::size_t> invertedElements(const surfaceMesh &input,
                                          const surfaceMesh &output);

} // namespace reparam

#endif
