// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Feature patches (components between sharp edges) and the merging of those
// that are noise at the mesh scale: ClassifySurfaces' 40 degree test cuts
// scans into patches of one or two triangles around noisy spikes and folded
// input triangles; their corners pinch the large patches around them and
// their short curves force tiny segments (bench/README.md, "Faces that are
// noise at the mesh scale").

#include <algorithm>
#include <map>
#include <queue>
#include "patchLayout.h"
#include "triangleAdjacency.h"
#include "unionFind.h"

namespace reparam {

namespace {

  // A patch being merged: its triangles, area and perimeter (the length of
  // its edges on a boundary, a feature or another patch)
  struct patchStats {
    std::vector<int> triangles;
    double area = 0., perimeter = 0.;
  };

  bool isNoise(const patchStats &s, const layoutParameters &p)
  {
    if((int)s.triangles.size() <= p.noiseTriangles) return true;
    if(s.area < p.noiseArea) return true;
    return s.area < p.noiseWidthMaxArea && s.perimeter > 0. &&
           2. * s.area / s.perimeter < p.noiseWidth;
  }

} // namespace

std::vector<int> featurePatches(const layoutMesh &mesh,
                                const triangleAdjacency &adjacency,
                                const std::vector<char> &featureEdge,
                                int &numPatches)
{
  const int nt = (int)mesh.triangles.size();
  unionFind sets(nt);
  for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
    if(featureEdge[e] || adjacency.numTriangles(e) != 2) continue;
    int a = adjacency.edgeTriangles[adjacency.edgeStart[e]];
    int b = adjacency.edgeTriangles[adjacency.edgeStart[e] + 1];
    sets.join(a, b);
  }
  std::vector<int> index(nt, -1), patch(nt);
  numPatches = 0;
  for(int t = 0; t < nt; t++) {
    int r = sets.find(t);
    if(index[r] < 0) index[r] = numPatches++;
    patch[t] = index[r];
  }
  return patch;
}

int mergeNoisePatches(const layoutMesh &mesh, const triangleAdjacency &adjacency,
                      const layoutParameters &parameters,
                      std::vector<int> &patch, int &numPatches)
{
  std::vector<patchStats> stats(numPatches);
  for(std::size_t t = 0; t < patch.size(); t++) {
    stats[patch[t]].triangles.push_back((int)t);
    stats[patch[t]].area += triangleArea(mesh, (int)t);
  }
  for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
    const int n = adjacency.numTriangles((int)e);
    const int *tris = &adjacency.edgeTriangles[adjacency.edgeStart[e]];
    const double len = edgeLength(mesh, adjacency.edges[e]);
    for(int i = 0; i < n; i++) {
      bool inner = n == 2 && patch[tris[0]] == patch[tris[1]];
      if(!inner) stats[patch[tris[i]]].perimeter += len;
    }
  }

  // Smallest first, so that noise goes into what it borders, not into
  // other noise; a patch that grows is queued again with its new area
  typedef std::pair<double, int> entry;
  std::priority_queue<entry, std::vector<entry>, std::greater<entry> > queue;
  for(int p = 0; p < numPatches; p++)
    if(isNoise(stats[p], parameters)) queue.push(entry(stats[p].area, p));
  int merged = 0;
  std::vector<char> gone(numPatches, 0);
  while(!queue.empty()) {
    entry top = queue.top();
    queue.pop();
    const int p = top.second;
    if(gone[p] || top.first != stats[p].area ||
       !isNoise(stats[p], parameters))
      continue;
    // Length shared with each neighbour, across manifold edges only (a
    // non-manifold edge stays a cut)
    std::map<int, double> shared;
    for(int t : stats[p].triangles)
      for(int k = 0; k < 3; k++) {
        int e = adjacency.triangleEdges[t][k];
        int other = adjacency.across(e, t);
        if(other >= 0 && patch[other] != p)
          shared[patch[other]] += edgeLength(mesh, adjacency.edges[e]);
      }
    if(shared.empty()) continue; // alone: nothing to merge into
    auto best = std::max_element(
      shared.begin(), shared.end(),
      [](const std::pair<const int, double> &a,
         const std::pair<const int, double> &b) { return a.second < b.second; });
    const int q = best->first;
    for(int t : stats[p].triangles) patch[t] = q;
    stats[q].triangles.insert(stats[q].triangles.end(),
                              stats[p].triangles.begin(),
                              stats[p].triangles.end());
    stats[q].area += stats[p].area;
    stats[q].perimeter += stats[p].perimeter - 2. * best->second;
    stats[p] = patchStats();
    gone[p] = 1;
    merged++;
    if(isNoise(stats[q], parameters)) queue.push(entry(stats[q].area, q));
  }

  // Renumber the patches left
  std::vector<int> index(numPatches, -1);
  int n = 0;
  for(int &p : patch) {
    if(index[p] < 0) index[p] = n++;
    p = index[p];
  }
  numPatches = n;
  return merged;
}
} // namespace reparam

