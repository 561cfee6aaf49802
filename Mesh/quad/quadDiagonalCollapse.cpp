// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include "SVector3.h"
#include "closestTriangle.h"
#include "quadDiagonalCollapse.h"
#include "quadConnectivity.h"
#include "quadEdgeRotation.h"
#include "quadFidelity.h"
#include "quadQuality.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  typedef std::array<int, 4> quad;

  // m's inner nodes not of valence 4, without the quadrangles removed
  std::size_t irregularCount(const surfaceMesh &m,
                             const std::vector<bool> &removed)
  {
    surfaceMesh live;
    live.points = m.points;
    live.triangles = m.triangles;
    for(std::size_t i = 0; i < m.quadrangles.size(); i++)
      if(!removed[i]) live.quadrangles.push_back(m.quadrangles[i]);
    return irregularNodes(live);
  }

  // The mesh's connectivity, kept exact through the collapses (and their
  // undoing, for the look-ahead)
  struct collapser : quadConnectivity {
    surfaceMesh &m;
    const std::vector<int> &part, &owner, &ideal;
    const std::vector<bool> &closed;
    std::vector<int> &mergedInto;
    std::vector<bool> &removed;
    const quadCollapseOptions &o;

    int partOf(int q) const { return part.empty() ? 0 : part[q]; }

    double cost(int v, int change) const
    {
      return quadConnectivity::cost(v, change, ideal);
    }

    // The change of the valences' squared distance to their ideal when q
    // collapses along its diagonal from corner k (a, c = corners k, k + 2)
    double change(int q, int k) const
    {
      const quad &Q = m.quadrangles[q];
      const int a = Q[k], b = Q[(k + 1) % 4], c = Q[(k + 2) % 4],
                d = Q[(k + 3) % 4];
      const double merged =
        (double)neighbours[a].size() + neighbours[c].size() - 2 - ideal[a];
      return merged * merged + cost(b, -1) + cost(d, -1) - cost(a, 0) -
             cost(c, 0) - cost(b, 0) - cost(d, 0);
    }

    // Whether a and c may merge without two elements sharing more than a
    // side or a corner losing its last quadrangles but one
    bool mergeable(int q, int a, int b, int c, int d) const
    {
      if(owner[a] < 0 || owner[a] != owner[c] || owner[a] != partOf(q) ||
         onTriangle[a] || onTriangle[c] || neighbours[a].count(c))
        return false;
      std::vector<int> common;
      std::set_intersection(neighbours[a].begin(), neighbours[a].end(),
                            neighbours[c].begin(), neighbours[c].end(),
                            std::back_inserter(common));
      if(common.size() != 2 || !std::count(common.begin(), common.end(), b) ||
         !std::count(common.begin(), common.end(), d))
        return false;
      for(int v : {b, d}) {
        const int least = closed[v] ? 3 : 2;
        if((int)neighbours[v].size() - 1 < least) return false;
      }
      return true;
    }

    // The quadrangles around a and c but q, with c as a
    std::vector<std::pair<int, quad> > around(int q, int a, int c) const
    {
      std::vector<std::pair<int, quad> > out;
      for(int v : {a, c})
        for(int i : quadsAt[v]) {
          if(i == q) continue;
          quad Q = m.quadrangles[i];
          for(int &x : Q)
            if(x == c) x = a;
          out.push_back(std::make_pair(i, Q));
        }
      return out;
    }

    SPoint3 onInput(const SPoint3 &x) const
    {
      return o.onInput ? o.onInput->closest(x).point : x;
    }

    // The worst eta of the quadrangles `next` with a at x, or -1 where one
    // turns by o.maxTurn or more from what it was
    double worstAt(int a, const SPoint3 &x,
                   const std::vector<std::pair<int, quad> > &next)
    {
      const double cosTurn = std::cos(o.maxTurn);
      std::vector<SVector3> before;
      for(const auto &n : next)
        before.push_back(quadNormal(m.quadrangles[n.first], m.points));
      const SPoint3 old = m.points[a];
      m.points[a] = x;
      double worst = 1.;
      for(std::size_t i = 0; i < next.size() && worst >= 0.; i++) {
        const quad &Q = next[i].second;
        if(dot(quadNormal(Q, m.points), before[i]) < cosTurn)
          worst = -1.;
        else
          worst = std::min(worst, quadEta(m.points[Q[0]], m.points[Q[1]],
                                          m.points[Q[2]], m.points[Q[3]]));
      }
      m.points[a] = old;
      return worst;
    }

    // How far p lies from the quadrangles `next` with a at x (p a copy: it
    // may be a's old place)
    double distanceTo(const SPoint3 p, int a, const SPoint3 &x,
                      const std::vector<std::pair<int, quad> > &next)
    {
      std::vector<quad> quads;
      for(const auto &n : next) quads.push_back(n.second);
      const SPoint3 old = m.points[a];
      m.points[a] = x;
      const double d = distanceToQuadrangles(p, quads, m.points);
      m.points[a] = old;
      return d;
    }

    // Whether the new quadrangles follow the input as closely as the old
    // ones did, up to o.tolerance times `side`: a bump the old ones
    // followed is not cut off
    bool followsInput(int q, int a, const SPoint3 &x,
                      const std::vector<std::pair<int, quad> > &next,
                      double side)
    {
      if(!o.onInput) return true;
      std::vector<quad> before = {m.quadrangles[q]}, after;
      for(const auto &n : next) {
        before.push_back(m.quadrangles[n.first]);
        after.push_back(n.second);
      }
      const double was = farthestCentreFromInput(before, m.points, *o.onInput);
      const SPoint3 old = m.points[a];
      m.points[a] = x;
      const double now = farthestCentreFromInput(after, m.points, *o.onInput);
      m.points[a] = old;
      return now <= was + o.tolerance * side;
    }

    // What a collapse changed, to undo it
    struct undo {
      int q = -1, a = -1, c = -1;
      SPoint3 place;
      std::vector<std::pair<int, quad> > quads;
      std::vector<std::pair<int, std::set<int> > > rings, quadSets;
    };

    // Merges c into a at `place`: q goes, the quadrangles around c take a
    void apply(int q, int a, int c, const SPoint3 &place,
               const std::vector<std::pair<int, quad> > &next, undo &u)
    {
      u.q = q;
      u.a = a;
      u.c = c;
      u.place = m.points[a];
      std::set<int> changed = {a, c};
      for(int v : neighbours[c]) changed.insert(v);
      for(int v : m.quadrangles[q]) changed.insert(v);
      for(int v : changed) {
        u.rings.push_back(std::make_pair(v, neighbours[v]));
        u.quadSets.push_back(std::make_pair(v, quadsAt[v]));
      }
      for(const auto &n : next)
        u.quads.push_back(std::make_pair(n.first, m.quadrangles[n.first]));
      m.points[a] = place;
      for(const auto &n : next) m.quadrangles[n.first] = n.second;
      removed[q] = true;
      mergedInto[c] = a;
      for(int v : m.quadrangles[q]) quadsAt[v].erase(q);
      for(int i : quadsAt[c]) quadsAt[a].insert(i);
      quadsAt[c].clear();
      for(int v : neighbours[c]) {
        neighbours[v].erase(c);
        if(v != a) {
          neighbours[v].insert(a);
          neighbours[a].insert(v);
        }
      }
      neighbours[c].clear();
    }

    void revert(const undo &u)
    {
      m.points[u.a] = u.place;
      for(const auto &q : u.quads) m.quadrangles[q.first] = q.second;
      removed[u.q] = false;
      mergedInto[u.c] = -1;
      for(const auto &r : u.rings) neighbours[r.first] = r.second;
      for(const auto &r : u.quadSets) quadsAt[r.first] = r.second;
    }

    // Collapses q along its diagonal from corner k where the valences'
    // change is at most `most` and the merged node has a place passing o's
    // tests; returns whether it did
    bool collapse(int q, int k, double most, undo &u)
    {
      if(removed[q] || change(q, k) > most) return false;
      const quad Q = m.quadrangles[q];
      const int a = Q[k], b = Q[(k + 1) % 4], c = Q[(k + 2) % 4],
                d = Q[(k + 3) % 4];
      if(!mergeable(q, a, b, c, d)) return false;
      const std::vector<std::pair<int, quad> > next = around(q, a, c);
      std::set<int> ring;
      for(const auto &n : next)
        for(int v : n.second)
          if(v != a) ring.insert(v);
      SPoint3 centroid(0., 0., 0.);
      for(int v : ring) centroid += m.points[v];
      centroid *= 1. / std::max<std::size_t>(1, ring.size());
      double best = -1.;
      SPoint3 place;
      for(const SPoint3 &x :
          {onInput((m.points[a] + m.points[c]) * 0.5), onInput(centroid)}) {
        const double worst = worstAt(a, x, next);
        if(worst > best) {
          best = worst;
          place = x;
        }
      }
      if(best < o.minEta) return false;
      // the two nodes stay on the new mesh: a node on a tip or a crease
      // keeps the mesh there
      double side = 0.;
      for(int j = 0; j < 4; j++)
        side += 0.25 * m.points[Q[j]].distance(m.points[Q[(j + 1) % 4]]);
      if(o.size && side > o.largest * o.size((m.points[a] + m.points[c]) * 0.5))
        return false;
      for(int v : {a, c})
        if(o.onInput &&
           distanceTo(m.points[v], a, place, next) > o.nodeTolerance * side)
          return false;
      if(!followsInput(q, a, place, next, side)) return false;
      apply(q, a, c, place, next, u);
      return true;
    }

    // The collapses that make the mesh more regular, best first
    std::size_t sweep()
    {
      std::vector<std::pair<double, std::pair<int, int> > > candidates;
      for(std::size_t q = 0; q < m.quadrangles.size(); q++)
        for(int k = 0; k < 2 && !removed[q]; k++) {
          const double c = change((int)q, k);
          if(c < 0.) candidates.push_back({c, {(int)q, k}});
        }
      std::sort(candidates.begin(), candidates.end());
      std::size_t collapses = 0;
      undo u;
      for(const auto &c : candidates)
        collapses += collapse(c.second.first, c.second.second, -0.5, u);
      return collapses;
    }

    // Collapses that change nothing alone but let one nearby (a quadrangle
    // at a node of the first or a neighbour of the merged node) make the
    // mesh more regular: both kept, or the first undone. Most irregular
    // nodes left after the sweeps are a node of valence 3 next to one of
    // 5, which no single collapse nor rotation removes (how many gain:
    // bench/README.md#quadrangles-collapsed-along-a-diagonal)
    std::size_t lookAhead()
    {
      std::size_t collapses = 0;
      for(std::size_t q = 0; q < m.quadrangles.size(); q++)
        for(int k = 0; k < 2 && !removed[q]; k++) {
          if(change((int)q, k) != 0.) continue;
          const quad Q = m.quadrangles[q];
          undo first;
          if(!collapse((int)q, k, 0., first)) continue;
          std::set<int> near;
          for(int v : {Q[0], Q[1], Q[2], Q[3]}) {
            for(int i : quadsAt[v]) near.insert(i);
            for(int w : neighbours[v])
              for(int i : quadsAt[w]) near.insert(i);
          }
          bool gained = false;
          for(int i : near)
            for(int j = 0; j < 2 && !gained; j++) {
              undo second;
              gained = collapse(i, j, -0.5, second);
            }
          if(gained)
            collapses += 2;
          else
            revert(first);
        }
      return collapses;
    }
  };

} // namespace

quadCollapseResult collapseQuadDiagonals(surfaceMesh &m,
                                         const std::vector<int> &part,
                                         const std::vector<int> &owner,
                                         std::vector<int> &mergedInto,
                                         std::vector<bool> &removed,
                                         const quadCollapseOptions &o)
{
  quadCollapseResult r;
  mergedInto.assign(m.points.size(), -1);
  removed.assign(m.quadrangles.size(), false);
  const std::vector<int> ideal = idealValences(m);
  const std::vector<bool> closed = closedRings(m);
  r.irregularBefore = irregularCount(m, removed);
  collapser pass{{}, m, part, owner, ideal, closed, mergedInto, removed, o};
  pass.build(m, &removed);
  while(r.passes < o.maxPasses) {
    r.passes++;
    std::size_t collapses = pass.sweep();
    if(!collapses) collapses = pass.lookAhead();
    r.collapses += collapses;
    if(!collapses) break;
  }
  r.irregularAfter = irregularCount(m, removed);
  return r;
}
} // namespace reparam

