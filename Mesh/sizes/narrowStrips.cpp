// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include "SVector3.h"
#include "boxTree.h"
#include "closestTriangle.h"
#include "narrowStrips.h"
#include "surfaceMesh.h"
#include "triangleAdjacency.h"

namespace reparam {

namespace {

  // cos 60 degrees: the sides of a fillet bent by 90 degrees see each
  // other 45 degrees off their normals
  const double straightAcross = 0.5;
  // a strip's sides are farther apart along the boundary than this many
  // times across (a tip of angle t: 1 / sin(t / 2))
  const double fartherAlong = 4.;
  // samples along the boundary, per size
  const double samplesPerSize = 4.;
  // a narrowing shorter than the size along the boundary is left to the
  // size: one triangle spans it either way, and sizes that shrink and grow
  // back within one element only bend the curve's mesh (the little necks
  // of a scan's classification)
  const double shortestRun = 1.;
  // a boundary needing more samples than this is left alone: the size far
  // below the model's scale, whose curves Gmsh would not mesh either
  // (Geo/sizes/reparamSizeGrading.h refuses them)
  const double mostSamples = 1e6;

  struct sample {
    stripWidth strip;
    int loop;
    double s, step, size;
  };

  // The samples of runs along the boundary at least shortestRun sizes long
  // (consecutive samples at most 1.5 steps apart; a closed loop's last run
  // goes on into its first)
  std::vector<stripWidth> longRuns(std::vector<sample> &samples,
                                   const std::vector<double> &loops)
  {
    std::sort(samples.begin(), samples.end(),
              [](const sample &x, const sample &y) {
                return x.loop < y.loop || (x.loop == y.loop && x.s < y.s);
              });
    // run[i]: the index of sample i's run
    std::vector<int> run(samples.size(), 0);
    std::vector<double> extent(1, 0.);
    for(std::size_t i = 0; i < samples.size(); i++) {
      const sample &x = samples[i];
      if(i > 0) {
        const sample &w = samples[i - 1];
        const bool joined =
          w.loop == x.loop && x.s - w.s <= 1.5 * std::max(w.step, x.step);
        run[i] = joined ? run[i - 1] : run[i - 1] + 1;
        if(!joined)
          extent.push_back(0.);
        else
          extent[run[i]] += x.s - w.s;
      }
    }
    // a closed loop's run across its start
    for(std::size_t i = 0, first = 0; i < samples.size(); i++) {
      if(i + 1 < samples.size() && samples[i + 1].loop == samples[i].loop)
        continue;
      const sample &last = samples[i], &start = samples[first];
      const double length = loops[last.loop];
      if(run[i] != run[first] && length > 0. &&
         length - last.s + start.s <= 1.5 * std::max(last.step, start.step)) {
        const double joined =
          extent[run[i]] + extent[run[first]] + length - last.s + start.s;
        extent[run[i]] = extent[run[first]] = joined;
      }
      first = i + 1;
    }
    std::vector<stripWidth> strips;
    for(std::size_t i = 0; i < samples.size(); i++)
      if(extent[run[i]] + samples[i].step >= shortestRun * samples[i].size)
        strips.push_back(samples[i].strip);
    return strips;
  }

  struct boundaryEdge {
    int a, b; // the walk along the loop enters at a
    SVector3 inward; // unit, towards the triangle; 0 for a sliver's
    int loop = -1;
    double s = 0.; // arc length at a along the loop
    bool side = true; // may be a strip's side
  };

  // The edges of one triangle, with their inward normals in `flat`
  std::vector<boundaryEdge> boundaryEdgesOf(const surfaceMesh &m,
                                            const std::vector<SPoint3> &flat)
  {
    const triangleAdjacency adjacency = makeTriangleAdjacency(m.triangles);
    std::vector<boundaryEdge> edges;
    for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
      if(adjacency.numTriangles((int)e) != 1) continue;
      boundaryEdge be;
      be.a = adjacency.edges[e][0];
      be.b = adjacency.edges[e][1];
      const std::array<int, 3> &t =
        m.triangles[adjacency.edgeTriangles[adjacency.edgeStart[e]]];
      const int opposite = t[0] + t[1] + t[2] - be.a - be.b;
      const SVector3 ab(flat[be.a], flat[be.b]);
      const SVector3 ac(flat[be.a], flat[opposite]);
      const double l2 = dot(ab, ab);
      if(l2 > 0.) {
        be.inward = ac - ab * (dot(ac, ab) / l2);
        if(be.inward.norm() > 0.) be.inward.normalize();
      }
      edges.push_back(be);
    }
    return edges;
  }

  // Walks the boundary loops (open chains from their ends first), setting
  // each edge's loop and arc length; returns each loop's length, negative
  // for an open chain (whose path does not wrap around)
  std::vector<double> walkLoops(const surfaceMesh &m,
                                std::vector<boundaryEdge> &edges)
  {
    std::unordered_map<int, std::vector<int> > at;
    for(std::size_t i = 0; i < edges.size(); i++) {
      at[edges[i].a].push_back((int)i);
      at[edges[i].b].push_back((int)i);
    }
    std::vector<int> starts;
    for(const auto &v : at)
      if(v.second.size() == 1) starts.push_back(v.first);
    for(const boundaryEdge &e : edges) starts.push_back(e.a);
    std::vector<double> lengths;
    for(int start : starts) {
      int next = -1;
      for(int e : at[start])
        if(edges[e].loop < 0) next = e;
      if(next < 0) continue;
      const int loop = (int)lengths.size();
      double s = 0.;
      int v = start;
      while(next >= 0) {
        boundaryEdge &e = edges[next];
        if(e.a != v) std::swap(e.a, e.b);
        e.loop = loop;
        e.s = s;
        s += m.points[e.a].distance(m.points[e.b]);
        v = e.b;
        next = -1;
        for(int n : at[v])
          if(edges[n].loop < 0) next = n;
      }
      lengths.push_back(v == start ? s : -s);
    }
    return lengths;
  }

  // The boundary edges within r of p, by a box tree over them
  class edgeSearch {
  public:
    edgeSearch(const std::vector<SPoint3> &points,
               const std::vector<boundaryEdge> &edges)
    {
      _tree.build(
        (int)edges.size(), 4,
        [&](int i, double *lo, double *hi) {
          const SPoint3 &a = points[edges[i].a], &b = points[edges[i].b];
          for(int k = 0; k < 3; k++) {
            lo[k] = std::min(a[k], b[k]);
            hi[k] = std::max(a[k], b[k]);
          }
        },
        [&](int i, int k) {
          return 0.5 * (points[edges[i].a][k] + points[edges[i].b][k]);
        });
    }
    template <class Visit>
    void within(const SPoint3 &p, double r, const Visit &visit) const
    {
      if(_tree.nodes.empty()) return;
      std::vector<int> stack(1, 0);
      while(!stack.empty()) {
        const auto &node = _tree.nodes[stack.back()];
        stack.pop_back();
        double d2 = 0.;
        for(int k = 0; k < 3; k++) {
          const double out =
            std::max(0., std::max(node.lo[k] - p[k], p[k] - node.hi[k]));
          d2 += out * out;
        }
        if(d2 > r * r) continue;
        if(node.left < 0) {
          for(int i = node.first; i < node.first + node.count; i++)
            visit(_tree.order[i]);
          continue;
        }
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }

  private:
    boxTree<3> _tree;
  };

  // Whether q on edge f lies across the surface from p on edge e (above):
  // pq in the flat points, d apart in space, sp and sq along the loops
  bool across(const boundaryEdge &e, double sp, const boundaryEdge &f,
              double sq, const SVector3 &pq, double d,
              const std::vector<double> &loops)
  {
    const double flat = pq.norm();
    if(!(d > 0.) || !(flat > 0.)) return false;
    if(dot(pq, e.inward) < straightAcross * flat ||
       -dot(pq, f.inward) < straightAcross * flat)
      return false;
    if(e.loop != f.loop) return true;
    double along = std::fabs(sp - sq);
    const double loop = loops[e.loop];
    if(loop > 0.) along = std::min(along, loop - along);
    return along > fartherAlong * d;
  }

} // namespace

std::vector<stripWidth>
narrowStripWidths(const surfaceMesh &m, const std::vector<SPoint3> &flat,
                  const std::function<double(const SPoint3 &)> &size,
                  double share, const std::function<bool(int, int)> &side)
{
  std::vector<boundaryEdge> edges = boundaryEdgesOf(m, flat);
  if(edges.empty()) return std::vector<stripWidth>();
  if(side)
    for(boundaryEdge &e : edges) e.side = side(e.a, e.b);
  const std::vector<double> loops = walkLoops(m, edges);
  double count = 0.;
  for(const boundaryEdge &e : edges) {
    const SPoint3 &a = m.points[e.a], &b = m.points[e.b];
    const double step = std::min(size(a), size(b)) / samplesPerSize;
    count += step > 0. ? a.distance(b) / step + 1. : 1.;
  }
  if(!(count <= mostSamples)) return std::vector<stripWidth>();
  const edgeSearch search(flat, edges);
  std::vector<sample> samples;
  for(const boundaryEdge &e : edges) {
    const SPoint3 &a = m.points[e.a], &b = m.points[e.b];
    const double length = a.distance(b);
    if(!e.side || !(length > 0.)) continue;
    // flat lengths per length in space along e, doubled: the search's
    // radius holds the strip's other side where the scale changes across
    const double scale = 2. * flat[e.a].distance(flat[e.b]) / length;
    const double step = std::min(size(a), size(b)) / samplesPerSize;
    const int n = step > 0. ? std::max(1, (int)std::ceil(length / step)) : 1;
    for(int i = 0; i < n; i++) {
      const double t = (double)i / n;
      const SPoint3 p = a + (b - a) * t;
      const SPoint3 pFlat = flat[e.a] + (flat[e.b] - flat[e.a]) * t;
      const double here = size(p), widest = share * here;
      double width = widest;
      search.within(pFlat, widest * scale, [&](int j) {
        const boundaryEdge &f = edges[j];
        if(&f == &e || !f.side) return;
        const SPoint3 &fa = flat[f.a], &fb = flat[f.b];
        const SPoint3 qFlat = closestPointOnSegment(pFlat, fa, fb);
        const double lf = fa.distance(fb);
        const double tf = lf > 0. ? fa.distance(qFlat) / lf : 0.;
        const SPoint3 q = m.points[f.a] + (m.points[f.b] - m.points[f.a]) * tf;
        const double d = p.distance(q);
        if(d >= width) return;
        const double sq = f.s + tf * m.points[f.a].distance(m.points[f.b]);
        if(across(e, e.s + t * length, f, sq, SVector3(pFlat, qFlat), d, loops))
          width = d;
      });
      if(width < widest)
        samples.push_back(
          {{p, width, e.a, e.b}, e.loop, e.s + t * length, step, here});
    }
  }
  return longRuns(samples, loops);
}
} // namespace reparam

