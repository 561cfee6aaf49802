// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <set>
#include "SVector3.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "optimizableMesh.h"
#include "triangleQuality.h"
#include "triangleSplit.h"

namespace reparam {

void triangleBarycentric(const SPoint3 &p, const SPoint3 &a, const SPoint3 &b,
                         const SPoint3 &c, double l[3])
{
  const SVector3 e1(a, b), e2(a, c), ep(a, p);
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  l[0] = l[1] = l[2] = 0.;
  if(!(det > 1e-14 * g11 * g22)) return;
  l[1] = (g22 * dot(ep, e1) - g12 * dot(ep, e2)) / det;
  l[2] = (g11 * dot(ep, e2) - g12 * dot(ep, e1)) / det;
  l[0] = 1. - l[1] - l[2];
}

namespace {
  std::pair<int, int> edgeKey(int a, int b)
  {
    return std::make_pair(std::min(a, b), std::max(a, b));
  }
} // namespace

triangleSplitter::triangleSplitter(optimizableMesh &m, const surfaceMesh &input,
                                   const closestTriangleSearch &onInput,
                                   bool reversed)
  : _m(m), _input(input), _onInput(onInput), _reversed(reversed)
{
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    for(int k = 0; k < 3; k++)
      _edges[edgeKey(m.triangles[t][k], m.triangles[t][(k + 1) % 3])].push_back(
        (int)t);
  _touched.assign(m.triangles.size(), false);
  _around.resize(m.points.size());
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    for(int v : m.triangles[t]) _around[v].push_back((int)t);
}

// The triangles around `triangles` (untouched until now, so the edge map
// still holds their edges) wait for the next round
void triangleSplitter::touchAround(const std::vector<int> &triangles)
{
  for(int t : triangles)
    for(int k = 0; k < 3; k++)
      for(int s :
          edgeTriangles(_m.triangles[t][k], _m.triangles[t][(k + 1) % 3]))
        _touched[s] = true;
}

bool triangleSplitter::moveNode(int v, const SPoint3 &x, int inputNode,
                                double floor)
{
  if(v >= (int)_around.size() || !_m.movable[v] || _around[v].empty())
    return false;
  // any change to v's triangles this round touched one of those at its start
  const std::vector<int> &ring = _around[v];
  for(int t : ring)
    if(_touched[t]) return false;
  const int n = (int)_m.points.size(); // v's index in the triangles below
  std::vector<std::array<int, 3> > moved;
  for(int t : ring) {
    std::array<int, 3> c = _m.triangles[t];
    for(int &w : c)
      if(w == v) w = n;
    if(against(c, x)) return false;
    moved.push_back(c);
  }
  if(worstWith(moved, x) < floor) return false;
  touchAround(ring);
  _m.landing.resize(_m.points.size(), -1);
  _m.inputNode.resize(_m.points.size(), -1);
  _m.points[v] = x;
  _m.movable[v] = false;
  _m.landing[v] = _onInput.closest(x).triangle;
  _m.inputNode[v] = inputNode;
  return true;
}

const std::vector<int> &triangleSplitter::edgeTriangles(int a, int b)
{
  return _edges[edgeKey(a, b)];
}

bool triangleSplitter::against(const std::array<int, 3> &t,
                               const SPoint3 &x) const
{
  SPoint3 c[3];
  for(int k = 0; k < 3; k++)
    c[k] = t[k] < (int)_m.points.size() ? _m.points[t[k]] : x;
  return triangleAgainstInput(c[0], c[1], c[2], _input, _onInput) != _reversed;
}

// The worst kappa of triangles `in` (node index points.size() at x)
double triangleSplitter::worstWith(const std::vector<std::array<int, 3> > &in,
                                   const SPoint3 &x) const
{
  double worst = 1.;
  for(const std::array<int, 3> &t : in) {
    SPoint3 c[3];
    for(int k = 0; k < 3; k++)
      c[k] = t[k] < (int)_m.points.size() ? _m.points[t[k]] : x;
    worst = std::min(worst, triangleKappa(c[0], c[1], c[2]));
  }
  return worst;
}

// Whether the new node at x, or (movable) at the input point closest to the
// centroid of the corners around it (x then moved there), leaves no new
// triangle below both the floor and the worst old one: the midpoint of an
// edge across a strip makes slivers that the centroid of the four corners
// does not
bool triangleSplitter::placeAboveFloor(
  const std::vector<int> &out, const std::vector<std::array<int, 3> > &in,
  bool movable, double floor, SPoint3 &x) const
{
  double before = 1.;
  for(int t : out) {
    const std::array<int, 3> &c = _m.triangles[t];
    before = std::min(
      before, triangleKappa(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]));
  }
  const double least = std::min(before, floor);
  if(worstWith(in, x) >= least) return true;
  if(!movable) return false;
  std::set<int> corners;
  for(int t : out)
    for(int v : _m.triangles[t]) corners.insert(v);
  SPoint3 centroid(0., 0., 0.);
  for(int v : corners) centroid += _m.points[v];
  centroid *= 1. / corners.size();
  const closestTriangleHit hit = _onInput.closest(centroid);
  if(hit.triangle < 0 || worstWith(in, hit.point) < least) return false;
  x = hit.point;
  return true;
}

// Replaces the triangles `out` by `in` (node index points.size() is the new
// node, at onEdge or where placeAboveFloor moves it) if none of `in` points
// against the input
bool triangleSplitter::apply(const std::vector<int> &out,
                             const std::vector<std::array<int, 3> > &in,
                             const SPoint3 &onEdge, bool movable, int inputNode,
                             double floor)
{
  SPoint3 x = onEdge;
  if(floor > 0. && !placeAboveFloor(out, in, movable, floor, x)) return false;
  for(const std::array<int, 3> &t : in)
    if(against(t, x)) return false;
  touchAround(out);
  _m.points.push_back(x);
  _m.movable.push_back(movable);
  _m.landing.push_back(_onInput.closest(x).triangle);
  _m.inputNode.push_back(inputNode);
  if(_m.origin.size() + 1 == _m.points.size()) _m.origin.push_back(-1);
  if(_m.size.size() + 1 == _m.points.size()) {
    const std::array<int, 3> &c = _m.triangles[out[0]];
    _m.size.push_back((_m.size[c[0]] + _m.size[c[1]] + _m.size[c[2]]) / 3.);
  }
  const bool trackAgainst = _m.against.size() == _m.triangles.size();
  for(std::size_t i = 0; i < in.size(); i++) {
    if(i < out.size())
      _m.triangles[out[i]] = in[i];
    else {
      _m.triangles.push_back(in[i]);
      _touched.push_back(true);
      if(_m.triangleOrigin.size() + 1 == _m.triangles.size())
        _m.triangleOrigin.push_back(-1);
      if(trackAgainst) _m.against.push_back(false);
    }
    if(trackAgainst && i < out.size()) _m.against[out[i]] = false;
  }
  return true;
}

bool triangleSplitter::splitTriangle(int t, const SPoint3 &x, bool movable,
                                     int inputNode)
{
  if(_touched[t]) return false;
  const std::array<int, 3> c = _m.triangles[t];
  const int n = (int)_m.points.size();
  return apply({t}, {{{c[0], c[1], n}}, {{c[1], c[2], n}}, {{c[2], c[0], n}}},
               x, movable, inputNode);
}

bool triangleSplitter::splitEdge(int t, int k, const SPoint3 &x, bool movable,
                                 int inputNode, double floor)
{
  if(_touched[t]) return false;
  const std::array<int, 3> c = _m.triangles[t];
  const int a = c[k], b = c[(k + 1) % 3], p = c[(k + 2) % 3];
  if(_m.lockedEdges.count(edgeKey(a, b))) return false;
  const std::vector<int> &on = edgeTriangles(a, b);
  if(on.size() != 2) return false; // a boundary (or non-manifold) edge
  const int s = on[0] == t ? on[1] : on[0];
  if(_touched[s]) return false;
  int q = -1;
  for(int v : _m.triangles[s])
    if(v != a && v != b) q = v;
  if(q < 0) return false;
  const int n = (int)_m.points.size();
  // (a, b, p) and (b, a, q) become (a, n, p), (n, b, p), (b, n, q), (n, a, q)
  return apply({t, s}, {{{a, n, p}}, {{n, b, p}}, {{b, n, q}}, {{n, a, q}}}, x,
               movable, inputNode, floor);
}
} // namespace reparam

