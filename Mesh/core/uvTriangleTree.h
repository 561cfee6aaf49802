// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Which triangle of a planar triangulation holds a point: the question a
// discrete face answers for every point, normal and derivative a planar
// mesher asks at (u, v). Gmsh's octree of element boxes (MElementOctree)
// tests each candidate through virtual calls and a 3x3 inversion; on the
// shared scans that point location was 6 % of the whole recipe's CPU.

#ifndef UV_TRIANGLE_TREE_H
#define UV_TRIANGLE_TREE_H

#include <array>
#include <vector>
#include "boxTree.h"

namespace reparam {

// A tree of boxes over the triangles (halved at the median centroid along
// their longer side, four triangles a leaf), searched for the boxes that
// hold the point
class uvTriangleTree {
public:
  // corners: per triangle, (u, v) of its three corners
  explicit uvTriangleTree(const std::vector<std::array<double, 6> > &corners);
  // The first triangle found whose barycentric coordinates at (u, v) are
  // all >= -tolerance (Gmsh's MElement tolerance is 1e-6); -1 if none
  int find(double u, double v, double tolerance = 1e-6) const;
  // The same, triangle `hint` tried first (a triangle found just before)
  int find(double u, double v, int hint, double tolerance = 1e-6) const
  {
    if(hint >= 0 && hint < (int)_corners.size() && holds(hint, u, v, tolerance))
      return hint;
    return find(u, v, tolerance);
  }
  std::size_t numBoxes() const { return _tree.nodes.size(); }

private:
  std::vector<std::array<double, 6> > _corners;
  boxTree<2> _tree; // over the triangles
  bool holds(int t, double u, double v, double tolerance) const;
};

} // namespace reparam

#endif
