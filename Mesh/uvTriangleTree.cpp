// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "uvTriangleTree.h"

namespace {

  const int leafSize = 4;

} // namespace

uvTriangleTree::uvTriangleTree(
  const std::vector<std::array<double, 6> > &corners)
  : _corners(corners), _order(corners.size())
{
  for(std::size_t t = 0; t < _order.size(); t++) _order[t] = (int)t;
  if(!_order.empty()) {
    _nodes.reserve(2 * _order.size() / leafSize + 1);
    build(0, (int)_order.size());
  }
}

int uvTriangleTree::build(int first, int count)
{
  const int index = (int)_nodes.size();
  _nodes.push_back(boxNode());
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  double clo[2] = {1e300, 1e300}, chi[2] = {-1e300, -1e300};
  for(int i = first; i < first + count; i++) {
    const std::array<double, 6> &c = _corners[_order[i]];
    for(int k = 0; k < 2; k++) {
      const double a = c[k], b = c[2 + k], d = c[4 + k];
      lo[k] = std::min(lo[k], std::min(a, std::min(b, d)));
      hi[k] = std::max(hi[k], std::max(a, std::max(b, d)));
      const double g = (a + b + d) / 3.;
      clo[k] = std::min(clo[k], g);
      chi[k] = std::max(chi[k], g);
    }
  }
  for(int k = 0; k < 2; k++) {
    _nodes[index].lo[k] = lo[k];
    _nodes[index].hi[k] = hi[k];
  }
  if(count <= leafSize) {
    _nodes[index].first = first;
    _nodes[index].count = count;
    return index;
  }
  const int axis = chi[1] - clo[1] > chi[0] - clo[0] ? 1 : 0;
  const int half = count / 2;
  auto centroid = [&](int t) {
    const std::array<double, 6> &c = _corners[t];
    return c[axis] + c[2 + axis] + c[4 + axis];
  };
  std::nth_element(_order.begin() + first, _order.begin() + first + half,
                   _order.begin() + first + count,
                   [&](int a, int b) { return centroid(a) < centroid(b); });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  _nodes[index].left = left;
  _nodes[index].right = right;
  return index;
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
  if(_nodes.empty()) return -1;
  // the boxes are the triangles' own: a point just outside one (within the
  // tolerance, relative to the triangle) may lie outside its box by as
  // much, so the boxes are tested with that margin of their size
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while(top) {
    const boxNode &n = _nodes[stack[--top]];
    const double mu = tolerance * (n.hi[0] - n.lo[0]);
    const double mv = tolerance * (n.hi[1] - n.lo[1]);
    if(u < n.lo[0] - mu || u > n.hi[0] + mu || v < n.lo[1] - mv ||
       v > n.hi[1] + mv)
      continue;
    if(n.left < 0) {
      for(int i = n.first; i < n.first + n.count; i++)
        if(holds(_order[i], u, v, tolerance)) return _order[i];
      continue;
    }
    if(top + 2 > 128) return -1; // deeper than any balanced tree of ints
    stack[top++] = n.right;
    stack[top++] = n.left;
  }
  return -1;
}
