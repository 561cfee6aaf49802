// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include "SVector3.h"
#include "closestTriangle.h"
#include "inputNodesNear.h"
#include "quadConnectivity.h"
#include "quadEdgeRotation.h"
#include "quadFidelity.h"
#include "quadNodeSplit.h"
#include "quadQuality.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  typedef std::array<int, 4> quad;

  // A node's quadrangles in turn around it (counterclockwise, as they are
  // oriented): quads[i] = (v, nodes[i], its opposite corner, nodes[i + 1])
  struct ring {
    std::vector<int> nodes, quads;
  };

  // A split of v along nodes[i] and nodes[j] of its ring (i < j): the first
  // half keeps quads[i .. j - 1], the second the others
  struct split {
    int v, i, j;
  };

  // The mesh's connectivity, kept exact through the splits
  struct splitter : quadConnectivity {
    surfaceMesh &m;
    std::vector<int> &part, &owner, &splitFrom;
    std::vector<int> ideal;
    std::vector<bool> closed;
    const quadNodeSplitOptions &o;
    std::unique_ptr<inputNodesNear> nearInput;

    int partOf(int q) const { return part.empty() ? 0 : part[q]; }

    // v's ring, if v is an inner node of its owner's quadrangles only
    bool ringOf(int v, ring &r) const
    {
      if(owner[v] < 0 || onTriangle[v] || !closed[v] || quadsAt[v].empty())
        return false;
      std::map<int, std::pair<int, int> > from; // node -> (quad, next node)
      for(int q : quadsAt[v]) {
        if(partOf(q) != owner[v]) return false;
        const quad &Q = m.quadrangles[q];
        int k = 0;
        while(Q[k] != v) k++;
        if(!from.emplace(Q[(k + 1) % 4], std::make_pair(q, Q[(k + 3) % 4]))
              .second)
          return false;
      }
      int at = from.begin()->first;
      do {
        auto it = from.find(at);
        if(it == from.end() || r.nodes.size() >= from.size()) return false;
        r.nodes.push_back(at);
        r.quads.push_back(it->second.first);
        at = it->second.second;
      } while(at != r.nodes.front());
      return r.nodes.size() == from.size() &&
             r.nodes.size() == neighbours[v].size();
    }

    double cost(int v, int change) const
    {
      return quadConnectivity::cost(v, change, ideal);
    }

    // The change of the valences' squared distance to their ideal (4 for
    // the halves)
    double change(const ring &r, const split &s) const
    {
      const int n = (int)r.nodes.size();
      const int a = r.nodes[s.i], b = r.nodes[s.j];
      const double first = s.j - s.i + 1 - 4, second = n - (s.j - s.i) + 1 - 4;
      return first * first + second * second + cost(a, 1) + cost(b, 1) -
             cost(s.v, 0) - cost(a, 0) - cost(b, 0);
    }

    SPoint3 onInput(const SPoint3 &x) const
    {
      return o.onInput ? o.onInput->closest(x).point : x;
    }

    // The mean of the corners other than v of the ring's quadrangles from
    // `begin` on, `count` of them
    SPoint3 centroidOf(const ring &r, int v, int begin, int count) const
    {
      SPoint3 c(0., 0., 0.);
      int n = 0;
      for(int k = 0; k < count; k++)
        for(int x : m.quadrangles[r.quads[(begin + k) % r.quads.size()]])
          if(x != v) {
            c += m.points[x];
            n++;
          }
      return c * (1. / n);
    }

    // The worst eta of `after` (the ring's quadrangles, then the new one)
    // with the halves at p1 (point v) and p2 (point w, the last of m), or
    // -1 where one turns by o.maxTurn or more: an old one from where it
    // was, the new one from their mean
    double worstAt(const std::vector<quad> &after,
                   const std::vector<SVector3> &before, const SVector3 &mean,
                   int v, const SPoint3 &p1, const SPoint3 &p2)
    {
      const double cosTurn = std::cos(o.maxTurn);
      const SPoint3 old = m.points[v];
      m.points[v] = p1;
      m.points.back() = p2;
      double worst = 1.;
      for(std::size_t i = 0; i < after.size() && worst >= 0.; i++) {
        const SVector3 &was = i < before.size() ? before[i] : mean;
        if(dot(quadNormal(after[i], m.points), was) < cosTurn)
          worst = -1.;
        else
          worst = std::min(
            worst, quadEta(m.points[after[i][0]], m.points[after[i][1]],
                           m.points[after[i][2]], m.points[after[i][3]]));
      }
      m.points[v] = old;
      return worst;
    }

    // Whether, with the halves at p1 and p2, the new quadrangles pass
    // within o.nodeTolerance * side of v's old place and of the input nodes
    // under the ring (or no farther from those than the old ones), and
    // follow the input as closely as the old ones. The input nodes are
    // checked as the short-edge collapses check them (checking the removed
    // point alone, a collapse cut across a coarse input; measured in
    // bench/README.md#nodes-split)
    bool followsInput(const std::vector<quad> &before,
                      const std::vector<quad> &after, int v, const SPoint3 &p1,
                      const SPoint3 &p2, double side)
    {
      if(!o.onInput) return true;
      const SPoint3 old = m.points[v];
      const double was = farthestCentreFromInput(before, m.points, *o.onInput);
      std::vector<std::pair<SPoint3, double> > under;
      if(nearInput) {
        double radius = 0.;
        for(const quad &Q : before)
          for(int x : Q) radius = std::max(radius, m.points[x].distance(old));
        for(int n :
            nearInput->within(o.onInput->closest(old).triangle, old, radius)) {
          const SPoint3 &p = o.input->points[n];
          under.push_back(
            std::make_pair(p, distanceToQuadrangles(p, before, m.points)));
        }
      }
      m.points[v] = p1;
      m.points.back() = p2;
      bool near =
        distanceToQuadrangles(old, after, m.points) <= o.nodeTolerance * side;
      for(std::size_t i = 0; i < under.size() && near; i++)
        near = distanceToQuadrangles(under[i].first, after, m.points) <=
               std::max(under[i].second, o.nodeTolerance * side);
      const double now = farthestCentreFromInput(after, m.points, *o.onInput);
      m.points[v] = old;
      return near && now <= was + o.tolerance * side;
    }

    // Splits v along its ring's nodes i and j where the valences' change
    // is at most `most` and the halves have places passing o's tests
    bool apply(const ring &r, const split &s, double most)
    {
      const int n = (int)r.nodes.size(), v = s.v;
      const int a = r.nodes[s.i], b = r.nodes[s.j];
      if(s.j - s.i < 2 || n - (s.j - s.i) < 2 || neighbours[a].count(b) ||
         change(r, s) > most)
        return false;
      const int w = (int)m.points.size();
      std::vector<quad> before, after;
      std::vector<SVector3> normals;
      SVector3 mean(0., 0., 0.);
      double side = 0.;
      for(int k = 0; k < n; k++) {
        const quad &Q = m.quadrangles[r.quads[k]];
        before.push_back(Q);
        normals.push_back(quadNormal(Q, m.points));
        mean += normals.back();
        for(int j = 0; j < 4; j++)
          side += m.points[Q[j]].distance(m.points[Q[(j + 1) % 4]]) / (4. * n);
        quad next = Q;
        const bool second = k < s.i || k >= s.j;
        for(int &x : next)
          if(x == v && second) x = w;
        after.push_back(next);
      }
      const double length = mean.norm();
      if(length <= 0.) return false;
      mean *= 1. / length;
      after.push_back({{w, a, v, b}});
      const SPoint3 c1 = centroidOf(r, v, s.i, s.j - s.i),
                    c2 = centroidOf(r, v, s.j, n - (s.j - s.i));
      const SPoint3 x = m.points[v];
      m.points.push_back(x);
      double best = -1.;
      SPoint3 p1, p2;
      for(const SPoint3 &t1 : {onInput(c1), onInput((x + c1) * 0.5)})
        for(const SPoint3 &t2 : {onInput(c2), onInput((x + c2) * 0.5)}) {
          const double worst = worstAt(after, normals, mean, v, t1, t2);
          if(worst > best) {
            best = worst;
            p1 = t1;
            p2 = t2;
          }
        }
      if(best < o.minEta || !followsInput(before, after, v, p1, p2, side)) {
        m.points.pop_back();
        return false;
      }
      m.points[v] = p1;
      m.points.back() = p2;
      connect(r, s, w, after);
      return true;
    }

    // The new point w, the quadrangles `after` and the connectivity
    void connect(const ring &r, const split &s, int w,
                 const std::vector<quad> &after)
    {
      const int n = (int)r.nodes.size(), v = s.v;
      const int a = r.nodes[s.i], b = r.nodes[s.j];
      const int q = (int)m.quadrangles.size();
      for(int k = 0; k < n; k++) m.quadrangles[r.quads[k]] = after[k];
      m.quadrangles.push_back(after.back());
      if(!part.empty()) part.push_back(partOf(r.quads[0]));
      owner.push_back(owner[v]);
      splitFrom.push_back(v);
      ideal.push_back(4);
      closed.push_back(true);
      onTriangle.push_back(false);
      neighbours.push_back(std::set<int>());
      quadsAt.push_back(std::set<int>());
      for(int k = s.j; k <= s.i + n; k++) {
        const int x = r.nodes[k % n];
        neighbours[w].insert(x);
        neighbours[x].insert(w);
        if(x != a && x != b) {
          neighbours[x].erase(v);
          neighbours[v].erase(x);
        }
      }
      for(int k = 0; k < n; k++)
        if(k < s.i || k >= s.j) {
          quadsAt[v].erase(r.quads[k]);
          quadsAt[w].insert(r.quads[k]);
        }
      for(int x : {v, w, a, b}) quadsAt[x].insert(q);
    }

    // The splits that make the mesh more regular, best first
    std::size_t sweep()
    {
      std::vector<std::tuple<double, int, int, int> > candidates;
      for(int v = 0; v < (int)m.points.size(); v++) {
        ring r;
        if(!ringOf(v, r)) continue;
        const int n = (int)r.nodes.size();
        for(int i = 0; i < n; i++)
          for(int j = i + 2; j <= n - 2 + i && j < n; j++) {
            const double c = change(r, {v, i, j});
            if(c < 0.)
              candidates.push_back(
                std::make_tuple(c, v, r.nodes[i], r.nodes[j]));
          }
      }
      std::sort(candidates.begin(), candidates.end());
      std::size_t splits = 0;
      std::set<int> touched;
      for(const auto &c : candidates) {
        const int v = std::get<1>(c), a = std::get<2>(c), b = std::get<3>(c);
        // once per pass around a split: its valences changed
        if(touched.count(v) || touched.count(a) || touched.count(b)) continue;
        ring r;
        if(!ringOf(v, r)) continue;
        const int i = (int)(std::find(r.nodes.begin(), r.nodes.end(), a) -
                            r.nodes.begin()),
                  j = (int)(std::find(r.nodes.begin(), r.nodes.end(), b) -
                            r.nodes.begin());
        if(i >= (int)r.nodes.size() || j >= (int)r.nodes.size()) continue;
        if(!apply(r, {v, std::min(i, j), std::max(i, j)}, -0.5)) continue;
        splits++;
        for(int x : r.nodes) touched.insert(x);
        touched.insert(v);
      }
      return splits;
    }
  };

} // namespace

quadNodeSplitResult splitQuadNodes(surfaceMesh &m, std::vector<int> &part,
                                   std::vector<int> &owner,
                                   std::vector<int> &splitFrom,
                                   const quadNodeSplitOptions &o)
{
  quadNodeSplitResult r;
  splitFrom.assign(m.points.size(), -1);
  r.irregularBefore = irregularNodes(m);
  splitter pass{{}, m, part, owner, splitFrom, idealValences(m), closedRings(m),
                o};
  pass.build(m);
  if(o.input && o.onInput) pass.nearInput.reset(new inputNodesNear(*o.input));
  while(r.passes < o.maxPasses) {
    r.passes++;
    const std::size_t splits = pass.sweep();
    r.splits += splits;
    if(!splits) break;
  }
  r.irregularAfter = irregularNodes(m);
  return r;
}
} // namespace reparam

