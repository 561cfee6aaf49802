// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "bijectivityCheck.h"
#include "flipRepair.h"

namespace reparam {

std::vector<std::array<double, 2> >
starKernel(const std::vector<std::array<double, 4> > &edges,
           const std::array<double, 4> &box, int orientation)
{
  std::vector<std::array<double, 2> > poly = {{{box[0], box[1]}},
                                              {{box[2], box[1]}},
                                              {{box[2], box[3]}},
                                              {{box[0], box[3]}}};
  // Sutherland-Hodgman: clip by the half-plane left of each edge (right for
  // orientation -1). Floating point: the caller checks the result exactly.
  for(const auto &e : edges) {
    const double dx = e[2] - e[0], dy = e[3] - e[1];
    auto side = [&](const std::array<double, 2> &p) {
      return orientation * (dx * (p[1] - e[1]) - dy * (p[0] - e[0]));
    };
    std::vector<std::array<double, 2> > out;
    for(std::size_t i = 0; i < poly.size(); i++) {
      const auto &p = poly[i], &q = poly[(i + 1) % poly.size()];
      double sp = side(p), sq = side(q);
      if(sp > 0.) out.push_back(p);
      if((sp > 0.) != (sq > 0.) && sp != sq) {
        double t = sp / (sp - sq);
        out.push_back({{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
      }
    }
    poly.swap(out);
    if(poly.size() < 3) return {};
  }
  return poly;
}

namespace {

  // Area centroid of a simple polygon (its vertex mean if degenerate)
  std::array<double, 2> centroid(const std::vector<std::array<double, 2> > &p)
  {
    double a = 0., cx = 0., cy = 0., mx = 0., my = 0.;
    for(std::size_t i = 0; i < p.size(); i++) {
      const auto &s = p[i], &t = p[(i + 1) % p.size()];
      double w = s[0] * t[1] - t[0] * s[1];
      a += w;
      cx += (s[0] + t[0]) * w;
      cy += (s[1] + t[1]) * w;
      mx += s[0] / p.size();
      my += s[1] / p.size();
    }
    if(std::fabs(a) < 1e-300) return {{mx, my}};
    return {{cx / (3. * a), cy / (3. * a)}};
  }

  struct patchStars {
    // triangles around each node (CSR)
    std::vector<int> start, triangles;
    // boundary neighbours (previous, next along its loop), -1 inside
    std::vector<std::array<int, 2> > boundaryNeighbours;
  };

  patchStars makeStars(const discretePatch &patch)
  {
    patchStars s;
    const std::size_t n = patch.points.size();
    s.start.assign(n + 1, 0);
    for(const auto &t : patch.triangles)
      for(int v : t) s.start[v + 1]++;
    for(std::size_t i = 0; i < n; i++) s.start[i + 1] += s.start[i];
    s.triangles.resize(s.start[n]);
    std::vector<int> next(s.start.begin(), s.start.end() - 1);
    for(std::size_t t = 0; t < patch.triangles.size(); t++)
      for(int v : patch.triangles[t]) s.triangles[next[v]++] = (int)t;
    s.boundaryNeighbours.assign(n, {{-1, -1}});
    for(const auto &loop : patch.boundaryLoops)
      for(std::size_t k = 0; k < loop.size(); k++)
        s.boundaryNeighbours[loop[k]] = {
          {loop[(k + loop.size() - 1) % loop.size()],
           loop[(k + 1) % loop.size()]}};
    return s;
  }

  // Would node i at p leave every triangle around it well oriented?
  bool acceptable(const discretePatch &patch, const patchStars &stars,
                  const std::vector<double> &uv, int i, const double *p,
                  int orientation)
  {
    for(int k = stars.start[i]; k < stars.start[i + 1]; k++) {
      const auto &t = patch.triangles[stars.triangles[k]];
      const double *x[3];
      for(int j = 0; j < 3; j++) x[j] = (t[j] == i) ? p : &uv[2 * t[j]];
      if(!(orientation * orientation2d(x[0], x[1], x[2]) > 0.)) return false;
    }
    return true;
  }

  // The opposite edges of node i's triangles, in their orientation, and the
  // bounding box of its one-ring
  void starOf(const discretePatch &patch, const patchStars &stars,
              const std::vector<double> &uv, int i,
              std::vector<std::array<double, 4> > &edges,
              std::array<double, 4> &box)
  {
    edges.clear();
    box = {{1e300, 1e300, -1e300, -1e300}};
    for(int k = stars.start[i]; k < stars.start[i + 1]; k++) {
      const auto &t = patch.triangles[stars.triangles[k]];
      int j = 0;
      while(t[j] != i) j++;
      int a = t[(j + 1) % 3], b = t[(j + 2) % 3];
      edges.push_back({{uv[2 * a], uv[2 * a + 1], uv[2 * b], uv[2 * b + 1]}});
      for(int c : {a, b}) {
        box[0] = std::min(box[0], uv[2 * c]);
        box[1] = std::min(box[1], uv[2 * c + 1]);
        box[2] = std::max(box[2], uv[2 * c]);
        box[3] = std::max(box[3], uv[2 * c + 1]);
      }
    }
  }

  // Boundary check (Fig. 11): towards and past the projection of u_i onto
  // the segment of its boundary neighbours
  bool boundaryMove(const discretePatch &patch, const patchStars &stars,
                    std::vector<double> &uv, int i, int orientation)
  {
    const int a = stars.boundaryNeighbours[i][0],
              b = stars.boundaryNeighbours[i][1];
    const double *ua = &uv[2 * a], *ub = &uv[2 * b], *ui = &uv[2 * i];
    const double dx = ub[0] - ua[0], dy = ub[1] - ua[1];
    const double len2 = dx * dx + dy * dy;
    if(!(len2 > 0.)) return false;
    double s = ((ui[0] - ua[0]) * dx + (ui[1] - ua[1]) * dy) / len2;
    s = std::min(1., std::max(0., s));
    const double proj[2] = {ua[0] + s * dx, ua[1] + s * dy};
    for(double t : {0.5, 1., 1.5, 2., 3.}) {
      double p[2] = {ui[0] + t * (proj[0] - ui[0]),
                     ui[1] + t * (proj[1] - ui[1])};
      if(acceptable(patch, stars, uv, i, p, orientation)) {
        uv[2 * i] = p[0];
        uv[2 * i + 1] = p[1];
        return true;
      }
    }
    return false;
  }

  // Cavity check: the centroid of the kernel of the one-ring
  bool kernelMove(const discretePatch &patch, const patchStars &stars,
                  std::vector<double> &uv, int i, int orientation)
  {
    std::vector<std::array<double, 4> > edges;
    std::array<double, 4> box;
    starOf(patch, stars, uv, i, edges, box);
    std::vector<std::array<double, 2> > kernel =
      starKernel(edges, box, orientation);
    if(kernel.empty()) return false;
    std::array<double, 2> c = centroid(kernel);
    if(!acceptable(patch, stars, uv, i, c.data(), orientation)) return false;
    uv[2 * i] = c[0];
    uv[2 * i + 1] = c[1];
    return true;
  }

  std::vector<int> flipped(const discretePatch &patch,
                           const std::vector<double> &uv, int orientation)
  {
    std::vector<int> f;
    for(std::size_t t = 0; t < patch.triangles.size(); t++) {
      const auto &tri = patch.triangles[t];
      if(!(orientation *
             orientation2d(&uv[2 * tri[0]], &uv[2 * tri[1]], &uv[2 * tri[2]]) >
           0.))
        f.push_back((int)t);
    }
    return f;
  }

} // namespace

flipRepairResult repairFlips(const discretePatch &patch,
                             std::vector<double> &uv, int orientation,
                             bool freeBoundary, int maxPasses)
{
  flipRepairResult result;
  std::vector<int> bad = flipped(patch, uv, orientation);
  result.flippedBefore = bad.size();
  if(bad.empty()) return result;
  patchStars stars = makeStars(patch);
  for(int pass = 0; pass < maxPasses && !bad.empty(); pass++) {
    result.passes++;
    std::vector<int> nodes;
    for(int t : bad)
      for(int v : patch.triangles[t]) nodes.push_back(v);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    int moved = 0;
    for(int i : nodes) {
      const bool onBoundary = stars.boundaryNeighbours[i][0] >= 0;
      if(onBoundary && !freeBoundary) continue;
      if(onBoundary && boundaryMove(patch, stars, uv, i, orientation))
        moved++;
      else if(kernelMove(patch, stars, uv, i, orientation))
        moved++;
    }
    result.movedNodes += moved;
    bad = flipped(patch, uv, orientation);
    if(moved == 0) break;
  }
  result.flippedAfter = bad.size();
  return result;
}
} // namespace reparam

