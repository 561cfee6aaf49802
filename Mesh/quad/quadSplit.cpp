// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "quadQuality.h"
#include "quadSplit.h"
#include "surfaceMesh.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // quadrangle q's triangles along the diagonal from its corner `from`
  // (0: corners 0-2, 1: corners 1-3)
  std::array<std::array<int, 3>, 2> halves(const std::array<int, 4> &q,
                                           int from)
  {
    const int a = q[from], b = q[from + 1], c = q[(from + 2) % 4],
              d = q[(from + 3) % 4];
    return {{{{a, b, c}}, {{a, c, d}}}};
  }

  double worseKappa(const surfaceMesh &m,
                    const std::array<std::array<int, 3>, 2> &t)
  {
    double worst = 1.;
    for(const std::array<int, 3> &c : t)
      worst = std::min(
        worst, triangleKappa(m.points[c[0]], m.points[c[1]], m.points[c[2]]));
    return worst;
  }

} // namespace

std::vector<quadSplit> quadSplits(const surfaceMesh &m, double maxEta,
                                  double minKappa)
{
  std::vector<quadSplit> splits;
  for(std::size_t i = 0; i < m.quadrangles.size(); i++) {
    const std::array<int, 4> &q = m.quadrangles[i];
    const double eta =
      quadEta(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]);
    if(eta >= maxEta) continue;
    quadSplit best{(int)i, halves(q, 0), eta, worseKappa(m, halves(q, 0))};
    const double other = worseKappa(m, halves(q, 1));
    if(other > best.kappa) {
      best.triangles = halves(q, 1);
      best.kappa = other;
    }
    if(best.kappa >= minKappa && best.kappa > eta) splits.push_back(best);
  }
  std::sort(
    splits.begin(), splits.end(),
    [](const quadSplit &x, const quadSplit &y) { return x.eta < y.eta; });
  return splits;
}
} // namespace reparam

