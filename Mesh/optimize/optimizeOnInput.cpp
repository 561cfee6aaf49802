// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "closestTriangle.h"
#include "farInputNodes.h"
#include "longEdgeSplit.h"
#include "meshFidelity.h"
#include "optimizationPasses.h"
#include "optimizeOnInput.h"
#include "shortEdgeCollapse.h"
#include "tangledCavity.h"

namespace reparam {

using namespace optimizeInternal;

namespace {

  // The per-point and per-triangle arrays m lacks, and which of its
  // triangles point against the input (but those the caller knows along it)
  void prepare(optimizableMesh &m, const surfaceMesh &input,
               const closestTriangleSearch &onInput,
               const meshOptimizationOptions &o)
  {
    m.landing.resize(m.points.size(), -1);
    m.inputNode.resize(m.points.size(), -1);
    m.movable.resize(m.points.size(), false);
    if(m.origin.size() != m.points.size()) {
      m.origin.resize(m.points.size());
      for(std::size_t i = 0; i < m.points.size(); i++) m.origin[i] = (int)i;
    }
    if(m.triangleOrigin.size() != m.triangles.size()) {
      m.triangleOrigin.resize(m.triangles.size());
      for(std::size_t t = 0; t < m.triangles.size(); t++)
        m.triangleOrigin[t] = (int)t;
    }
    m.against.resize(m.triangles.size());
    for(std::size_t t = 0; t < m.triangles.size(); t++) {
      if(t < o.knownAlong.size() && o.knownAlong[t]) continue;
      const std::array<int, 3> &c = m.triangles[t];
      m.against[t] =
        triangleAgainstInput(m.points[c[0]], m.points[c[1]], m.points[c[2]],
                             input, onInput) != o.reversed;
    }
  }

  // Rounds of insertions, splits and collapses, each followed by the
  // targeted flips and moves, until one adds and removes nothing
  void insertionRounds(optimizableMesh &m, const surfaceMesh &input,
                       const closestTriangleSearch &onInput,
                       const meshOptimizationOptions &o,
                       meshOptimizationResult &r)
  {
    for(int round = 0; round < std::max(1, o.maxInsertionRounds); round++) {
      std::size_t snapped = 0;
      const std::size_t inserted =
        o.insertAbove > 0. ? insertFarInputNodes(m, input, onInput, o.reversed,
                                                 o.insertAbove, &snapped) :
                             0;
      const std::size_t splits =
        splitLongEdges(m, input, onInput, o.reversed, o.splitAbove);
      std::vector<int> collapsedInto;
      const std::size_t collapses =
        o.collapseBelow > 0. ?
          collapseShortEdges(m, input, onInput, o.reversed, o.collapseBelow,
                             4. * o.tolerance, &collapsedInto) :
          0;
      r.inserted += inserted;
      r.snapped += snapped;
      r.splits += splits;
      r.collapses += collapses;
      improvePoorTriangles(m, input, onInput, o, r, collapsedInto);
      if(!inserted && !splits && !collapses) break;
    }
  }

} // namespace

meshOptimizationResult optimizeOnInput(optimizableMesh &m,
                                       const surfaceMesh &input,
                                       const closestTriangleSearch &onInput,
                                       const meshOptimizationOptions &o)
{
  meshOptimizationResult r;
  prepare(m, input, onInput, o);
  r.minBefore = worstKappa(m);
  countPoorTriangles(m, o, r.belowBefore, r.againstBefore);
  insertionRounds(m, input, onInput, o, r);
  countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
  if(r.againstAfter) {
    // tangles no flip nor single move undid: their cavities re-meshed
    std::vector<int> centers;
    r.cavities = remeshTangledCavities(m, input, onInput, o.reversed, &centers);
    if(r.cavities) {
      improvePoorTriangles(m, input, onInput, o, r, centers);
      countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
    }
  }
  if(o.smoothPasses > 0) {
    smoothMesh(m, input, onInput, o, r);
    // the moves smoothing made free others around the worst triangles
    improvePoorTriangles(m, input, onInput, o, r, {});
    countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
  }
  r.minAfter = worstKappa(m);
  return r;
}

} // namespace reparam
