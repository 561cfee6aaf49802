// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <string>
#include "SVector3.h"
#include "discretePatch.h"
#include "unionFind.h"

namespace reparam {

namespace {

  // One triangle side; sorting these by (lo, hi) groups the sides of an edge
  struct triangleSide {
    int lo, hi; // node indices, lo < hi
    int triangle;
    int side; // nodes side and side + 1 (mod 3) of the triangle
    bool forward; // the triangle runs lo -> hi
  };

  std::string triangleName(int t) { return "triangle " + std::to_string(t); }

  // Flips triangles so that every interior edge is run in opposite directions
  // by its two triangles; false if the patch is not orientable
  bool orientConsistently(const std::vector<triangleSide> &sides,
                          std::vector<std::array<int, 3> > &triangles,
                          std::size_t &flipped)
  {
    flipped = 0;
    bool consistent = true; // the common case: nothing to do
    for(std::size_t i = 0; i + 1 < sides.size() && consistent; i++) {
      if(sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi &&
         sides[i].forward == sides[i + 1].forward)
        consistent = false;
    }
    if(consistent) return true;

    const std::size_t nt = triangles.size();
    std::vector<std::vector<std::pair<int, bool> > > neighbours(nt);
    for(std::size_t i = 0; i + 1 < sides.size(); i++) {
      const triangleSide &a = sides[i], &b = sides[i + 1];
      if(a.lo != b.lo || a.hi != b.hi) continue;
      // same direction means the two triangles disagree
      bool disagree = (a.forward == b.forward);
      neighbours[a.triangle].push_back({b.triangle, disagree});
      neighbours[b.triangle].push_back({a.triangle, disagree});
    }
    std::vector<int> flip(nt, -1);
    std::vector<int> stack;
    for(std::size_t seed = 0; seed < nt; seed++) {
      if(flip[seed] >= 0) continue;
      flip[seed] = 0;
      stack.push_back(seed);
      while(!stack.empty()) {
        int t = stack.back();
        stack.pop_back();
        for(auto &n : neighbours[t]) {
          int want = flip[t] ^ (int)n.second;
          if(flip[n.first] < 0) {
            flip[n.first] = want;
            stack.push_back(n.first);
          }
          else if(flip[n.first] != want)
            return false;
        }
      }
    }
    for(std::size_t t = 0; t < nt; t++) {
      if(flip[t]) {
        std::swap(triangles[t][1], triangles[t][2]);
        flipped++;
      }
    }
    return true;
  }

  // The sides of all triangles, sorted by (lo, hi), so that the sides of an
  // edge are consecutive: a bucket per low node (few sides each), in linear
  // time rather than a global sort
  std::vector<triangleSide>
  sortedSides(const std::vector<std::array<int, 3> > &triangles, int nv)
  {
    std::vector<int> start(nv + 1, 0);
    for(const auto &tri : triangles)
      for(int j = 0; j < 3; j++)
        start[std::min(tri[j], tri[(j + 1) % 3]) + 1]++;
    for(int v = 0; v < nv; v++) start[v + 1] += start[v];
    std::vector<triangleSide> sides(3 * triangles.size());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for(std::size_t t = 0; t < triangles.size(); t++) {
      for(int j = 0; j < 3; j++) {
        int a = triangles[t][j], b = triangles[t][(j + 1) % 3];
        sides[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), (int)t,
                                         j, a < b};
      }
    }
    for(int v = 0; v < nv; v++) {
      for(int i = start[v] + 1; i < start[v + 1]; i++) {
        triangleSide s = sides[i];
        int k = i;
        for(; k > start[v] && sides[k - 1].hi > s.hi; k--)
          sides[k] = sides[k - 1];
        sides[k] = s;
      }
    }
    return sides;
  }

  // Finite coordinates, valid node indices, no repeated node, no zero area
  reparamError checkTriangles(const std::vector<SPoint3> &points,
                              const std::vector<std::array<int, 3> > &triangles)
  {
    const int nv = (int)points.size();
    for(int i = 0; i < nv; i++) {
      if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) ||
         !std::isfinite(points[i].z()))
        return reparamFailure(reparamStatus::invalidCoordinates,
                              "node " + std::to_string(i), i);
    }
    for(std::size_t t = 0; t < triangles.size(); t++) {
      const auto &tri = triangles[t];
      for(int j = 0; j < 3; j++) {
        if(tri[j] < 0 || tri[j] >= nv)
          return reparamFailure(reparamStatus::degenerateTriangle,
                                triangleName(t) + " has no node " +
                                  std::to_string(tri[j]));
      }
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
        return reparamFailure(reparamStatus::degenerateTriangle,
                              triangleName(t) + " repeats a node");
      SVector3 n = crossprod(SVector3(points[tri[0]], points[tri[1]]),
                             SVector3(points[tri[0]], points[tri[2]]));
      if(n.norm() == 0.)
        return reparamFailure(reparamStatus::degenerateTriangle,
                              triangleName(t) + " has zero area");
    }
    return reparamError();
  }

  // No edge of more than two triangles (sides sorted by edge)
  reparamError checkManifoldEdges(const std::vector<triangleSide> &sides)
  {
    for(std::size_t i = 0; i < sides.size();) {
      std::size_t j = i;
      while(j < sides.size() && sides[j].lo == sides[i].lo &&
            sides[j].hi == sides[i].hi)
        j++;
      if(j - i > 2)
        return reparamFailure(reparamStatus::nonManifoldEdge,
                              "edge " + std::to_string(sides[i].lo) + "-" +
                                std::to_string(sides[i].hi) + " has " +
                                std::to_string(j - i) + " triangles",
                              sides[i].lo);
      i = j;
    }
    return reparamError();
  }

  // One connected component, through shared edges
  reparamError checkConnected(const std::vector<triangleSide> &sides,
                              std::size_t numTriangles)
  {
    unionFind sets(numTriangles);
    for(std::size_t i = 0; i + 1 < sides.size(); i++) {
      if(sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi)
        sets.join(sides[i].triangle, sides[i + 1].triangle);
    }
    int root = sets.find(0);
    for(std::size_t t = 1; t < numTriangles; t++) {
      if(sets.find((int)t) != root)
        return reparamFailure(reparamStatus::severalComponents,
                              triangleName(t) + " is not connected to " +
                                triangleName(0));
    }
    return reparamError();
  }

  // The boundary's next node from each node: boundary sides taken in their
  // triangle's direction leave the patch on their left
  reparamError boundaryNext(const std::vector<triangleSide> &sides, int nv,
                            std::vector<int> &next)
  {
    next.assign(nv, -1);
    for(std::size_t i = 0; i < sides.size();) {
      bool single = (i + 1 == sides.size() || sides[i + 1].lo != sides[i].lo ||
                     sides[i + 1].hi != sides[i].hi);
      if(single) {
        int a = sides[i].forward ? sides[i].lo : sides[i].hi;
        int b = sides[i].forward ? sides[i].hi : sides[i].lo;
        if(next[a] >= 0)
          return reparamFailure(reparamStatus::nonManifoldVertex,
                                "node " + std::to_string(a), a);
        next[a] = b;
        i++;
      }
      else
        i += 2;
    }
    return reparamError();
  }

  // The patch's edges and each triangle's edges, from the sorted sides
  void buildEdges(const std::vector<triangleSide> &sides,
                  std::size_t numTriangles, discretePatch &patch)
  {
    patch.triangleEdges.resize(numTriangles);
    for(std::size_t i = 0; i < sides.size(); i++) {
      if(i == 0 || sides[i].lo != sides[i - 1].lo ||
         sides[i].hi != sides[i - 1].hi)
        patch.edges.push_back({sides[i].lo, sides[i].hi});
      patch.triangleEdges[sides[i].triangle][sides[i].side] =
        (int)patch.edges.size() - 1;
    }
  }

  // The boundary loops following `next`, the longest the outer one
  reparamError buildBoundaryLoops(const std::vector<int> &next,
                                  discretePatch &patch)
  {
    const int nv = (int)next.size();
    std::vector<char> used(nv, 0);
    for(int start = 0; start < nv; start++) {
      if(next[start] < 0 || used[start]) continue;
      std::vector<int> loop;
      for(int v = start; !used[v]; v = next[v]) {
        if(next[v] < 0)
          return reparamFailure(reparamStatus::nonManifoldVertex,
                                "open boundary at node " + std::to_string(v),
                                v);
        used[v] = 1;
        loop.push_back(v);
      }
      patch.boundaryLoops.push_back(loop);
    }
    double longest = -1.;
    for(std::size_t l = 0; l < patch.boundaryLoops.size(); l++) {
      double len = boundaryLoopLength(patch, l);
      if(len > longest) {
        longest = len;
        patch.outerLoop = (int)l;
      }
    }
    return reparamError();
  }

  int countUnreferenced(const std::vector<std::array<int, 3> > &triangles,
                        int nv)
  {
    std::vector<char> referenced(nv, 0);
    for(const auto &tri : triangles)
      for(int j = 0; j < 3; j++) referenced[tri[j]] = 1;
    return (int)std::count(referenced.begin(), referenced.end(), 0);
  }

} // namespace

reparamError makeDiscretePatch(std::vector<SPoint3> points,
                               std::vector<std::array<int, 3> > triangles,
                               discretePatch &patch)
{
  patch = discretePatch();
  if(triangles.empty()) return reparamFailure(reparamStatus::emptyPatch);
  reparamError e = checkTriangles(points, triangles);
  if(!e.ok()) return e;

  const int nv = (int)points.size();
  std::vector<triangleSide> sides = sortedSides(triangles, nv);
  e = checkManifoldEdges(sides);
  if(!e.ok()) return e;
  std::size_t flipped = 0;
  if(!orientConsistently(sides, triangles, flipped))
    return reparamFailure(reparamStatus::nonOrientable);
  if(flipped) sides = sortedSides(triangles, nv);
  e = checkConnected(sides, triangles.size());
  if(!e.ok()) return e;
  std::vector<int> next;
  e = boundaryNext(sides, nv, next);
  if(!e.ok()) return e;
  const int unreferenced = countUnreferenced(triangles, nv);

  buildEdges(sides, triangles.size(), patch);
  patch.points = std::move(points);
  patch.triangles = std::move(triangles);
  patch.numReorientedTriangles = flipped;
  e = buildBoundaryLoops(next, patch);
  if(!e.ok()) return e;

  // Unreferenced nodes would make the matrices singular: they are the
  // caller's bug, not the user's input
  if(unreferenced)
    return reparamFailure(reparamStatus::degenerateTriangle,
                          std::to_string(unreferenced) +
                            " nodes belong to no triangle");
  if(patch.boundaryLoops.empty())
    return reparamFailure(reparamStatus::noBoundary);
  if(patch.genus() != 0)
    return reparamFailure(reparamStatus::notDiskTopology,
                          "genus " + std::to_string(patch.genus()));
  return reparamError();
}

double boundaryLoopLength(const discretePatch &patch, int loop)
{
  const std::vector<int> &l = patch.boundaryLoops[loop];
  double len = 0.;
  for(std::size_t i = 0; i < l.size(); i++)
    len += patch.points[l[i]].distance(patch.points[l[(i + 1) % l.size()]]);
  return len;
}
} // namespace reparam
