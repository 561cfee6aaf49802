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
    // between calls) rather than a search; the arrays allocated first:
    // nothing may throw while the scratch is written
    a.start.assign(a.nodes.size() + 1, 0);
    a.at.resize(3 * part.size());
    std::vector<int> fill(a.nodes.size());
    thread_local std::vector<int> place;
    if(place.size() < mesh.points.size()) place.resize(mesh.points.size(), -1);
    for(std::size_t i = 0; i < a.nodes.size(); i++) place[a.nodes[i]] = (int)i;
    for(int t : part)
      for(int n : mesh.triangles[t]) a.start[place[n] + 1]++;
    for(std::size_t i = 0; i < a.nodes.size(); i++)
      a.start[i + 1] += a.start[i];
    std::copy(a.start.begin(), a.start.end() - 1, fill.begin());
    for(std::size_t i = 0; i < part.size(); i++)
      for(int n : mesh.triangles[part[i]]) a.at[fill[place[n]]++] = (int)i;
    for(int n : a.nodes) place[n] = -1;
    return a;
  }

  class cutSides {
  public:
    cutSides(const layoutMesh &mesh, const std::vector<int> &part,
             std::vector<char> &side,
             const std::vector<std::array<int, 3> > &across)
      : _mesh(mesh), _part(part), _side(side), _around(indexPart(mesh, part)),
        _across(across)
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
    const std::vector<std::array<int, 3> > &_across;
    std::vector<int> _mine, _label, _order;
  };

  // Whether the part's triangles (of one side each, when `side` is given)
  // make several fans around any node: each fan walked once, around its
  // node across the edges through it, and counted at the node (per side).
  // What cutSides finds node by node with the triangles around each, in
  // one pass without them: most parts and cuts have no such node. True
  // also for a triangle with a repeated node, which the walk cannot take
  // (cutSides then decides).
  bool anyPinchedNode(const layoutMesh &mesh,
                      const std::vector<std::array<int, 3> > &across,
                      const std::vector<int> &part,
                      const std::vector<char> *side)
  {
    // fans counted per node and side, in a scratch array per thread (all
    // 0 between calls)
    thread_local std::vector<unsigned char> fans;
    if(fans.size() < 2 * mesh.points.size())
      fans.resize(2 * mesh.points.size(), 0);
    std::vector<char> walked(3 * part.size(), 0); // (triangle, corner)
    auto cornerOf = [&](int i, int v) {
      const auto &tri = mesh.triangles[part[i]];
      return tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
    };
    bool pinched = false;
    for(std::size_t i = 0; i < part.size() && !pinched; i++) {
      const auto &tri = mesh.triangles[part[i]];
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
        pinched = true;
        break;
      }
      const int s = side ? (*side)[i] : 0;
      for(int c = 0; c < 3 && !pinched; c++) {
        if(walked[3 * i + c]) continue;
        walked[3 * i + c] = 1;
        const int v = tri[c];
        if(++fans[2 * v + s] > 1) pinched = true;
        // both ways from triangle i: out across edge c (nodes c, c + 1)
        // and edge c + 2 (nodes c + 2, c), the two through v
        for(int out : {c, (c + 2) % 3}) {
          int at = (int)i, edge = out;
          while(true) {
            const int next = across[at][edge];
            if(next < 0 || (side && (*side)[next] != s)) break;
            const int cn = cornerOf(next, v);
            if(walked[3 * next + cn]) break; // round the node, or met
            walked[3 * next + cn] = 1;
            // leave `next` by its other edge through v
            const int back = across[next][cn] == at ? cn : (cn + 2) % 3;
            edge = back == cn ? (cn + 2) % 3 : cn;
            at = next;
          }
        }
      }
    }
    for(int t : part)
      for(int v : mesh.triangles[t]) fans[2 * v] = fans[2 * v + 1] = 0;
    return pinched;
  }

} // namespace

std::vector<char>
separateFansAtPinch(const layoutMesh &mesh, const triangleAdjacency &adjacency,
                    const std::vector<int> &part,
                    const std::vector<std::array<int, 3> > *given)
{
  std::vector<std::array<int, 3> > own;
  if(!given) own = partNeighbours(adjacency, part, mesh.triangles.size());
  const std::vector<std::array<int, 3> > &across = given ? *given : own;
  if(!anyPinchedNode(mesh, across, part, nullptr)) return std::vector<char>();
  std::vector<char> side(part.size(), 0);
  cutSides sides(mesh, part, side, across);
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
  unpinchCut(mesh, adjacency, part, side, &across);
  return side;
}

std::size_t unpinchCut(const layoutMesh &mesh,
                       const triangleAdjacency &adjacency,
                       const std::vector<int> &part, std::vector<char> &side,
                       const std::vector<std::array<int, 3> > *given)
{
  std::vector<std::array<int, 3> > own;
  if(!given) own = partNeighbours(adjacency, part, mesh.triangles.size());
  const std::vector<std::array<int, 3> > &across = given ? *given : own;
  // no pinched node: no fan to move (the rounds would leave the sides)
  if(!anyPinchedNode(mesh, across, part, &side)) return 0;
  const std::vector<char> before = side;
  cutSides sides(mesh, part, side, across);
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
