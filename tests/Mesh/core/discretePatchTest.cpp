// Reparam - preconditions and topology of patches

#include <cmath>
#include <limits>
#include <gtest/gtest.h>
#include "discretePatch.h"
#include "testPatches.h"

using namespace reparam;

TEST(discretePatch, diskHasOneCounterclockwiseLoop)
{
  testTriangulation t = polarDisk(4, 12);
  discretePatch patch = makePatchOrDie(t);
  ASSERT_EQ(patch.boundaryLoops.size(), 1u);
  EXPECT_EQ(patch.boundaryLoops[0].size(), 12u);
  EXPECT_EQ(patch.outerLoop, 0);
  EXPECT_EQ(patch.eulerCharacteristic(), 1);
  EXPECT_EQ(patch.genus(), 0);
  // counterclockwise in the xy plane: positive shoelace area, the polygon's
  double area2 = 0.;
  const auto &loop = patch.boundaryLoops[0];
  for(std::size_t i = 0; i < loop.size(); i++) {
    const SPoint3 &a = patch.points[loop[i]];
    const SPoint3 &b = patch.points[loop[(i + 1) % loop.size()]];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(area2, 12. * std::sin(2. * M_PI / 12.), 1e-12);
  EXPECT_NEAR(boundaryLoopLength(patch, 0), 24. * std::sin(M_PI / 12.), 1e-12);
}

TEST(discretePatch, longestLoopIsOuter)
{
  testTriangulation t = polarDiskWithHoles(8, 32, {{{2, 4, 0, 4}}, {{5, 7, 10, 20}}});
  discretePatch patch = makePatchOrDie(t);
  ASSERT_EQ(patch.boundaryLoops.size(), 3u);
  EXPECT_EQ(patch.genus(), 0);
  double outer = boundaryLoopLength(patch, patch.outerLoop);
  for(std::size_t l = 0; l < 3; l++)
    if((int)l != patch.outerLoop) EXPECT_LT(boundaryLoopLength(patch, l), outer);
  EXPECT_EQ(patch.boundaryLoops[patch.outerLoop].size(), 32u);
}

TEST(discretePatch, reorientsInconsistentTriangles)
{
  testTriangulation t = polarDisk(3, 8);
  std::swap(t.triangles[5][0], t.triangles[5][1]);
  std::swap(t.triangles[17][1], t.triangles[17][2]);
  discretePatch patch = makePatchOrDie(t);
  EXPECT_EQ(patch.numReorientedTriangles, 2u);
  ASSERT_EQ(patch.boundaryLoops.size(), 1u);
}

TEST(discretePatch, rejectsBadInput)
{
  discretePatch patch;
  EXPECT_EQ(makeDiscretePatch({}, {}, patch).status, reparamStatus::emptyPatch);

  testTriangulation t = polarDisk(3, 8);
  testTriangulation nan = t;
  nan.points[4] = SPoint3(std::numeric_limits<double>::quiet_NaN(), 0., 0.);
  reparamError nanError = makeDiscretePatch(nan.points, nan.triangles, patch);
  EXPECT_EQ(nanError.status, reparamStatus::invalidCoordinates);
  EXPECT_EQ(nanError.node, 4);

  testTriangulation repeated = t;
  repeated.triangles[3][1] = repeated.triangles[3][0];
  EXPECT_EQ(makeDiscretePatch(repeated.points, repeated.triangles, patch).status,
            reparamStatus::degenerateTriangle);

  testTriangulation flat = t; // a zero-area triangle: three collinear nodes
  flat.points.push_back(SPoint3(3., 0., 0.));
  flat.points.push_back(SPoint3(4., 0., 0.));
  flat.points.push_back(SPoint3(5., 0., 0.));
  flat.triangles.push_back({25, 26, 27});
  EXPECT_EQ(makeDiscretePatch(flat.points, flat.triangles, patch).status,
            reparamStatus::degenerateTriangle);

  testTriangulation fin = t; // a third triangle on edge 1-2
  fin.points.push_back(SPoint3(0., 0., 1.));
  fin.triangles.push_back({1, 2, (int)fin.points.size() - 1});
  EXPECT_EQ(makeDiscretePatch(fin.points, fin.triangles, patch).status,
            reparamStatus::nonManifoldEdge);

  testTriangulation two = t; // a second, disjoint triangle
  for(int k = 0; k < 3; k++) two.points.push_back(SPoint3(5. + k, k * k, 0.));
  two.triangles.push_back({25, 26, 27});
  EXPECT_EQ(makeDiscretePatch(two.points, two.triangles, patch).status,
            reparamStatus::severalComponents);

  // pinch two rim nodes of a disk together: two boundary fans meet at one
  // node (the last rim node takes the place of the merged one)
  testTriangulation pinched = polarDisk(3, 8);
  const int rim0 = 1 + 2 * 8, rim4 = 1 + 2 * 8 + 4, last = 24;
  for(auto &tri : pinched.triangles)
    for(int &v : tri) {
      if(v == rim4) v = rim0;
      else if(v == last) v = rim4;
    }
  std::vector<SPoint3> pts = pinched.points;
  pts[rim4] = pts[last];
  pts.pop_back();
  reparamError pinch = makeDiscretePatch(pts, pinched.triangles, patch);
  EXPECT_EQ(pinch.status, reparamStatus::nonManifoldVertex);
  EXPECT_EQ(pinch.node, rim0);
}

TEST(discretePatch, rejectsClosedAndHandles)
{
  // octahedron: closed, genus 0
  std::vector<SPoint3> p = {SPoint3(1, 0, 0), SPoint3(-1, 0, 0), SPoint3(0, 1, 0),
                            SPoint3(0, -1, 0), SPoint3(0, 0, 1), SPoint3(0, 0, -1)};
  std::vector<std::array<int, 3> > t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  discretePatch patch;
  EXPECT_EQ(makeDiscretePatch(p, t, patch).status, reparamStatus::noBoundary);

  // a torus with a hole cut out: one boundary loop, genus 1
  const int n = 8, m = 6;
  std::vector<SPoint3> q;
  std::vector<std::array<int, 3> > tt;
  for(int i = 0; i < n; i++)
    for(int j = 0; j < m; j++) {
      double a = 2 * M_PI * i / n, b = 2 * M_PI * j / m;
      q.push_back(SPoint3((2 + std::cos(b)) * std::cos(a),
                          (2 + std::cos(b)) * std::sin(a), std::sin(b)));
    }
  for(int i = 0; i < n; i++)
    for(int j = 0; j < m; j++) {
      if(i == 0 && j == 0) continue;
      int a = i * m + j, b = ((i + 1) % n) * m + j, c = i * m + (j + 1) % m,
          d = ((i + 1) % n) * m + (j + 1) % m;
      tt.push_back({a, b, d});
      tt.push_back({a, d, c});
    }
  reparamError err = makeDiscretePatch(q, tt, patch);
  EXPECT_EQ(err.status, reparamStatus::notDiskTopology);
  EXPECT_EQ(patch.genus(), 1);
  EXPECT_NE(err.what().find("genus 1"), std::string::npos);
}

TEST(discretePatch, isTheSurfaceMeshItWasBuiltFrom)
{
  // nodes and triangles kept as given (consistent already), no quadrangles:
  // what reads a surfaceMesh reads the patch
  const testTriangulation t = rectangleGrid(3, 2, 3., 2.);
  const discretePatch patch = makePatchOrDie(t);
  const surfaceMesh &mesh = patch;
  EXPECT_EQ(mesh.points.size(), 12u);
  EXPECT_EQ(mesh.numElements(), 12u);
  EXPECT_TRUE(mesh.quadrangles.empty());
  EXPECT_EQ(mesh.triangles, t.triangles);
  EXPECT_EQ(patch.edges.size(), 23u);
}
