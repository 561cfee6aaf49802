// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "facetPieces.h"
#include "flatPieces.h"

namespace reparam {

namespace {

  typedef std::array<double, 3> point;

  SVector3 vec(const point &a, const point &b)
  {
    return SVector3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  }

  bool usable(const std::array<int, 3> &f, const std::vector<bool> &skip,
              std::size_t i)
  {
    return !skip[i] && f[0] != f[1] && f[1] != f[2] && f[2] != f[0];
  }

  struct pieceMeasures {
    double area = 0., volume = 0.;
    point lo = {{INFINITY, INFINITY, INFINITY}};
    point hi = {{-INFINITY, -INFINITY, -INFINITY}};
  };

  // Per piece root: its area, signed volume (relative to the origin of the
  // first node, so that far-off coordinates lose no digits), bounding box
  void measure(const std::vector<point> &nodes,
               const std::vector<std::array<int, 3> > &facets,
               const std::vector<bool> &skip, const std::vector<int> &root,
               std::vector<pieceMeasures> &m)
  {
    std::vector<point> origin(facets.size());
    std::vector<char> seen(facets.size(), 0);
    for(std::size_t i = 0; i < facets.size(); i++)
      if(usable(facets[i], skip, i) && !seen[root[i]]) {
        seen[root[i]] = 1;
        origin[root[i]] = nodes[facets[i][0]];
      }
    for(std::size_t i = 0; i < facets.size(); i++) {
      if(!usable(facets[i], skip, i)) continue;
      pieceMeasures &p = m[root[i]];
      const point &o = origin[root[i]];
      const SVector3 a = vec(o, nodes[facets[i][0]]),
                     b = vec(o, nodes[facets[i][1]]),
                     c = vec(o, nodes[facets[i][2]]);
      p.area += 0.5 * crossprod(b - a, c - a).norm();
      p.volume += dot(a, crossprod(b, c)) / 6.;
      for(const int v : facets[i])
        for(int k = 0; k < 3; k++) {
          p.lo[k] = std::min(p.lo[k], nodes[v][k]);
          p.hi[k] = std::max(p.hi[k], nodes[v][k]);
        }
    }
  }

} // namespace

double facetArea(const std::vector<point> &nodes,
                 const std::vector<std::array<int, 3> > &facets,
                 const std::vector<bool> &skip, std::size_t &count)
{
  double area = 0.;
  count = 0;
  for(std::size_t i = 0; i < facets.size(); i++) {
    if(!usable(facets[i], skip, i)) continue;
    const point &a = nodes[facets[i][0]];
    area +=
      0.5 * crossprod(vec(a, nodes[facets[i][1]]), vec(a, nodes[facets[i][2]]))
              .norm();
    count++;
  }
  return area;
}

flatPieceDrop findFlatPieces(const std::vector<point> &nodes,
                             const std::vector<std::array<int, 3> > &facets,
                             const std::vector<bool> &skip, double size)
{
  flatPieceDrop r;
  r.drop.assign(facets.size(), false);
  std::vector<char> closed;
  const std::vector<int> root = facetPieceRoots(facets, &skip, &closed);
  std::vector<pieceMeasures> m(facets.size());
  measure(nodes, facets, skip, root, m);
  std::vector<char> flat(facets.size(), 0);
  for(std::size_t i = 0; i < facets.size(); i++) {
    if(!usable(facets[i], skip, i) || root[i] != (int)i) continue;
    const pieceMeasures &p = m[i];
    const double diagonal = vec(p.lo, p.hi).norm();
    // a hundredth: a closed piece as thick as a sphere, a cube or a
    // flattened tetrahedron has a mean thickness of a fifth to a
    // twentieth of its diagonal
    flat[i] = closed[i] && p.area > 0. && diagonal < size &&
              3. * std::fabs(p.volume) < 0.01 * diagonal * p.area;
    if(flat[i]) r.pieces.push_back((int)i);
  }
  for(std::size_t i = 0; i < facets.size(); i++)
    if(usable(facets[i], skip, i) && flat[root[i]]) {
      r.drop[i] = true;
      r.dropped++;
    }
  return r;
}

} // namespace reparam
