// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "efficiencyIndex.h"

namespace reparam {

double adimensionalLength(const SPoint3 &a, const SPoint3 &b,
                          const std::function<double(const SPoint3 &)> &size)
{
  // Gauss-Legendre on [0, 1]
  static const double t[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5,
                              0.5 + 0.5 * std::sqrt(0.6)};
  static const double w[3] = {5. / 18., 8. / 18., 5. / 18.};
  double integral = 0.;
  for(int g = 0; g < 3; g++) {
    SPoint3 x(a.x() + t[g] * (b.x() - a.x()), a.y() + t[g] * (b.y() - a.y()),
              a.z() + t[g] * (b.z() - a.z()));
    integral += w[g] / size(x);
  }
  return a.distance(b) * integral;
}

double efficiencyIndex(const std::vector<SPoint3> &points,
                       const std::vector<std::array<int, 2> > &edges,
                       const std::function<double(const SPoint3 &)> &size)
{
  if(edges.empty()) return 0.;
  double sum = 0.;
  for(const auto &e : edges) {
    double l = adimensionalLength(points[e[0]], points[e[1]], size);
    sum += l < 1. ? l - 1. : 1. / l - 1.;
  }
  return 100. * std::exp(sum / edges.size());
}

std::vector<std::array<int, 2> >
uniqueEdges(const std::vector<std::array<int, 3> > &triangles,
            const std::vector<std::array<int, 4> > &quadrangles)
{
  std::vector<std::array<int, 2> > edges;
  edges.reserve(3 * triangles.size() + 4 * quadrangles.size());
  auto add = [&](int a, int b) {
    edges.push_back({{std::min(a, b), std::max(a, b)}});
  };
  for(const auto &t : triangles)
    for(int j = 0; j < 3; j++) add(t[j], t[(j + 1) % 3]);
  for(const auto &q : quadrangles)
    for(int j = 0; j < 4; j++) add(q[j], q[(j + 1) % 4]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}
} // namespace reparam

