// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <set>
#include "SVector3.h"
#include "boundaryStitch.h"

namespace reparam {

namespace {

  typedef std::array<int, 2> edgeKey;
  edgeKey key(int a, int b) { return a < b ? edgeKey{{a, b}} : edgeKey{{b, a}}; }

  struct stitching {
    std::vector<SPoint3> points; // input nodes, then boundary nodes
    std::vector<std::array<int, 3> > triangles;
    std::vector<bool> alive;
    std::vector<SVector3> inputNormal; // of each triangle before any change
    std::vector<std::vector<int> > nodeTriangles; // may hold stale entries

    SVector3 normal(const std::array<int, 3> &t) const
    {
      return crossprod(SVector3(points[t[0]], points[t[1]]),
                       SVector3(points[t[0]], points[t[2]]));
    }

    void addTriangle(const std::array<int, 3> &t, const SVector3 &n)
    {
      triangles.push_back(t);
      alive.push_back(true);
      inputNormal.push_back(n);
      for(int v : t) nodeTriangles[v].push_back((int)triangles.size() - 1);
    }

    bool has(int t, int n) const
    {
      return alive[t] && std::count(triangles[t].begin(), triangles[t].end(), n);
    }

    // the living triangles with node n
    std::vector<int> around(int n) const
    {
      std::vector<int> a;
      for(int t : nodeTriangles[n])
        if(has(t, n) && std::find(a.begin(), a.end(), t) == a.end())
          a.push_back(t);
      return a;
    }

    // the nodes joined to n by a boundary edge (one triangle)
    std::vector<int> boundaryNeighbours(int n) const
    {
      std::map<int, int> count;
      for(int t : around(n))
        for(int m : triangles[t])
          if(m != n) count[m]++;
      std::vector<int> b;
      for(const auto &c : count)
        if(c.second == 1) b.push_back(c.first);
      return b;
    }
  };

  // boundary edges: used by exactly one triangle (then its index)
  std::map<edgeKey, int> boundaryEdges(const stitching &st)
  {
    std::map<edgeKey, int> count;
    for(std::size_t t = 0; t < st.triangles.size(); t++) {
      if(!st.alive[t]) continue;
      for(int j = 0; j < 3; j++) {
        auto it = count.insert(
          {key(st.triangles[t][j], st.triangles[t][(j + 1) % 3]), (int)t});
        if(!it.second) it.first->second = -1;
      }
    }
    std::map<edgeKey, int> boundary;
    for(const auto &e : count)
      if(e.second >= 0) boundary.insert(e);
    return boundary;
  }

  // The parameter (0..1) of p's projection on segment ab, and its distance
  double projectOnSegment(const SPoint3 &p, const SPoint3 &a, const SPoint3 &b,
                          double &s)
  {
    SVector3 ab(a, b), ap(a, p);
    const double l2 = dot(ab, ab);
    s = l2 > 0. ? std::min(std::max(dot(ap, ab) / l2, 0.), 1.) : 0.;
    return p.distance(a + (b - a) * s);
  }

  // Labels of the points (empty: none) and the labels a boundary node takes
  struct labelling {
    const std::vector<int> &points;
    const std::vector<int> *node; // null: any
    bool allows(int p) const
    {
      if(!node) return true;
      if(p >= (int)points.size()) return false;
      return std::find(node->begin(), node->end(), points[p]) != node->end();
    }
  };

  // The boundary edge nearest to b within `best`, among those whose ends
  // the labels allow
  edgeKey nearestEdge(const stitching &st,
                      const std::map<edgeKey, int> &boundary, int b,
                      const labelling &labels, double &best, double &at)
  {
    edgeKey where{{-1, -1}};
    for(const auto &e : boundary) {
      if(!labels.allows(e.first[0]) || !labels.allows(e.first[1])) continue;
      double s;
      const double d = projectOnSegment(st.points[b], st.points[e.first[0]],
                                        st.points[e.first[1]], s);
      if(d <= best) {
        best = d;
        where = e.first;
        at = s;
      }
    }
    return where;
  }

  // Node b inserted on the boundary edge it lies on (splitting it, or
  // taking the place of an input node it is on); false if none is near
  bool insertBoundaryNode(stitching &st, std::map<edgeKey, int> &boundary,
                          int b, double tolerance, const labelling &labels,
                          std::vector<int> &replacedBy)
  {
    const int numInput = (int)replacedBy.size();
    if(labels.node) {
      // a corner: the input point of the same label, if near
      for(int p = 0; p < numInput; p++)
        if(replacedBy[p] < 0 && labels.allows(p) &&
           st.points[p].distance(st.points[b]) <= tolerance &&
           labels.node->size() == 1) {
          replacedBy[p] = b;
          return true;
        }
    }
    double best = tolerance, at = 0.;
    edgeKey where = nearestEdge(st, boundary, b, labels, best, at);
    if(where[0] < 0 && labels.node) {
      best = tolerance;
      where = nearestEdge(st, boundary, b, {labels.points, nullptr}, best, at);
    }
    if(where[0] < 0) return false;
    const double length = st.points[where[0]].distance(st.points[where[1]]);
    for(int end = 0; end < 2; end++) {
      const int n = where[end];
      const double fromEnd = (end ? 1. - at : at) * length;
      if(fromEnd <= tolerance && n < numInput && replacedBy[n] < 0) {
        replacedBy[n] = b;
        return true;
      }
    }
    const int t = boundary.at(where);
    const std::array<int, 3> tri = st.triangles[t];
    int j = 0;
    while(key(tri[j], tri[(j + 1) % 3]) != where) j++;
    const int p = tri[j], q = tri[(j + 1) % 3], o = tri[(j + 2) % 3];
    st.triangles[t] = {{p, b, o}};
    st.nodeTriangles[b].push_back(t);
    st.addTriangle({{b, q, o}}, st.inputNormal[t]);
    const int added = (int)st.triangles.size() - 1;
    boundary.erase(where);
    boundary[key(p, b)] = t;
    boundary[key(b, q)] = added;
    // the edge qo moved to the new triangle (t kept op)
    auto moved = boundary.find(key(q, o));
    if(moved != boundary.end()) moved->second = added;
    return true;
  }

  // p's only triangle (a tip of a sliver) removed leaves its edge opposite
  // p on the boundary, if another triangle holds that edge (else nothing
  // would be left of that piece)
  bool tipOverEdge(const stitching &st, const std::vector<int> &around, int p,
                   int q)
  {
    if(around.size() != 1) return false;
    const std::array<int, 3> &tip = st.triangles[around[0]];
    int r = -1;
    for(int n : tip)
      if(n != p && n != q) r = n;
    for(int t : st.around(q))
      if(t != around[0] && st.has(t, r)) return true;
    return false;
  }

  // Collapsing p onto q: the triangles it turns against their input normal,
  // or -1 when it would make an edge non-manifold or leave no triangle
  int turnedByCollapse(const stitching &st, const std::vector<int> &around,
                       int p, int q)
  {
    std::set<int> neighboursOfQ;
    for(int t : st.around(q))
      for(int n : st.triangles[t])
        if(n != q) neighboursOfQ.insert(n);
    int turned = 0, shared = 0, kept = 0;
    std::set<int> common;
    for(int t : around) {
      std::array<int, 3> tri = st.triangles[t];
      for(int n : tri)
        if(n != p && n != q && neighboursOfQ.count(n)) common.insert(n);
      if(std::count(tri.begin(), tri.end(), q)) {
        shared++;
        continue;
      }
      kept++;
      for(int &n : tri)
        if(n == p) n = q;
      if(dot(st.normal(tri), st.inputNormal[t]) <= 0.) turned++;
    }
    // the link condition: the common neighbours of p and q are the third
    // nodes of the triangles they share
    if(shared == 0 || (int)common.size() > shared) return -1;
    if(!kept && !tipOverEdge(st, around, p, q)) return -1;
    return turned;
  }

  void collapse(stitching &st, const std::vector<int> &around, int p, int q)
  {
    for(int t : around) {
      std::array<int, 3> &tri = st.triangles[t];
      if(std::count(tri.begin(), tri.end(), q)) {
        st.alive[t] = false;
        continue;
      }
      for(int &n : tri)
        if(n == p) n = q;
      st.nodeTriangles[q].push_back(t);
    }
  }

  // p collapsed onto the boundary neighbour that turns fewest triangles
  // (a boundary node rather than an input node when equal); -1 if none can
  int collapseOntoNeighbour(stitching &st, int p, int numInput)
  {
    const std::vector<int> around = st.around(p);
    int best = -1, fewest = -1;
    for(int q : st.boundaryNeighbours(p)) {
      const int turned = turnedByCollapse(st, around, p, q);
      if(turned < 0) continue;
      if(best < 0 || turned < fewest ||
         (turned == fewest && q >= numInput && best < numInput)) {
        best = q;
        fewest = turned;
      }
    }
    if(best >= 0) collapse(st, around, p, best);
    return best < 0 ? -1 : fewest;
  }

} // namespace

namespace {

  // Every boundary node inserted on the input boundary edge it lies on,
  // then the input nodes they coincide with replaced; returns how many found
  // no edge within the tolerance
  std::size_t insertBoundaryNodes(stitching &st, int numInput,
                                  double tolerance,
                                  const std::vector<int> &pointLabels,
                                  const std::vector<std::vector<int> > &nodeLabels)
  {
    const std::size_t numNodes = st.points.size() - numInput;
    std::vector<int> replacedBy(numInput, -1);
    std::map<edgeKey, int> boundary = boundaryEdges(st);
    // labels of the inserted nodes too: a later node may split their edges
    std::vector<int> labelOf = pointLabels;
    const bool labelled = (int)pointLabels.size() == numInput &&
                          nodeLabels.size() == numNodes;
    std::size_t unplaced = 0;
    for(std::size_t k = 0; k < numNodes; k++) {
      const labelling labels{labelOf, labelled ? &nodeLabels[k] : nullptr};
      if(!insertBoundaryNode(st, boundary, numInput + (int)k, tolerance,
                             labels, replacedBy))
        unplaced++;
      if(labelled)
        labelOf.push_back(nodeLabels[k].empty() ? 0 : nodeLabels[k].front());
    }
    for(int n = 0; n < numInput; n++) {
      if(replacedBy[n] < 0) continue;
      for(int t : st.around(n)) {
        for(int &m : st.triangles[t])
          if(m == n) m = replacedBy[n];
        st.nodeTriangles[replacedBy[n]].push_back(t);
      }
    }
    return unplaced;
  }

  // The input nodes left on the boundary loops with curve nodes collapsed
  // onto a neighbour along them, in passes until none can (each collapse
  // removes a node: it ends); returns how many are left, `turned` the
  // triangles turned
  std::size_t collapseInputBoundary(stitching &st, int numInput,
                                    std::size_t &turned)
  {
    // only on the boundary loops a curve node went to: a loop no curve
    // runs along (a surface given without curves) stays as it is
    std::map<int, std::vector<int> > along;
    for(const auto &e : boundaryEdges(st)) {
      along[e.first[0]].push_back(e.first[1]);
      along[e.first[1]].push_back(e.first[0]);
    }
    std::set<int> pending, seen;
    for(const auto &start : along) {
      if(seen.count(start.first)) continue;
      std::vector<int> loop, stack = {start.first};
      seen.insert(start.first);
      bool stitched = false;
      while(!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        loop.push_back(n);
        stitched = stitched || n >= numInput;
        for(int m : along[n])
          if(seen.insert(m).second) stack.push_back(m);
      }
      if(!stitched) continue;
      for(int n : loop)
        if(n < numInput) pending.insert(n);
    }
    for(bool progress = true; progress && !pending.empty();) {
      progress = false;
      for(auto it = pending.begin(); it != pending.end();) {
        const int t = collapseOntoNeighbour(st, *it, numInput);
        if(t < 0) {
          ++it;
          continue;
        }
        turned += t;
        it = pending.erase(it);
        progress = true;
      }
    }
    return pending.size();
  }

} // namespace

stitchedTriangulation
stitchToBoundaryNodes(const std::vector<SPoint3> &points,
                      const std::vector<std::array<int, 3> > &triangles,
                      const std::vector<SPoint3> &boundaryNodes,
                      double tolerance, const std::vector<int> &pointLabels,
                      const std::vector<std::vector<int> > &nodeLabels)
{
  stitchedTriangulation result;
  stitching st;
  st.points = points;
  st.points.insert(st.points.end(), boundaryNodes.begin(), boundaryNodes.end());
  st.nodeTriangles.resize(st.points.size());
  for(const auto &t : triangles) st.addTriangle(t, st.normal(t));
  const int numInput = (int)points.size();
  result.unplacedNodes =
    insertBoundaryNodes(st, numInput, tolerance, pointLabels, nodeLabels);
  result.keptInputNodes =
    collapseInputBoundary(st, numInput, result.turnedTriangles);
  for(std::size_t t = 0; t < st.triangles.size(); t++)
    if(st.alive[t]) result.triangles.push_back(st.triangles[t]);
  return result;
}
} // namespace reparam

