// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The targeted passes: flips and moves around the triangles below the
// target or pointing against the input, worst first.

#include <set>
#include "localOptimizer.h"
#include "optimizationPasses.h"
#include "triangleQuality.h"

namespace reparam::optimizeInternal {

// Flips and moves around the triangles below the target or against the
// input, pass after pass
void improvePoorTriangles(optimizableMesh &m, const surfaceMesh &input,
                          const closestTriangleSearch &onInput,
                          const meshOptimizationOptions &o,
                          meshOptimizationResult &r,
                          const std::vector<int> &smooth)
{
  localOptimizer opt(m, input, onInput, o, r.searches,
                     o.searchesPerTriangle * m.triangles.size() + 1000);
  // first the nodes around the edges collapsed: their triangles are valid
  // but uneven
  std::set<int> around;
  for(int v : smooth) opt.addNeighbours(v, around);
  for(int v : around) r.moves += opt.tryMove(v);
  std::vector<int> below = opt.trianglesBelowTarget();
  for(int pass = 0; !below.empty() && pass < o.maxPasses; pass++) {
    r.passes++;
    std::size_t changes = 0;
    for(int t : below)
      if((m.against[t] || opt.kappa(t) < o.target) && opt.tryFlips(t))
        changes++;
    r.flips += changes;
    std::set<int> corners;
    for(int t : opt.trianglesBelowTarget())
      for(int v : m.triangles[t]) corners.insert(v);
    for(int v : corners)
      if(opt.tryMove(v)) {
        r.moves++;
        changes++;
      }
    below = opt.trianglesBelowTarget();
    if(!changes || opt.spent()) break;
  }
}

// Triangles of m below the target, and pointing against the input
void countPoorTriangles(const optimizableMesh &m,
                        const meshOptimizationOptions &o, std::size_t &below,
                        std::size_t &against)
{
  below = against = 0;
  for(std::size_t t = 0; t < m.triangles.size(); t++) {
    const std::array<int, 3> &c = m.triangles[t];
    below +=
      triangleKappa(m.points[c[0]], m.points[c[1]], m.points[c[2]]) < o.target;
    against += m.against[t];
  }
}

} // namespace reparam::optimizeInternal
