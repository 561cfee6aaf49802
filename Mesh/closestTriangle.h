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

// Exact closest triangle by a kd-tree (ANN) over sample points of the
// triangles: every point of a triangle lies within `sampleRadius` of one of
// its samples, so the nearest sample gives an upper bound d and every triangle
// closer than d has a sample within d + sampleRadius. Large triangles get
// more samples (uniform subdivision), so that sampleRadius stays of the order
// of the mean edge length.
class closestTriangleSearch {
public:
  closestTriangleSearch(const std::vector<SPoint3> &points,
                        const std::vector<std::array<int, 3> > &triangles);
  ~closestTriangleSearch();
  closestTriangleSearch(const closestTriangleSearch &) = delete;
  closestTriangleSearch &operator=(const closestTriangleSearch &) = delete;

  // triangle -1 if the surface has no triangle
  closestTriangleHit closest(const SPoint3 &p) const;
  double sampleRadius() const { return _sampleRadius; }
  std::size_t numSamples() const { return _sampleTriangle.size(); }

private:
  std::vector<SPoint3> _points;
  std::vector<std::array<int, 3> > _triangles;
  std::vector<int> _sampleTriangle;
  double **_samplePoints = nullptr; // ANN's point array
  std::unique_ptr<ANNkd_tree> _tree;
  double _sampleRadius = 0.;
  double distanceTo(int t, const SPoint3 &p, SPoint3 &closest) const;
};

#endif
