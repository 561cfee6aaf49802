// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "OS.h"
#include "SVector3.h"
#include "patchLayout.h"
#include "triangleAdjacency.h"

double triangleArea(const layoutMesh &mesh, int t)
{
  const auto &tri = mesh.triangles[t];
  SVector3 n = crossprod(SVector3(mesh.points[tri[0]], mesh.points[tri[1]]),
                         SVector3(mesh.points[tri[0]], mesh.points[tri[2]]));
  return 0.5 * n.norm();
}

double edgeLength(const layoutMesh &mesh, const std::array<int, 2> &edge)
{
  return mesh.points[edge[0]].distance(mesh.points[edge[1]]);
}

namespace {

  std::vector<char> featureEdgeFlags(const layoutMesh &mesh,
                                     const triangleAdjacency &adjacency)
  {
    std::vector<char> flags(adjacency.edges.size(), 0);
    for(const auto &f : mesh.featureEdges) {
      int e = adjacency.find(f[0], f[1]);
      if(e >= 0) flags[e] = 1;
    }
    return flags;
  }

  struct pendingPart {
    std::vector<int> triangles;
    int depth;
  };

  // Verifies every part of the stack, cutting those refused: first into
  // their edge-connected components, then in two by bisectPart. Each cut
  // leaves strictly smaller parts and the depth is bounded, so it ends.
  void splitUntilVerified(const layoutMesh &mesh,
                          const triangleAdjacency &adjacency,
                          const layoutParameters &parameters,
                          const partVerifier &verify,
                          std::vector<pendingPart> stack, layoutResult &result)
  {
    while(!stack.empty()) {
      pendingPart part = std::move(stack.back());
      stack.pop_back();
      std::vector<std::vector<int> > components =
        partComponents(adjacency, part.triangles, mesh.triangles.size());
      if(components.size() > 1) {
        // not a cut of ours: a patch of Gmsh's classification joined by a
        // node only (or a merge through one)
        for(auto &c : components) stack.push_back({std::move(c), part.depth});
        continue;
      }
      partCheck check = verify(part.triangles);
      if(check.ok || part.triangles.size() < 2 ||
         part.depth >= parameters.maxDepth) {
        const int index = result.numPatches++;
        for(int t : part.triangles) result.patch[t] = index;
        if(!check.ok) result.unverified.push_back({index, check.reason});
        continue;
      }
      std::vector<char> side = bisectPart(mesh, adjacency, part.triangles);
      std::vector<int> halves[2];
      for(std::size_t i = 0; i < side.size(); i++)
        halves[(int)side[i]].push_back(part.triangles[i]);
      layoutSplit split;
      split.triangles = part.triangles.size();
      split.depth = part.depth;
      split.reason = check.reason;
      for(auto &h : halves)
        for(auto &c : partComponents(adjacency, h, mesh.triangles.size())) {
          stack.push_back({std::move(c), part.depth + 1});
          split.parts++;
        }
      result.splits.push_back(split);
    }
  }

} // namespace

layoutResult computePatchLayout(const layoutMesh &mesh,
                                const layoutParameters &parameters,
                                const partVerifier &verify)
{
  layoutResult result;
  result.patch.assign(mesh.triangles.size(), -1);
  if(mesh.triangles.empty()) return result;
  double t0 = TimeOfDay();
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<char> feature = featureEdgeFlags(mesh, adjacency);
  int numPatches = 0;
  std::vector<int> patch =
    featurePatches(mesh, adjacency, feature, numPatches);
  result.featurePatches = numPatches;
  result.mergedNoise =
    mergeNoisePatches(mesh, adjacency, parameters, patch, numPatches);
  result.cleanedPatches = numPatches;
  double t1 = TimeOfDay();

  std::vector<pendingPart> stack(numPatches);
  for(std::size_t t = 0; t < patch.size(); t++)
    stack[patch[t]].triangles.push_back((int)t);
  for(auto &p : stack) p.depth = 0;
  // the largest last, so that it is verified first (the log reads better)
  std::sort(stack.begin(), stack.end(),
            [](const pendingPart &a, const pendingPart &b) {
              return a.triangles.size() < b.triangles.size();
            });
  splitUntilVerified(mesh, adjacency, parameters, verify, std::move(stack),
                     result);
  for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
    const int n = adjacency.numTriangles((int)e);
    const int *t = &adjacency.edgeTriangles[adjacency.edgeStart[e]];
    if(n != 2 || result.patch[t[0]] != result.patch[t[1]])
      result.cutEdges.push_back(adjacency.edges[e]);
  }
  result.cleanTime = t1 - t0;
  result.splitTime = TimeOfDay() - t1;
  return result;
}
