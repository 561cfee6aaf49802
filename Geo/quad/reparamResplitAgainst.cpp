// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <set>
#include "GFace.h"
#include "GmshMessage.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "polygonSplits.h"
#include "quadQuality.h"
#include "reparamFaceEdits.h"
#include "reparamOptimizableMesh.h"
#include "reparamResplitAgainst.h"
#include "reparamSurfaceMesh.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // gf's elements: its triangles, then its quadrangles (element e >=
  // triangles is quadrangle e - triangles), as corner lists
  struct faceElements {
    std::vector<MVertex *> nodes;
    std::vector<SPoint3> points;
    std::vector<std::vector<int> > corners;
    std::size_t triangles = 0;
  };

  faceElements elementsOf(GFace *gf)
  {
    faceElements f;
    const surfaceMesh m = reparamMeshOfFaces({gf}, f.nodes);
    f.points = m.points;
    for(const auto &t : m.triangles) f.corners.push_back({t.begin(), t.end()});
    for(const auto &q : m.quadrangles)
      f.corners.push_back({q.begin(), q.end()});
    f.triangles = m.triangles.size();
    return f;
  }

  // The test of the report (Mesh/quality/meshFidelity.h) on an element's corners
  bool pointsAgainst(const std::vector<SPoint3> &x, const std::vector<int> &c,
                     const surfaceMesh &input,
                     const closestTriangleSearch &onInput)
  {
    if(c.size() == 3)
      return triangleAgainstInput(x[c[0]], x[c[1]], x[c[2]], input, onInput);
    return quadrangleAgainstInput(x[c[0]], x[c[1]], x[c[2]], x[c[3]], input,
                                  onInput);
  }

  double qualityOf(const std::vector<SPoint3> &x, const std::vector<int> &c)
  {
    if(c.size() == 3) return triangleKappa(x[c[0]], x[c[1]], x[c[2]]);
    return quadEta(x[c[0]], x[c[1]], x[c[2]], x[c[3]]);
  }

  // The polygon of the elements ce and cn sharing the edge (a, b) (a then
  // b in ce, the other way in cn): ce's corners from b round to a, then
  // cn's between a and b; false if a corner repeats
  bool unionOf(const std::vector<int> &ce, const std::vector<int> &cn, int a,
               int b, std::vector<int> &polygon)
  {
    const int ne = (int)ce.size(), nn = (int)cn.size();
    int k = 0, l = 0;
    while(k < ne && !(ce[k] == a && ce[(k + 1) % ne] == b)) k++;
    while(l < nn && !(cn[l] == b && cn[(l + 1) % nn] == a)) l++;
    if(k == ne || l == nn) return false;
    polygon.clear();
    for(int i = 0; i < ne; i++) polygon.push_back(ce[(k + 1 + i) % ne]);
    for(int i = 0; i + 2 < nn; i++) polygon.push_back(cn[(l + 2 + i) % nn]);
    return std::set<int>(polygon.begin(), polygon.end()).size() ==
           polygon.size();
  }

  // The elements of a split as corner lists
  std::vector<std::vector<int> > elementsOf(const polygonSplit &s)
  {
    std::vector<std::vector<int> > e;
    for(const auto &t : s.triangles) e.push_back({t.begin(), t.end()});
    for(const auto &q : s.quadrangles) e.push_back({q.begin(), q.end()});
    return e;
  }

  // The best split of the polygon none of whose elements points against
  // the input (reversed: gf's elements turn against it); false if none
  // with at most `maxTriangles` triangles
  bool bestSplit(const faceElements &f, const std::vector<int> &polygon,
                 std::size_t maxTriangles, const surfaceMesh &input,
                 const closestTriangleSearch &onInput, bool reversed,
                 polygonSplit &best)
  {
    double bestWorst = 0.;
    std::size_t bestTriangles = 0;
    bool found = false;
    for(const polygonSplit &s : polygonSplits(polygon)) {
      if(s.triangles.size() > maxTriangles) continue;
      double worst = 1.;
      for(const std::vector<int> &c : elementsOf(s))
        worst = std::min(worst, qualityOf(f.points, c));
      if(!(worst > 0.) || (found && worst < bestWorst) ||
         (found && worst == bestWorst && s.triangles.size() >= bestTriangles))
        continue;
      bool along = true;
      for(const std::vector<int> &c : elementsOf(s))
        along = along && pointsAgainst(f.points, c, input, onInput) == reversed;
      if(!along) continue;
      best = s;
      bestWorst = worst;
      bestTriangles = s.triangles.size();
      found = true;
    }
    return found;
  }

  // The elements of f against the input
  std::vector<int> againstOf(const faceElements &f, const surfaceMesh &input,
                             const closestTriangleSearch &onInput,
                             bool reversed)
  {
    std::vector<int> against;
    for(std::size_t e = 0; e < f.corners.size(); e++)
      if(pointsAgainst(f.points, f.corners[e], input, onInput) != reversed)
        against.push_back((int)e);
    return against;
  }

  // One round over gf's elements against the input (`against`, of f, gf's
  // elements now): each split again with the first neighbour that takes it
  std::size_t resplitOnce(GFace *gf, const faceElements &f,
                          const std::vector<int> &against,
                          const surfaceMesh &input,
                          const closestTriangleSearch &onInput, bool reversed)
  {
    std::map<std::pair<int, int>, std::vector<int> > byEdge;
    for(std::size_t e = 0; e < f.corners.size(); e++) {
      const std::vector<int> &c = f.corners[e];
      for(std::size_t k = 0; k < c.size(); k++) {
        const int a = c[k], b = c[(k + 1) % c.size()];
        byEdge[std::make_pair(std::min(a, b), std::max(a, b))].push_back(
          (int)e);
      }
    }
    std::vector<bool> gone(f.corners.size(), false);
    std::vector<polygonSplit> splits;
    for(int e : against) {
      if(gone[e]) continue;
      const std::vector<int> &c = f.corners[e];
      for(std::size_t k = 0; k < c.size() && !gone[e]; k++) {
        const int a = c[k], b = c[(k + 1) % c.size()];
        const std::vector<int> &on =
          byEdge[std::make_pair(std::min(a, b), std::max(a, b))];
        if(on.size() != 2) continue; // a curve's edge, or not manifold
        const int n = on[0] == e ? on[1] : on[0];
        std::vector<int> polygon;
        if(gone[n] || !unionOf(c, f.corners[n], a, b, polygon)) continue;
        const std::size_t triangles =
          (c.size() == 3) + (f.corners[n].size() == 3);
        polygonSplit s;
        if(!bestSplit(f, polygon, triangles + 2, input, onInput, reversed, s))
          continue;
        gone[e] = gone[n] = true;
        splits.push_back(s);
      }
    }
    if(splits.empty()) return 0;
    reparamDropMarked(
      gf->triangles,
      std::vector<bool>(gone.begin(), gone.begin() + f.triangles));
    reparamDropMarked(
      gf->quadrangles,
      std::vector<bool>(gone.begin() + f.triangles, gone.end()));
    for(const polygonSplit &s : splits) {
      for(const auto &t : s.triangles)
        gf->triangles.push_back(
          new MTriangle(f.nodes[t[0]], f.nodes[t[1]], f.nodes[t[2]]));
      for(const auto &q : s.quadrangles)
        gf->quadrangles.push_back(new MQuadrangle(
          f.nodes[q[0]], f.nodes[q[1]], f.nodes[q[2]], f.nodes[q[3]]));
    }
    return splits.size();
  }

} // namespace

std::size_t reparamResplitElementsAgainstInput(GFace *gf)
{
  if(gf->quadrangles.empty()) return 0;
  const surfaceMesh input = inputTriangulationOf(gf);
  if(input.triangles.empty()) return 0;
  const closestTriangleSearch onInput(input.points, input.triangles);
  const bool reversed = meshReversedOnInput(gf, input, onInput);
  // a few rounds: an element another one's split took as its neighbour
  // tries its other neighbours in the next
  std::size_t splits = 0, before = 0, after = 0;
  for(int round = 0; round < 4; round++) {
    const faceElements f = elementsOf(gf);
    const std::vector<int> against = againstOf(f, input, onInput, reversed);
    if(!round) before = against.size();
    after = against.size();
    const std::size_t done =
      against.empty() ? 0 :
                        resplitOnce(gf, f, against, input, onInput, reversed);
    if(!done) break;
    splits += done;
    if(round == 3)
      after = againstOf(elementsOf(gf), input, onInput, reversed).size();
  }
  if(!splits) return 0;
  Msg::Info("Reparam: surface %d: %lu element%s against the input split "
            "again with a neighbour into elements along it (%lu -> %lu "
            "against the input)",
            gf->tag(), splits, splits > 1 ? "s" : "", before, after);
  return splits;
}
} // namespace reparam

