// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "gradedCurveNodes.h"

namespace reparam {

std::vector<double> gradedCurveParameters(
  const std::vector<SPoint3> &polyline,
  const std::function<double(const SPoint3 &, double)> &size, int fewest,
  bool even)
{
  // the running integral of 1 / size at the ends of small pieces
  std::vector<double> t = {0.}, integral = {0.};
  for(std::size_t i = 0; i + 1 < polyline.size(); i++) {
    const SPoint3 &a = polyline[i], &b = polyline[i + 1];
    const double length = a.distance(b);
    if(length <= 0.) continue;
    double step = size(a, (double)i);
    int pieces = (int)std::ceil(4. * length / std::max(step, 1e-300));
    pieces = std::max(1, std::min(pieces, 1000));
    for(int k = 0; k < pieces; k++) {
      const double u = (k + 0.5) / pieces;
      const SPoint3 middle = a + (b - a) * u;
      const double s = size(middle, i + u);
      if(!(s > 0.)) continue;
      t.push_back(i + (k + 1.) / pieces);
      integral.push_back(integral.back() + length / pieces / s);
    }
  }
  const double total = integral.back();
  int segments = std::max(fewest, (int)std::lround(total));
  if(even && segments % 2) segments++;
  std::vector<double> params = {0.};
  std::size_t j = 0;
  for(int n = 1; n < segments; n++) {
    const double target = total * n / segments;
    while(j + 1 < integral.size() && integral[j + 1] < target) j++;
    const double span = integral[j + 1] - integral[j];
    const double w = span > 0. ? (target - integral[j]) / span : 0.;
    params.push_back(t[j] + w * (t[j + 1] - t[j]));
  }
  params.push_back(polyline.size() - 1.);
  return params;
}
} // namespace reparam

