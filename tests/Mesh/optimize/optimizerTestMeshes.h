// Reparam - meshes and measures the tests of Mesh/optimize share: grids
// lifted on a smooth bump or a roof, as meshes to optimize, and how far they
// are from their input

#ifndef OPTIMIZER_TEST_MESHES_H
#define OPTIMIZER_TEST_MESHES_H

#include <cstddef>
#include "closestTriangle.h"
#include "optimizableMesh.h"
#include "testPatches.h"

namespace optimizeTest {

  using namespace reparam;

  // t to optimize: nodes off the border movable
  optimizableMesh optimizable(const testTriangulation &t);

  // The largest distance of m's points to the input searched by onInput
  double largestDistance(const optimizableMesh &m,
                         const closestTriangleSearch &onInput);

  // How many triangles of m point against the input
  std::size_t againstCount(const optimizableMesh &m, const surfaceMesh &input,
                           const closestTriangleSearch &onInput);

  // Each node of t lifted onto z = 0.3 sin(2 x) cos(y) (a smooth bump)
  testTriangulation bump(testTriangulation t);

  // An n x n grid of the unit square lifted on the bump, its nodes on the
  // input triangulation (searched by onInput)
  optimizableMesh bumpGridOnInput(int n, const closestTriangleSearch &onInput);

  // A roof over t: two planes of the given slope meeting at a ridge along
  // x = 0.5
  testTriangulation roof(testTriangulation t, double slope);

  // The largest and the mean distance to a mesh of the input's nodes on
  // the ridge (x = 0.5) with y in (from, to)
  double ridgeDistance(const optimizableMesh &mesh, const surfaceMesh &input,
                       double from, double to, double *mean = nullptr);

  // The mean kappa of m's triangles
  double meanKappa(const optimizableMesh &m);

} // namespace optimizeTest

#endif
