// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include "facetPieces.h"
#include "flatPieces.h"

namespace reparam {

namespace {

  typedef std::array<double, 3> point;

  point minus(const point &a, const point &b)
  {
    return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
  }

  point cross(const point &a, const point &b)
  {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
             a[0] * b[1] - a[1] * b[0]}};
  }

  double dot(const point &a, const point &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
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
    bool closed = true;
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
      const point a = minus(nodes[facets[i][0]], o),
                  b = minus(nodes[facets[i][1]], o),
                  c = minus(nodes[facets[i][2]], o);
      const point n = cross(minus(b, a), minus(c, a));
      p.area += 0.5 * std::sqrt(dot(n, n));
      p.volume += dot(a, cross(b, c)) / 6.;
      for(const int v : facets[i])
        for(int k = 0; k < 3; k++) {
          p.lo[k] = std::min(p.lo[k], nodes[v][k]);
          p.hi[k] = std::max(p.hi[k], nodes[v][k]);
        }
    }
  }

  // A piece with an edge used once or more than twice is open
  void markOpen(const std::vector<std::array<int, 3> > &facets,
                const std::vector<bool> &skip, const std::vector<int> &root,
                std::vector<pieceMeasures> &m)
  {
    std::vector<std::pair<std::uint64_t, int> > edges;
    edges.reserve(3 * facets.size());
    for(std::size_t i = 0; i < facets.size(); i++) {
      if(!usable(facets[i], skip, i)) continue;
      for(int k = 0; k < 3; k++) {
        const std::uint64_t a = (std::uint32_t)facets[i][k],
                            b = (std::uint32_t)facets[i][(k + 1) % 3];
        edges.push_back({std::min(a, b) << 32 | std::max(a, b), root[i]});
      }
    }
    std::sort(edges.begin(), edges.end());
    for(std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while(j < edges.size() && edges[j].first == edges[i].first) j++;
      if(j - i != 2) m[edges[i].second].closed = false;
      i = j;
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
    const point n =
      cross(minus(nodes[facets[i][1]], a), minus(nodes[facets[i][2]], a));
    area += 0.5 * std::sqrt(dot(n, n));
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
  const std::vector<int> root = facetPieceRoots(facets, &skip);
  std::vector<pieceMeasures> m(facets.size());
  measure(nodes, facets, skip, root, m);
  markOpen(facets, skip, root, m);
  std::vector<char> flat(facets.size(), 0);
  for(std::size_t i = 0; i < facets.size(); i++) {
    if(!usable(facets[i], skip, i) || root[i] != (int)i) continue;
    const pieceMeasures &p = m[i];
    const point d = minus(p.hi, p.lo);
    const double diagonal = std::sqrt(dot(d, d));
    // a hundredth: a closed piece as thick as a sphere, a cube or a
    // flattened tetrahedron has a mean thickness of a fifth to a
    // twentieth of its diagonal
    flat[i] = p.closed && p.area > 0. && diagonal < size &&
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
