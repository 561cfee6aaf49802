// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <unordered_map>
#include "triangleAdjacency.h"
#include "unpinchCut.h"

namespace reparam {

namespace {

  // The part's triangles by node: (node, index in the part), sorted, and
  // each mesh triangle's index in the part
  struct partAround {
    std::unordered_map<int, int> local;
    std::vector<std::pair<int, int> > byNode;
  };

  partAround indexPart(const layoutMesh &mesh, const std::vector<int> &part)
  {
    partAround a;
    a.local.reserve(part.size());
    a.byNode.reserve(3 * part.size());
    for(std::size_t i = 0; i < part.size(); i++) {
      a.local[part[i]] = (int)i;
      for(int n : mesh.triangles[part[i]]) a.byNode.push_back({n, (int)i});
    }
    std::sort(a.byNode.begin(), a.byNode.end());
    return a;
  }

  class cutSides {
  public:
    cutSides(const layoutMesh &mesh, const triangleAdjacency &adjacency,
             const std::vector<int> &part, std::vector<char> &side)
      : _mesh(mesh), _adjacency(adjacency), _part(part), _side(side),
        _around(indexPart(mesh, part))
    {
    }

    // One round over the nodes; returns the fans moved
    std::size_t round()
    {
      std::size_t moved = 0;
      anyNode([&](int v, const std::vector<int> &at) {
        for(char s = 0; s < 2; s++) moved += unpinch(v, at, s);
        return false;
      });
      return moved;
    }

    // A node where the part's triangles of side s make several fans, and
    // those fans; -1 and none when there is no such node
    int pinchedNode(char s, std::vector<std::vector<int> > &fansThere) const
    {
      int node = -1;
      anyNode([&](int v, const std::vector<int> &at) {
        if(at.size() < 2) return false;
        fansThere = fans(v, at, s);
        if(fansThere.size() < 2) return false;
        node = v;
        return true;
      });
      if(node < 0) fansThere.clear();
      return node;
    }

    // Every triangle of the part on the side of the seed it is fewest
    // triangles away from (across edges, in the part), the seeds' sides
    // set first
    void growFrom(const std::vector<int> &seeds)
    {
      std::vector<char> reached(_part.size(), 0);
      for(int t : seeds) reached[t] = 1;
      std::vector<int> front = seeds;
      for(std::size_t n = 0; n < front.size(); n++) {
        const int t = front[n];
        for(int k = 0; k < 3; k++) {
          const int o = across(t, _adjacency.triangleEdges[_part[t]][k]);
          if(o < 0 || reached[o]) continue;
          reached[o] = 1;
          _side[o] = _side[t];
          front.push_back(o);
        }
      }
    }

  private:
    // f(node, the part's triangles around it) for each node of the part in
    // turn, until f returns true
    template <class F> void anyNode(F f) const
    {
      const auto &byNode = _around.byNode;
      for(std::size_t i = 0; i < byNode.size();) {
        std::size_t j = i;
        std::vector<int> at;
        for(; j < byNode.size() && byNode[j].first == byNode[i].first; j++)
          at.push_back(byNode[j].second);
        if(f(byNode[i].first, at)) return;
        i = j;
      }
    }

    // The part's triangle across edge e of (part) triangle i, or -1
    int across(int i, int e) const
    {
      const int o = _adjacency.across(e, _part[i]);
      if(o < 0) return -1;
      auto it = _around.local.find(o);
      return it == _around.local.end() ? -1 : it->second;
    }

    // The fans of side s at node v among the part's triangles `at` around
    // it: groups joined across the edges through v
    std::vector<std::vector<int> > fans(int v, const std::vector<int> &at,
                                        char s) const
    {
      std::vector<int> mine;
      for(int i : at)
        if(_side[i] == s) mine.push_back(i);
      std::vector<int> label(mine.size(), -1);
      std::vector<std::vector<int> > groups;
      for(std::size_t a = 0; a < mine.size(); a++) {
        if(label[a] >= 0) continue;
        label[a] = (int)groups.size();
        groups.push_back({mine[a]});
        for(std::size_t n = 0; n < groups.back().size(); n++) {
          const int t = groups.back()[n];
          for(int k = 0; k < 3; k++) {
            const auto &tri = _mesh.triangles[_part[t]];
            if(tri[k] != v && tri[(k + 1) % 3] != v) continue;
            const int o = across(t, _adjacency.triangleEdges[_part[t]][k]);
            for(std::size_t b = 0; b < mine.size(); b++)
              if(mine[b] == o && label[b] < 0) {
                label[b] = label[a];
                groups.back().push_back(o);
              }
          }
        }
      }
      return groups;
    }

    bool bordersOtherSide(const std::vector<int> &fan, char s) const
    {
      for(int t : fan)
        for(int k = 0; k < 3; k++) {
          const int o = across(t, _adjacency.triangleEdges[_part[t]][k]);
          if(o >= 0 && _side[o] != s) return true;
        }
      return false;
    }

    std::size_t unpinch(int v, const std::vector<int> &at, char s)
    {
      std::vector<std::vector<int> > f = fans(v, at, s);
      if(f.size() < 2) return 0;
      std::stable_sort(
        f.begin(), f.end(),
        [](const std::vector<int> &a, const std::vector<int> &b) {
          return a.size() > b.size();
        });
      std::size_t moved = 0;
      for(std::size_t k = 1; k < f.size(); k++) {
        if(!bordersOtherSide(f[k], s)) continue;
        for(int t : f[k]) _side[t] = 1 - s;
        moved++;
      }
      return moved;
    }

    const layoutMesh &_mesh;
    const triangleAdjacency &_adjacency;
    const std::vector<int> &_part;
    std::vector<char> &_side;
    partAround _around;
  };

} // namespace

std::vector<char> separateFansAtPinch(const layoutMesh &mesh,
                                      const triangleAdjacency &adjacency,
                                      const std::vector<int> &part)
{
  std::vector<char> side(part.size(), 0);
  cutSides sides(mesh, adjacency, part, side);
  std::vector<std::vector<int> > fans;
  if(sides.pinchedNode(0, fans) < 0) return std::vector<char>();
  // the largest fan on one side, the others on the other (a part pinched
  // at one node more is parted again)
  std::stable_sort(fans.begin(), fans.end(),
                   [](const std::vector<int> &a, const std::vector<int> &b) {
                     return a.size() > b.size();
                   });
  std::vector<int> seeds;
  for(std::size_t f = 0; f < fans.size(); f++)
    for(int t : fans[f]) {
      side[t] = f ? 1 : 0;
      seeds.push_back(t);
    }
  sides.growFrom(seeds);
  unpinchCut(mesh, adjacency, part, side);
  return side;
}

std::size_t unpinchCut(const layoutMesh &mesh,
                       const triangleAdjacency &adjacency,
                       const std::vector<int> &part, std::vector<char> &side)
{
  const std::vector<char> before = side;
  cutSides sides(mesh, adjacency, part, side);
  std::size_t moved = 0;
  // each move merges a fan into the other side's; a few rounds settle
  for(int round = 0; round < 8; round++) {
    const std::size_t m = sides.round();
    moved += m;
    if(!m) break;
  }
  const std::size_t ones = std::count(side.begin(), side.end(), 1);
  if(!ones || ones == side.size()) { // a side emptied: the cut as it was
    side = before;
    return 0;
  }
  return moved;
}

} // namespace reparam
