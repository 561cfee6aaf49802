// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "bijectivityCheck.h"
#include "robustPredicates.h"

namespace reparam {

double orientation2d(const double *a, const double *b, const double *c)
{
  // Gmsh initializes the predicates at startup; the unit tests do not start
  // Gmsh. Idempotent.
  static const bool initialized =
    (robustPredicates::exactinit(0, 1., 1., 1.), true);
  (void)initialized;
  return robustPredicates::orient2d(
    const_cast<double *>(a), const_cast<double *>(b), const_cast<double *>(c));
}

namespace {

  int sign(double x) { return (x > 0.) - (x < 0.); }

  // c on segment [a, b], given that a, b, c are collinear
  bool onSegment(const double *a, const double *b, const double *c)
  {
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) &&
           std::min(a[1], b[1]) <= c[1] && c[1] <= std::max(a[1], b[1]);
  }

} // namespace

bool segmentsIntersect(const double *a, const double *b, const double *c,
                       const double *d)
{
  const int o1 = sign(orientation2d(a, b, c));
  const int o2 = sign(orientation2d(a, b, d));
  const int o3 = sign(orientation2d(c, d, a));
  const int o4 = sign(orientation2d(c, d, b));
  if(o1 * o2 < 0 && o3 * o4 < 0) return true;
  // an endpoint on the other segment (touching, or collinear overlap)
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
         (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

namespace {

  struct boundaryEdges {
    const std::vector<double> &uv;
    std::vector<std::array<int, 2> > nodes;
    std::vector<std::array<double, 4> > box; // umin, vmin, umax, vmax
    std::vector<std::pair<int, int> > candidates;

    // Quadtree binning: a box with few edges tests all their pairs, a
    // crowded one is split in 4 at the middle of its edges' extent (clipped
    // to the cell), so that images crushed into a tiny part of the plane are
    // split down to their own scale; depth bounded for coincident nodes
    void collect(const std::vector<int> &edges,
                 const std::array<double, 4> &cell, int depth)
    {
      if(edges.size() <= 16 || depth == 48) {
        for(std::size_t i = 0; i < edges.size(); i++)
          for(std::size_t j = i + 1; j < edges.size(); j++)
            candidates.emplace_back(std::min(edges[i], edges[j]),
                                    std::max(edges[i], edges[j]));
        return;
      }
      std::array<double, 4> b = {{1e300, 1e300, -1e300, -1e300}};
      for(int e : edges)
        for(int c = 0; c < 2; c++) {
          b[c] = std::min(b[c], std::max(box[e][c], cell[c]));
          b[c + 2] = std::max(b[c + 2], std::min(box[e][c + 2], cell[c + 2]));
        }
      const double mid[2] = {0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3])};
      std::array<double, 4> child[4];
      std::vector<int> inside[4];
      bool separates = false;
      for(int q = 0; q < 4; q++) {
        child[q] = b;
        child[q][(q & 1) ? 0 : 2] = mid[0];
        child[q][(q & 2) ? 1 : 3] = mid[1];
        for(int e : edges)
          if(box[e][0] <= child[q][2] && box[e][2] >= child[q][0] &&
             box[e][1] <= child[q][3] && box[e][3] >= child[q][1])
            inside[q].push_back(e);
        if(inside[q].size() < edges.size()) separates = true;
      }
      // every edge in every quarter (they all pass near the middle):
      // splitting separates nothing
      if(!separates) {
        collect(edges, b, 48);
        return;
      }
      for(int q = 0; q < 4; q++) collect(inside[q], child[q], depth + 1);
    }
  };

} // namespace

namespace {

  double pointSegmentDistance(const double *p, const double *a,
                              const double *b)
  {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double l2 = dx * dx + dy * dy;
    double s = l2 > 0. ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0.;
    s = std::min(1., std::max(0., s));
    return std::hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy);
  }

  // Whether a node of edge e lies within `within` of edge f, or one of f's
  // of e
  bool nodesWithin(const std::vector<double> &uv, const std::array<int, 2> &e,
                   const std::array<int, 2> &f, double within)
  {
    for(int k = 0; k < 2; k++)
      if(pointSegmentDistance(&uv[2 * e[k]], &uv[2 * f[0]], &uv[2 * f[1]]) <=
           within ||
         pointSegmentDistance(&uv[2 * f[k]], &uv[2 * e[0]], &uv[2 * e[1]]) <=
           within)
        return true;
    return false;
  }

} // namespace

std::size_t countBoundaryFolds(const discretePatch &patch,
                               const std::vector<double> &uv, double within,
                               std::vector<std::array<int, 2> > *pairs)
{
  boundaryEdges all{uv, {}, {}, {}};
  for(const auto &loop : patch.boundaryLoops)
    for(std::size_t i = 0; i < loop.size(); i++)
      all.nodes.push_back({{loop[i], loop[(i + 1) % loop.size()]}});
  const std::size_t m = all.nodes.size();
  if(m < 4) return 0;
  std::array<double, 4> bounds = {{1e300, 1e300, -1e300, -1e300}};
  std::vector<int> edges(m);
  for(std::size_t e = 0; e < m; e++) {
    const double *p = &uv[2 * all.nodes[e][0]], *q = &uv[2 * all.nodes[e][1]];
    all.box.push_back({{std::min(p[0], q[0]), std::min(p[1], q[1]),
                        std::max(p[0], q[0]), std::max(p[1], q[1])}});
    for(int c = 0; c < 2; c++) {
      bounds[c] = std::min(bounds[c], all.box[e][c]);
      bounds[c + 2] = std::max(bounds[c + 2], all.box[e][c + 2]);
    }
    edges[e] = (int)e;
  }
  all.collect(edges, bounds, 0);
  std::sort(all.candidates.begin(), all.candidates.end());
  all.candidates.erase(
    std::unique(all.candidates.begin(), all.candidates.end()),
    all.candidates.end());
  std::size_t folds = 0;
  for(const auto &pr : all.candidates) {
    const auto &e = all.nodes[pr.first], &f = all.nodes[pr.second];
    if(e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]) continue;
    if(segmentsIntersect(&uv[2 * e[0]], &uv[2 * e[1]], &uv[2 * f[0]],
                         &uv[2 * f[1]]) &&
       !(within > 0. && nodesWithin(uv, e, f, within))) {
      folds++;
      if(pairs && pairs->size() < maxFoldPairs)
        pairs->push_back({{e[0], f[0]}});
    }
  }
  return folds;
}

bijectivityReport checkBijectivity(const discretePatch &patch,
                                   const std::vector<double> &uv,
                                   double degenerateRatio)
{
  bijectivityReport report;
  const std::size_t nt = patch.triangles.size();
  std::vector<double> area2(nt), area3d(nt);
  double totalUv = 0., total3d = 0.;
  for(std::size_t t = 0; t < nt; t++) {
    const auto &tri = patch.triangles[t];
    area2[t] = orientation2d(&uv[2 * tri[0]], &uv[2 * tri[1]], &uv[2 * tri[2]]);
    totalUv += area2[t];
    const SPoint3 &a = patch.points[tri[0]], &b = patch.points[tri[1]],
                  &c = patch.points[tri[2]];
    area3d[t] = crossprod(SVector3(a, b), SVector3(a, c)).norm();
    total3d += area3d[t];
  }
  report.orientation = (totalUv < 0.) ? -1 : 1;
  for(std::size_t t = 0; t < nt; t++) {
    const double a = report.orientation * area2[t];
    if(a <= 0.)
      report.flippedTriangles.push_back((int)t);
    else if(a / std::fabs(totalUv) < degenerateRatio * area3d[t] / total3d)
      report.degenerateTriangles.push_back((int)t);
  }
  report.numFolds = countBoundaryFolds(patch, uv, 0., &report.foldPairs);
  return report;
}
} // namespace reparam

