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
#include "boxTree.h"

namespace reparam {

// Closest point of segment [a, b] to p (a if the segment is a point)
SPoint3 closestPointOnSegment(const SPoint3 &p, const SPoint3 &a,
                              const SPoint3 &b);

// The distance from p to a polyline: to its closest segment, or its one
// point (infinity without any)
double distanceToPolyline(const SPoint3 &p,
                          const std::vector<SPoint3> &polyline);

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

// Exact closest triangle by a bounding-box tree over the triangles (boxes
// halved at the median centroid along their longest side, four triangles a
// leaf), searched depth first, nearer box first, skipping the boxes farther
// than the best distance found. It replaced kd-trees (ANN) over sample
// points of the triangles, whose search gathered every sample within the
// best distance: for a query off the surface among tiny triangles (the
// halfway points of a mesh triangle across a fold of a CAD STL) thousands of
// them (bench/README.md, "Report").
class closestTriangleSearch {
public:
  closestTriangleSearch(const std::vector<SPoint3> &points,
                        const std::vector<std::array<int, 3> > &triangles);
  ~closestTriangleSearch();
  closestTriangleSearch(const closestTriangleSearch &) = delete;
  closestTriangleSearch &operator=(const closestTriangleSearch &) = delete;

  // triangle -1 if the surface has no triangle
  closestTriangleHit closest(const SPoint3 &p) const;
  // the same, started from triangle `near` (-1: none), a guess of the
  // closest one (where a neighbouring point landed): its distance bounds
  // the search from the start, so that fewer boxes are opened
  closestTriangleHit closest(const SPoint3 &p, int near) const;
  // the boxes of the tree
  std::size_t numBoxes() const;

private:
  boxTree<3> _tree; // over the triangles
  // the corners of triangle _tree.order[i] at 3 i: a leaf's triangles read
  // one after the other, not through their nodes, and skipped by their box
  // when farther than the best distance
  std::vector<SPoint3> _corners;
  // _position[t]: where triangle t is in the tree's order
  std::vector<int> _position;
  double distanceTo(int t, const SPoint3 &p, SPoint3 &closest) const;
};

} // namespace reparam

#endif
