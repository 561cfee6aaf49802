// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Closest point of a triangulated surface to a query point: the search
// structure behind the mesh-fidelity measures (distances between a new mesh
// and its input triangulation, orientation of the new elements).

#ifndef CLOSEST_TRIANGLE_H
#define CLOSEST_TRIANGLE_H

#include <array>
#include <memory>
#include <vector>
#include "SPoint3.h"

// Closest point of triangle (a, b, c) to p, by the region of p among the
// triangle's vertices, edges and face. Unlike Gmsh's
// signedDistancePointTriangle, also defined for degenerate triangles (STL
// slivers), which are their longest edge.
SPoint3 closestPointOnTriangle(const SPoint3 &p, const SPoint3 &a,
                               const SPoint3 &b, const SPoint3 &c);

struct closestTriangleHit {
  int triangle = -1;
  double distance = 0.;
  SPoint3 point;
};

class ANNkd_tree;

// Exact closest triangle by kd-trees (ANN) over sample points of the
// triangles: every point of a triangle lies within its samples' radius of
// one of them, so the nearest sample gives an upper bound d and every
// triangle closer than d has a sample within d + its samples' radius. Large
// triangles get more samples (uniform subdivision), so that the radius stays
// below the mean triangle size. The samples are kept in classes of radius
// (a factor 4 apart from the largest), one tree each, so that a query
// gathers within d + the class radius in each: one global radius made a
// query among dense tiny triangles (CAD STL, slivers) gather thousands of
// samples (41 s, now 29 s, for the report of a noisy 7436-triangle part;
// halving classes: 26 s, but 30 % slower on scans). The few huge
// triangles among tiny ones (over 64 times the mean size) are not sampled
// but measured at every query.
class closestTriangleSearch {
public:
  closestTriangleSearch(const std::vector<SPoint3> &points,
                        const std::vector<std::array<int, 3> > &triangles);
  ~closestTriangleSearch();
  closestTriangleSearch(const closestTriangleSearch &) = delete;
  closestTriangleSearch &operator=(const closestTriangleSearch &) = delete;

  // triangle -1 if the surface has no triangle
  closestTriangleHit closest(const SPoint3 &p) const;
  std::size_t numSamples() const;

private:
  struct sampleClass {
    double radius = 0.; // of every sample of the class, at most
    std::vector<int> triangle; // of each sample
    double **points = nullptr; // ANN's point array
    std::unique_ptr<ANNkd_tree> tree;
  };
  std::vector<SPoint3> _points;
  std::vector<std::array<int, 3> > _triangles;
  std::vector<std::unique_ptr<sampleClass> > _classes;
  std::vector<int> _hugeTriangles; // not sampled: measured at every query
  double distanceTo(int t, const SPoint3 &p, SPoint3 &closest) const;
  // keeps in hit the closest of hit and the triangles in `candidates`
  void closer(const SPoint3 &p, std::vector<int> &candidates,
              closestTriangleHit &hit) const;
};

#endif
