// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "triangleAdjacency.h"
#include "unpinchCut.h"

namespace reparam {

namespace {

  // The part's triangles around each of its nodes, nodes by increasing
  // number, the triangles around one by increasing index in the part: the
  // triangles at byNode[i] are at[start[i] .. start[i + 1])
  struct partAround {
    std::vector<int> nodes, start, at;
  };

  partAround indexPart(const layoutMesh &mesh, const std::vector<int> &part)
  {
    partAround a;
    a.nodes.reserve(3 * part.size());
    for(int t : part)
      for(int n : mesh.triangles[t]) a.nodes.push_back(n);
    std::sort(a.nodes.begin(), a.nodes.end());
    a.nodes.erase(std::unique(a.nodes.begin(), a.nodes.end()), a.nodes.end());
    // each node's place among them, in a scratch array per thread (all -1
    // between calls) rather than a search
    thread_local std::vector<int> place;
    if(place.size() < mesh.points.size()) place.resize(mesh.points.size(), -1);
    for(std::size_t i = 0; i < a.nodes.size(); i++) place[a.nodes[i]] = (int)i;
    a.start.assign(a.nodes.size() + 1, 0);
    for(int t : part)
      for(int n : mesh.triangles[t]) a.start[place[n] + 1]++;
    for(std::size_t i = 0; i < a.nodes.size(); i++)
      a.start[i + 1] += a.start[i];
    std::vector<int> fill(a.start.begin(), a.start.end() - 1);
    a.at.resize(3 * part.size());
    for(std::size_t i = 0; i < part.size(); i++)
      for(int n : mesh.triangles[part[i]]) a.at[fill[place[n]]++] = (int)i;
    for(int n : a.nodes) place[n] = -1;
    return a;
  }

  class cutSides {
  public:
    cutSides(const layoutMesh &mesh, const triangleAdjacency &adjacency,
             const std::vector<int> &part, std::vector<char> &side)
      : _mesh(mesh), _part(part), _side(side), _around(indexPart(mesh, part)),
        _across(partNeighbours(adjacency, part, mesh.triangles.size()))
    {
    }

    // One round over the nodes; returns the fans moved
    std::size_t round()
    {
      std::size_t moved = 0;
      for(std::size_t i = 0; i < _around.nodes.size(); i++)
        for(char s = 0; s < 2; s++) moved += unpinch(i, s);
      return moved;
    }

    // A node where the part's triangles of side s make several fans, and
    // those fans; -1 and none when there is no such node
    int pinchedNode(char s, std::vector<std::vector<int> > &fansThere)
    {
      fansThere.clear();
      for(std::size_t i = 0; i < _around.nodes.size(); i++) {
        if(_around.start[i + 1] - _around.start[i] < 2) continue;
        if(labelFans(i, s) < 2) continue;
        fansThere = fans();
        return _around.nodes[i];
      }
      return -1;
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
          const int o = _across[t][k];
          if(o < 0 || reached[o]) continue;
          reached[o] = 1;
          _side[o] = _side[t];
          front.push_back(o);
        }
      }
    }

  private:
    // The fans of side s at the i-th node among the part's triangles around
    // it (groups joined across the edges through the node), each triangle's
    // in _label (_mine: those triangles, in the order of the part); returns
    // their number. Labels in the order of their first triangle, each
    // group grown breadth first in _order (see fans()).
    int labelFans(std::size_t i, char s)
    {
      const int v = _around.nodes[i];
      _mine.clear();
      for(int k = _around.start[i]; k < _around.start[i + 1]; k++)
        if(_side[_around.at[k]] == s) _mine.push_back(_around.at[k]);
      _label.assign(_mine.size(), -1);
      _order.clear();
      int groups = 0;
      for(std::size_t a = 0; a < _mine.size(); a++) {
        if(_label[a] >= 0) continue;
        _label[a] = groups;
        _order.push_back((int)a);
        for(std::size_t n = _order.size() - 1; n < _order.size(); n++) {
          const int t = _mine[_order[n]];
          const auto &tri = _mesh.triangles[_part[t]];
          for(int k = 0; k < 3; k++) {
            if(tri[k] != v && tri[(k + 1) % 3] != v) continue;
            const int o = _across[t][k];
            for(std::size_t b = 0; b < _mine.size(); b++)
              if(_mine[b] == o && _label[b] < 0) {
                _label[b] = groups;
                _order.push_back((int)b);
              }
          }
        }
        groups++;
      }
      return groups;
    }

    // The groups labelFans found, each in the order it grew
    std::vector<std::vector<int> > fans() const
    {
      std::vector<std::vector<int> > groups;
      for(int a : _order) {
        if(_label[a] == (int)groups.size()) groups.emplace_back();
        groups[_label[a]].push_back(_mine[a]);
      }
      return groups;
    }

    bool bordersOtherSide(const std::vector<int> &fan, char s) const
    {
      for(int t : fan)
        for(int k = 0; k < 3; k++) {
          const int o = _across[t][k];
          if(o >= 0 && _side[o] != s) return true;
        }
      return false;
    }

    std::size_t unpinch(std::size_t i, char s)
    {
      if(labelFans(i, s) < 2) return 0;
      std::vector<std::vector<int> > f = fans();
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
    const std::vector<int> &_part;
    std::vector<char> &_side;
    partAround _around;
    std::vector<std::array<int, 3> > _across;
    std::vector<int> _mine, _label, _order;
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
