// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <map>
#include "SVector3.h"
#include "closestTriangle.h"
#include "quadEdgeRotation.h"
#include "quadQuality.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  typedef std::pair<int, int> side;

  side sideOf(int a, int b) { return a < b ? side(a, b) : side(b, a); }

  // Every element's corners in order (corner 3 of a triangle: -1)
  std::vector<std::array<int, 4> > elementsOf(const surfaceMesh &m)
  {
    std::vector<std::array<int, 4> > elements;
    for(const std::array<int, 3> &t : m.triangles)
      elements.push_back({{t[0], t[1], t[2], -1}});
    elements.insert(elements.end(), m.quadrangles.begin(), m.quadrangles.end());
    return elements;
  }

  int cornersOf(const std::array<int, 4> &e) { return e[3] < 0 ? 3 : 4; }

  std::vector<std::set<int> > neighboursOf(const surfaceMesh &m)
  {
    std::vector<std::set<int> > neighbours(m.points.size());
    for(const std::array<int, 4> &e : elementsOf(m)) {
      const int n = cornersOf(e);
      for(int k = 0; k < n; k++) {
        neighbours[e[k]].insert(e[(k + 1) % n]);
        neighbours[e[(k + 1) % n]].insert(e[k]);
      }
    }
    return neighbours;
  }

  double cornerAngle(const SPoint3 &at, const SPoint3 &next,
                     const SPoint3 &previous)
  {
    const SVector3 u(at, next), v(at, previous);
    return std::atan2(crossprod(u, v).norm(), dot(u, v));
  }

  double etaOf(const std::array<int, 4> &q, const std::vector<SPoint3> &p)
  {
    return quadEta(p[q[0]], p[q[1]], p[q[2]], p[q[3]]);
  }

  std::size_t irregularCount(const std::vector<int> &valence,
                             const std::vector<bool> &closed)
  {
    std::size_t n = 0;
    for(std::size_t i = 0; i < valence.size(); i++)
      n += closed[i] && valence[i] != 4;
    return n;
  }

  // The two quadrangles on either side of an edge, as a hexagon: q1 runs
  // a -> b, q2 b -> a; corners a, r, s, b, p, q in turn
  struct hexagon {
    int q1, q2;
    int a, b, p, q, r, s;
  };

  bool hexagonOf(const surfaceMesh &m, int q1, int q2, const side &e,
                 hexagon &h)
  {
    const std::array<int, 4> &Q1 = m.quadrangles[q1];
    const std::array<int, 4> &Q2 = m.quadrangles[q2];
    for(int k = 0; k < 4; k++) {
      int a = Q1[k], b = Q1[(k + 1) % 4];
      if(sideOf(a, b) != e) continue;
      for(int j = 0; j < 4; j++) {
        if(Q2[j] != b || Q2[(j + 1) % 4] != a) continue;
        h = {q1,
             q2,
             a,
             b,
             Q1[(k + 2) % 4],
             Q1[(k + 3) % 4],
             Q2[(j + 2) % 4],
             Q2[(j + 3) % 4]};
        std::array<int, 6> all = {{h.a, h.b, h.p, h.q, h.r, h.s}};
        std::sort(all.begin(), all.end());
        return std::adjacent_find(all.begin(), all.end()) == all.end();
      }
      return false; // q2 runs the same way: not consistently oriented
    }
    return false;
  }

  struct rotationPass {
    surfaceMesh &m;
    const std::vector<int> &part;
    const std::set<side> &locked;
    const quadRotationOptions &o;
    const std::vector<int> &ideal;
    std::vector<int> &valence;
    std::vector<std::set<int> > &neighbours;

    double costChange(int v, int change) const
    {
      const double before = valence[v] - ideal[v];
      const double after = before + change;
      return after * after - before * before;
    }

    // The unit normal of the input triangle closest to x (zero without)
    SVector3 inputNormalAt(const SPoint3 &x) const
    {
      const closestTriangleHit hit = o.onInput->closest(x);
      if(hit.triangle < 0) return SVector3(0., 0., 0.);
      const std::array<int, 3> &t = o.input->triangles[hit.triangle];
      const std::vector<SPoint3> &q = o.input->points;
      SVector3 n =
        crossprod(SVector3(q[t[0]], q[t[1]]), SVector3(q[t[0]], q[t[2]]));
      const double length = n.norm();
      return length > 0. ? n * (1. / length) : n;
    }

    static SPoint3 centreOf(const std::array<int, 4> &q,
                            const std::vector<SPoint3> &p)
    {
      return (p[q[0]] + p[q[1]] + p[q[2]] + p[q[3]]) * 0.25;
    }

    // Whether the new diagonal from -> to follows the input as closely as
    // the old one a -> b did, and the new quadrangles lie on its side as
    // the old ones did
    bool followsInput(const hexagon &h, int from, int to,
                      const std::array<int, 4> &n1,
                      const std::array<int, 4> &n2) const
    {
      const std::vector<SPoint3> &p = m.points;
      const SPoint3 now = (p[h.a] + p[h.b]) * 0.5;
      const SPoint3 next = (p[from] + p[to]) * 0.5;
      const double allowed = std::max(o.onInput->closest(now).distance,
                                      o.tolerance * p[from].distance(p[to]));
      if(o.onInput->closest(next).distance > allowed) return false;
      for(int k = 0; k < 2; k++) {
        const std::array<int, 4> &old =
          k ? m.quadrangles[h.q2] : m.quadrangles[h.q1];
        const std::array<int, 4> &nu = k ? n2 : n1;
        const double side =
          dot(quadNormal(old, p), inputNormalAt(centreOf(old, p)));
        const double sideNew =
          dot(quadNormal(nu, p), inputNormalAt(centreOf(nu, p)));
        if(side * sideNew <= 0.) return false;
      }
      return true;
    }

    // Whether the new pair passes o's tests against the old pair
    bool acceptable(const hexagon &h, int from, int to,
                    const std::array<int, 4> &n1,
                    const std::array<int, 4> &n2) const
    {
      const std::vector<SPoint3> &p = m.points;
      if(etaOf(n1, p) < o.minEta || etaOf(n2, p) < o.minEta) return false;
      SVector3 old =
        quadNormal(m.quadrangles[h.q1], p) + quadNormal(m.quadrangles[h.q2], p);
      if(old.norm() == 0.) return false;
      old.normalize();
      const double cosTurn = std::cos(o.maxTurn);
      if(dot(quadNormal(n1, p), old) < cosTurn ||
         dot(quadNormal(n2, p), old) < cosTurn)
        return false;
      return !o.input || !o.onInput || followsInput(h, from, to, n1, n2);
    }

    // Rotates h's edge to the better of the two other diagonals where the
    // valences gain; returns whether it did
    bool rotate(const hexagon &h)
    {
      const double removed = costChange(h.a, -1) + costChange(h.b, -1);
      struct choice {
        int from, to;
        std::array<int, 4> n1, n2;
      };
      const choice choices[2] = {
        {h.r, h.p, {{h.r, h.s, h.b, h.p}}, {{h.p, h.q, h.a, h.r}}},
        {h.s, h.q, {{h.s, h.b, h.p, h.q}}, {{h.q, h.a, h.r, h.s}}}};
      const choice *best = nullptr;
      double bestChange = 0., bestEta = 0.;
      for(const choice &c : choices) {
        if(neighbours[c.from].count(c.to)) continue;
        const double change =
          removed + costChange(c.from, 1) + costChange(c.to, 1);
        if(change >= 0. || !acceptable(h, c.from, c.to, c.n1, c.n2)) continue;
        const double eta =
          std::min(etaOf(c.n1, m.points), etaOf(c.n2, m.points));
        if(!best || change < bestChange ||
           (change == bestChange && eta > bestEta)) {
          best = &c;
          bestChange = change;
          bestEta = eta;
        }
      }
      if(!best) return false;
      m.quadrangles[h.q1] = best->n1;
      m.quadrangles[h.q2] = best->n2;
      neighbours[h.a].erase(h.b);
      neighbours[h.b].erase(h.a);
      neighbours[best->from].insert(best->to);
      neighbours[best->to].insert(best->from);
      valence[h.a]--;
      valence[h.b]--;
      valence[best->from]++;
      valence[best->to]++;
      return true;
    }

    // One sweep over the edges between two quadrangles; each quadrangle
    // rotates at most once (its neighbours' edges were listed before)
    std::size_t sweep()
    {
      std::map<side, std::vector<int> > quadsAt;
      std::set<side> triangleSides;
      for(const std::array<int, 3> &t : m.triangles)
        for(int k = 0; k < 3; k++)
          triangleSides.insert(sideOf(t[k], t[(k + 1) % 3]));
      for(std::size_t i = 0; i < m.quadrangles.size(); i++)
        for(int k = 0; k < 4; k++)
          quadsAt[sideOf(m.quadrangles[i][k], m.quadrangles[i][(k + 1) % 4])]
            .push_back((int)i);
      std::vector<bool> touched(m.quadrangles.size(), false);
      std::size_t rotations = 0;
      for(const auto &at : quadsAt) {
        const std::vector<int> &q = at.second;
        if(q.size() != 2 || locked.count(at.first) ||
           triangleSides.count(at.first) || touched[q[0]] || touched[q[1]])
          continue;
        if(!part.empty() && part[q[0]] != part[q[1]]) continue;
        hexagon h;
        if(!hexagonOf(m, q[0], q[1], at.first, h) &&
           !hexagonOf(m, q[1], q[0], at.first, h))
          continue;
        if(!rotate(h)) continue;
        touched[q[0]] = touched[q[1]] = true;
        rotations++;
      }
      return rotations;
    }
  };

} // namespace

std::vector<bool> closedRings(const surfaceMesh &m)
{
  std::map<side, int> count;
  for(const std::array<int, 4> &e : elementsOf(m)) {
    const int n = cornersOf(e);
    for(int k = 0; k < n; k++) count[sideOf(e[k], e[(k + 1) % n])]++;
  }
  std::vector<bool> closed(m.points.size(), true);
  std::vector<bool> used(m.points.size(), false);
  for(const auto &c : count) {
    used[c.first.first] = used[c.first.second] = true;
    if(c.second != 2) closed[c.first.first] = closed[c.first.second] = false;
  }
  for(std::size_t i = 0; i < used.size(); i++)
    if(!used[i]) closed[i] = false;
  return closed;
}

std::size_t irregularNodes(const surfaceMesh &m)
{
  return irregularCount(valences(m), closedRings(m));
}

std::vector<int> valences(const surfaceMesh &m)
{
  std::vector<int> valence;
  for(const std::set<int> &n : neighboursOf(m))
    valence.push_back((int)n.size());
  return valence;
}

std::vector<int> idealValences(const surfaceMesh &m)
{
  const std::vector<bool> closed = closedRings(m);
  std::vector<double> angle(m.points.size(), 0.);
  for(const std::array<int, 4> &e : elementsOf(m)) {
    const int n = cornersOf(e);
    for(int k = 0; k < n; k++)
      angle[e[k]] += cornerAngle(m.points[e[k]], m.points[e[(k + 1) % n]],
                                 m.points[e[(k + n - 1) % n]]);
  }
  std::vector<int> ideal(m.points.size(), 4);
  for(std::size_t i = 0; i < ideal.size(); i++)
    if(!closed[i])
      ideal[i] = std::max(2, (int)std::lround(angle[i] / (M_PI / 2.)) + 1);
  return ideal;
}

quadRotationResult rotateQuadEdges(surfaceMesh &m, const std::vector<int> &part,
                                   const std::set<std::pair<int, int> > &locked,
                                   const quadRotationOptions &o)
{
  quadRotationResult r;
  const std::vector<bool> closed = closedRings(m);
  const std::vector<int> ideal = idealValences(m);
  std::vector<std::set<int> > neighbours = neighboursOf(m);
  std::vector<int> valence;
  for(const std::set<int> &n : neighbours) valence.push_back((int)n.size());
  r.irregularBefore = irregularCount(valence, closed);
  rotationPass pass{m, part, locked, o, ideal, valence, neighbours};
  while(r.passes < o.maxPasses) {
    r.passes++;
    const std::size_t rotations = pass.sweep();
    r.rotations += rotations;
    if(!rotations) break;
  }
  r.irregularAfter = irregularCount(valence, closed);
  return r;
}
} // namespace reparam

