// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "uvTriangleTree.h"

namespace reparam {

namespace {

  const int leafSize = 4;

} // namespace

uvTriangleTree::uvTriangleTree(
  const std::vector<std::array<double, 6> > &corners)
  : _corners(corners)
{
  _tree.build((int)_corners.size(), leafSize,
              [&](int t, double *lo, double *hi) {
                const std::array<double, 6> &c = _corners[t];
                for(int k = 0; k < 2; k++) {
                  lo[k] = std::min({c[k], c[2 + k], c[4 + k]});
                  hi[k] = std::max({c[k], c[2 + k], c[4 + k]});
                }
              },
              [&](int t, int k) {
                const std::array<double, 6> &c = _corners[t];
                return (c[k] + c[2 + k] + c[4 + k]) / 3.;
              });
}

bool uvTriangleTree::holds(int t, double u, double v, double tolerance) const
{
  // barycentric coordinates as Gmsh's MTriangle::xyz2uvw gives them in the
  // plane: (u, v) = p0 + xi (p1 - p0) + eta (p2 - p0)
  const std::array<double, 6> &c = _corners[t];
  const double a = c[2] - c[0], b = c[4] - c[0];
  const double d = c[3] - c[1], e = c[5] - c[1];
  const double det = a * e - b * d;
  if(det == 0.) return false;
  const double ru = u - c[0], rv = v - c[1];
  const double xi = (ru * e - b * rv) / det;
  const double eta = (a * rv - d * ru) / det;
  return xi >= -tolerance && eta >= -tolerance && xi <= 1. + tolerance - eta;
}

int uvTriangleTree::find(double u, double v, double tolerance) const
{
  if(_tree.nodes.empty()) return -1;
  // the boxes are the triangles' own: a point just outside one (within the
  // tolerance, relative to the triangle) may lie outside its box by as
  // much, so the boxes are tested with that margin of their size
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while(top) {
    const boxTree<2>::node &n = _tree.nodes[stack[--top]];
    const double mu = tolerance * (n.hi[0] - n.lo[0]);
    const double mv = tolerance * (n.hi[1] - n.lo[1]);
    if(u < n.lo[0] - mu || u > n.hi[0] + mu || v < n.lo[1] - mv ||
       v > n.hi[1] + mv)
      continue;
    if(n.left < 0) {
      for(int i = n.first; i < n.first + n.count; i++)
        if(holds(_tree.order[i], u, v, tolerance)) return _tree.order[i];
      continue;
    }
    if(top + 2 > 128) return -1; // deeper than any balanced tree of ints
    stack[top++] = n.right;
    stack[top++] = n.left;
  }
  return -1;
}
} // namespace reparam

