// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Cutting a part in two: spectral bisection of its dual graph, the cut taken
// at the level set of the Fiedler vector that is shortest for the area it
// separates (a sweep cut). The paper cuts along level sets of a harmonic or
// Fiedler function for smooth cuts; METIS halves by triangle counts and cuts
// zig-zags. On a pinched part the dual graph is a strip (the two fans at the
// pinch node share no edge), so its Fiedler vector runs along the strip and
// the cut separates the pinch.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include "fiedlerVector.h"
#include "patchLayout.h"
#include "triangleAdjacency.h"

namespace reparam {

namespace {

  SPoint3 centroid(const layoutMesh &mesh, int t)
  {
    const auto &tri = mesh.triangles[t];
    const SPoint3 &a = mesh.points[tri[0]], &b = mesh.points[tri[1]],
                  &c = mesh.points[tri[2]];
    return SPoint3((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.,
                   (a.z() + b.z() + c.z()) / 3.);
  }

  // Dual graph of a part: local triangle indices, edges across the manifold
  // mesh edges inside the part, with the mesh edge's length
  struct dualGraph {
    std::vector<std::array<int, 2> > edges;
    std::vector<double> lengths, weights;
    std::vector<std::vector<int> > incident; // dual edges of each triangle
  };

  dualGraph makeDualGraph(const layoutMesh &mesh,
                          const triangleAdjacency &adjacency,
                          const std::vector<int> &part,
                          const std::vector<std::array<int, 3> > &across)
  {
    dualGraph g;
    g.incident.resize(part.size());
    for(std::size_t i = 0; i < part.size(); i++) {
      const int t = part[i];
      for(int k = 0; k < 3; k++) {
        const int j = across[i][k];
        if(j < 0 || part[j] < t) continue;
        const auto &edge = adjacency.edges[adjacency.triangleEdges[t][k]];
        const double len = edgeLength(mesh, edge);
        const double d = centroid(mesh, t).distance(centroid(mesh, part[j]));
        g.incident[i].push_back((int)g.edges.size());
        g.incident[j].push_back((int)g.edges.size());
        g.edges.push_back({(int)i, j});
        g.lengths.push_back(len);
        // finite-volume weight length / distance; slivers give both ~0
        g.weights.push_back(len > 0. && d > 0. ? len / d : 1.);
      }
    }
    // Weights relative to their mean: some ratios of degenerate triangles
    // are huge or tiny, which only hurts the factorization
    if(!g.weights.empty()) {
      double mean = std::accumulate(g.weights.begin(), g.weights.end(), 0.) /
                    g.weights.size();
      for(double &w : g.weights) w = std::min(std::max(w / mean, 1e-3), 1e3);
    }
    return g;
  }

  // The coordinate along the longest side of the bounding box: the order
  // used when the eigensolver fails
  std::vector<double> axisOrder(const layoutMesh &mesh,
                                const std::vector<int> &part)
  {
    SPoint3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    std::vector<SPoint3> c(part.size());
    for(std::size_t i = 0; i < part.size(); i++) {
      c[i] = centroid(mesh, part[i]);
      for(int d = 0; d < 3; d++) {
        lo[d] = std::min(lo[d], c[i][d]);
        hi[d] = std::max(hi[d], c[i][d]);
      }
    }
    int axis = 0;
    for(int d = 1; d < 3; d++)
      if(hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    std::vector<double> x(part.size());
    for(std::size_t i = 0; i < part.size(); i++) x[i] = c[i][axis];
    return x;
  }

  // Clusters of about `size` nodes of g grown breadth first (cluster[i] of
  // node i); returns their number
  int growClusters(const dualGraph &g, std::size_t n, std::size_t size,
                   std::vector<int> &cluster)
  {
    cluster.assign(n, -1);
    int count = 0;
    std::vector<int> queue;
    for(std::size_t seed = 0; seed < n; seed++) {
      if(cluster[seed] >= 0) continue;
      queue.assign(1, (int)seed);
      cluster[seed] = count;
      std::size_t members = 1;
      for(std::size_t q = 0; q < queue.size() && members < size; q++)
        for(int de : g.incident[queue[q]]) {
          const int j =
            g.edges[de][0] == queue[q] ? g.edges[de][1] : g.edges[de][0];
          if(cluster[j] >= 0 || members >= size) continue;
          cluster[j] = count;
          members++;
          queue.push_back(j);
        }
      count++;
    }
    return count;
  }

  // The Fiedler vector of g computed on the graph of clusters of about n /
  // coarseNodes of its nodes (weights summed between clusters), taken to
  // the nodes and smoothed there by Jacobi sweeps (the clusters' own
  // boundaries are no cut); empty if the eigensolver fails
  std::vector<double> coarseFiedler(const dualGraph &g, std::size_t n,
                                    std::size_t coarseNodes)
  {
    std::vector<int> cluster;
    const std::size_t size = (n + coarseNodes - 1) / coarseNodes;
    const int nc = growClusters(g, n, size, cluster);
    std::vector<std::pair<std::array<int, 2>, double> > between;
    for(std::size_t e = 0; e < g.edges.size(); e++) {
      int a = cluster[g.edges[e][0]], b = cluster[g.edges[e][1]];
      if(a == b) continue;
      if(a > b) std::swap(a, b);
      between.push_back({{{a, b}}, g.weights[e]});
    }
    std::sort(between.begin(), between.end());
    std::vector<std::array<int, 2> > edges;
    std::vector<double> weights;
    for(const auto &b : between) {
      if(!edges.empty() && edges.back() == b.first)
        weights.back() += b.second;
      else {
        edges.push_back(b.first);
        weights.push_back(b.second);
      }
    }
    fiedlerResult f = fiedlerVector(nc, edges, weights);
    if(!f.error.ok()) return std::vector<double>();
    std::vector<double> x(n), next(n);
    for(std::size_t i = 0; i < n; i++) x[i] = f.x[cluster[i]];
    // about the clusters' diameter in sweeps
    const int sweeps = 2 * (int)std::ceil(std::sqrt((double)size));
    for(int s = 0; s < sweeps; s++) {
      for(std::size_t i = 0; i < n; i++) {
        double sum = 0., weight = 0.;
        for(int de : g.incident[i]) {
          const int j =
            g.edges[de][0] == (int)i ? g.edges[de][1] : g.edges[de][0];
          sum += g.weights[de] * x[j];
          weight += g.weights[de];
        }
        next[i] = weight > 0. ? 0.5 * (x[i] + sum / weight) : x[i];
      }
      x.swap(next);
    }
    return x;
  }

  // The first and last positions in `order` of the triangles at each of
  // `nodes` (sorted); first > last for a node on none
  std::vector<std::array<std::size_t, 2> >
  fanRanges(const layoutMesh &mesh, const std::vector<int> &part,
            const std::vector<int> &order, const std::vector<int> &nodes)
  {
    std::vector<std::array<std::size_t, 2> > range(nodes.size(),
                                                   {{part.size(), 0}});
    for(std::size_t k = 0; k < order.size(); k++)
      for(int c = 0; c < 3; c++) {
        const int node = mesh.triangles[part[order[k]]][c];
        auto it = std::lower_bound(nodes.begin(), nodes.end(), node);
        if(it == nodes.end() || *it != node) continue;
        auto &r = range[it - nodes.begin()];
        r[0] = std::min(r[0], k);
        r[1] = std::max(r[1], k);
      }
    return range;
  }

  // The levels of the sweep (order[0..k] on one side) that cut where the
  // part's maps fail: through one of check.cutThrough (between the first
  // and the last of its triangles in the order), or between the two nodes
  // of a pair of check.cutApart (between the last triangle of one and the
  // first of the other, else between the middles of their triangles).
  // Of those leaving at least a tenth of the area on each side and at most
  // twice as long for the area they separate as `fallback`'s, the one of
  // smallest ratio (`found`); `fallback` without any (a level cutting a sliver
  // off around the failure leaves a face smaller than the mesh, a long cut
  // pinches and leaves parts that fail again, and where the maps fail all
  // along a part that winds around, any level does).
  std::size_t levelAtFailure(const layoutMesh &mesh,
                             const std::vector<int> &part,
                             const std::vector<int> &order,
                             const partCheck &check,
                             const std::vector<double> &ratio,
                             std::size_t fallback, bool &found)
  {
    found = false;
    if(fallback >= ratio.size()) return fallback;
    // the fans of every node named, in one pass over the part
    std::vector<int> nodes(check.cutThrough);
    for(const auto &pr : check.cutApart)
      nodes.insert(nodes.end(), {pr[0], pr[1]});
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const auto ranges = fanRanges(mesh, part, order, nodes);
    auto rangeOf = [&](int node) {
      return ranges[std::lower_bound(nodes.begin(), nodes.end(), node) -
                    nodes.begin()];
    };
    // the levels [from, to) of each place, marked by their differences
    std::vector<int> marks(ratio.size() + 1, 0);
    auto mark = [&](std::size_t from, std::size_t to) {
      to = std::min(to, ratio.size());
      if(from >= to) return;
      marks[from]++;
      marks[to]--;
    };
    for(int v : check.cutThrough) {
      const auto r = rangeOf(v);
      mark(r[0], r[1]);
    }
    for(const auto &pr : check.cutApart) {
      std::array<std::size_t, 2> a = rangeOf(pr[0]), b = rangeOf(pr[1]);
      if(a[0] > a[1] || b[0] > b[1]) continue; // not on the part
      if(a[0] > b[0]) std::swap(a, b);
      // every triangle of one before every triangle of the other, else
      // between the middles of their triangles
      if(a[1] < b[0])
        mark(a[1], b[0]);
      else
        mark((a[0] + a[1]) / 2, (b[0] + b[1]) / 2);
    }
    const double longest = 2. * ratio[fallback];
    std::size_t best = fallback;
    double bestRatio = std::numeric_limits<double>::max();
    int inside = 0;
    for(std::size_t k = 0; k < ratio.size(); k++) {
      inside += marks[k];
      if(inside > 0 && ratio[k] < bestRatio && ratio[k] <= longest) {
        best = k;
        bestRatio = ratio[k];
        found = true;
      }
    }
    return best;
  }

} // namespace

std::vector<char> bisectPart(const layoutMesh &mesh,
                             const triangleAdjacency &adjacency,
                             const std::vector<int> &part,
                             std::size_t coarseNodes, const partCheck &check,
                             bool *atFailure,
                             const std::vector<std::array<int, 3> > *across)
{
  const std::size_t n = part.size();
  std::vector<char> side(n, 0);
  if(n < 2) return side;
  std::vector<std::array<int, 3> > own;
  if(!across) own = partNeighbours(adjacency, part, mesh.triangles.size());
  dualGraph g = makeDualGraph(mesh, adjacency, part, across ? *across : own);
  std::vector<double> x;
  if(coarseNodes >= 2 && n > 2 * coarseNodes)
    x = coarseFiedler(g, n, coarseNodes);
  else {
    fiedlerResult f = fiedlerVector((int)n, g.edges, g.weights);
    if(f.error.ok()) x.assign(f.x.data(), f.x.data() + n);
  }
  if(x.empty()) x = axisOrder(mesh, part);

  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&x](int a, int b) { return x[a] < x[b]; });
  std::vector<double> areas(n);
  double total = 0.;
  for(std::size_t i = 0; i < n; i++)
    total += (areas[i] = triangleArea(mesh, part[i]));
  const bool byCount = !(total > 0.); // all degenerate: count triangles
  if(byCount) {
    std::fill(areas.begin(), areas.end(), 1.);
    total = (double)n;
  }

  // Sweep: triangles enter side 1 in the order of x; the cut length changes
  // by the dual edges of the triangle that enters. Keep the cut with the
  // smallest length over the smaller side's area, among those leaving at
  // least a tenth of the area on each side (else the middle one).
  std::vector<char> in(n, 0);
  std::vector<double> ratio(n - 1, std::numeric_limits<double>::max());
  double cut = 0., sideArea = 0.;
  double bestRatio = std::numeric_limits<double>::max();
  std::size_t best = n / 2 - (n % 2 == 0 ? 1 : 0);
  for(std::size_t k = 0; k + 1 < n; k++) {
    const int i = order[k];
    in[i] = 1;
    sideArea += areas[i];
    for(int de : g.incident[i]) {
      int j = g.edges[de][0] == i ? g.edges[de][1] : g.edges[de][0];
      cut += in[j] ? -g.lengths[de] : g.lengths[de];
    }
    const double smaller = std::min(sideArea, total - sideArea);
    if(smaller < 0.1 * total) continue;
    ratio[k] = cut / smaller;
    if(ratio[k] < bestRatio) {
      bestRatio = ratio[k];
      best = k;
    }
  }
  bool found = false;
  if(!check.cutThrough.empty() || !check.cutApart.empty())
    best = levelAtFailure(mesh, part, order, check, ratio, best, found);
  if(atFailure) *atFailure = found;
  for(std::size_t k = 0; k <= best; k++) side[order[k]] = 1;
  return side;
}

std::vector<std::vector<int> >
partComponents(const triangleAdjacency &adjacency, const std::vector<int> &part,
               std::size_t numTriangles,
               const std::vector<std::array<int, 3> > *given)
{
  std::vector<std::array<int, 3> > own;
  if(!given) own = partNeighbours(adjacency, part, numTriangles);
  const std::vector<std::array<int, 3> > &across = given ? *given : own;
  std::vector<std::vector<int> > components;
  std::vector<char> seen(part.size(), 0);
  std::vector<int> stack;
  for(std::size_t s = 0; s < part.size(); s++) {
    if(seen[s]) continue;
    components.emplace_back();
    stack.assign(1, (int)s);
    seen[s] = 1;
    while(!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      components.back().push_back(part[i]);
      for(int k = 0; k < 3; k++) {
        const int j = across[i][k];
        if(j < 0 || seen[j]) continue;
        seen[j] = 1;
        stack.push_back(j);
      }
    }
  }
  return components;
}
} // namespace reparam

