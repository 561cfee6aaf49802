// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <tuple>
#include "closestTriangle.h"
#include "longEdgeSplit.h"
#include "meshFidelity.h"
#include "optimizableMesh.h"
#include "triangleSplit.h"

namespace reparam {

namespace {

  // Edges whose midpoint is farther from the input than this share of
  // their length are split even where the halves are worse
  const double chordOffShare = 0.1;

} // namespace

std::size_t splitLongEdges(optimizableMesh &m, const surfaceMesh &input,
                           const closestTriangleSearch &onInput, bool reversed,
                           double ratio)
{
  if(m.size.size() != m.points.size()) return 0;
  // (length over the size, triangle, edge), each inner edge once: from the
  // triangle where it runs from the smaller index to the larger
  std::vector<std::tuple<double, int, int> > longEdges;
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    for(int k = 0; k < 3; k++) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      if(a > b) continue;
      const double size = 0.5 * (m.size[a] + m.size[b]);
      const double length = m.points[a].distance(m.points[b]);
      if(size > 0. && length > ratio * size)
        longEdges.push_back(std::make_tuple(length / size, (int)t, k));
    }
  if(longEdges.empty()) return 0;
  std::sort(longEdges.rbegin(), longEdges.rend());
  triangleSplitter split(m, input, onInput, reversed);
  // no new triangle below the worst one already there (0.5 at most): across
  // a strip narrower than the size the halves would be slivers; but see
  // chordOffShare
  const double floor = std::min(0.5, worstKappa(m));
  std::size_t splits = 0;
  for(const auto &e : longEdges) {
    const int t = std::get<1>(e), k = std::get<2>(e);
    const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
    if(!split.untouched(t)) continue;
    const closestTriangleHit hit =
      onInput.closest((m.points[a] + m.points[b]) * 0.5);
    if(hit.triangle < 0) continue;
    // an edge whose chord passes farther from the input than a tenth of
    // its length cuts a crease or a hole's wall off: split for fidelity,
    // whatever its halves (bench/README.md, Optimization on the input)
    const bool cutsOff =
      hit.distance > chordOffShare * m.points[a].distance(m.points[b]);
    splits += split.splitEdge(t, k, hit.point, true, -1, cutsOff ? 0. : floor);
  }
  return splits;
}
} // namespace reparam

