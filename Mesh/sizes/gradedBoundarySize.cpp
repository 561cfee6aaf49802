// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "gradedBoundarySize.h"

namespace reparam {

gradedBoundarySize::gradedBoundarySize(const std::vector<SPoint3> &nodes,
                                       const std::vector<double> &sizes,
                                       double gradient, double reach)
  : _nodes(nodes), _sizes(sizes), _gradient(gradient)
{
  if(_sizes.empty()) return;
  _smallest = *std::min_element(_sizes.begin(), _sizes.end());
  const double largest =
    std::max(reach, *std::max_element(_sizes.begin(), _sizes.end()));
  // a node reaches (bound - size) / gradient: within the query's cell and
  // its neighbours for bounds up to the reach
  _cell = largest / gradient;
  if(!(_cell > 0.)) _cell = 1.;
  _low = _high = cellOf(_nodes[0]);
  for(std::size_t i = 0; i < _nodes.size(); i++) {
    const cellKey c = cellOf(_nodes[i]);
    _cells[c].push_back((int)i);
    for(int d = 0; d < 3; d++) {
      _low[d] = std::min(_low[d], c[d]);
      _high[d] = std::max(_high[d], c[d]);
    }
  }
}

gradedBoundarySize::cellKey gradedBoundarySize::cellOf(const SPoint3 &x) const
{
  return {{(long)std::floor(x.x() / _cell), (long)std::floor(x.y() / _cell),
           (long)std::floor(x.z() / _cell)}};
}

double gradedBoundarySize::operator()(const SPoint3 &x, double bound) const
{
  double best = bound;
  if(_sizes.empty() || _smallest >= best) return best;
  const cellKey c = cellOf(x);
  // the nodes of ring k (cells k away in the max norm) are at least
  // (k - 1) cells away; none beyond the rings reaching the last cells
  long last = 0;
  for(int d = 0; d < 3; d++)
    last = std::max(
      last, std::max(std::labs(c[d] - _low[d]), std::labs(_high[d] - c[d])));
  for(long k = 0; k <= last; k++) {
    if(k > 0 && _smallest + _gradient * (k - 1) * _cell >= best) break;
    for(long i = -k; i <= k; i++)
      for(long j = -k; j <= k; j++)
        for(long l = -k; l <= k; l++) {
          if(std::max(std::labs(i), std::max(std::labs(j), std::labs(l))) != k)
            continue;
          auto it = _cells.find({{c[0] + i, c[1] + j, c[2] + l}});
          if(it == _cells.end()) continue;
          for(int n : it->second)
            best =
              std::min(best, _sizes[n] + _gradient * x.distance(_nodes[n]));
        }
  }
  return best;
}

std::vector<double>
shortestSegmentAtNodes(const std::vector<SPoint3> &nodes,
                       const std::vector<std::pair<int, int> > &segments)
{
  std::vector<double> shortest(nodes.size(), 0.);
  for(const auto &s : segments) {
    const double l = nodes[s.first].distance(nodes[s.second]);
    for(int i : {s.first, s.second})
      if(shortest[i] == 0. || l < shortest[i]) shortest[i] = l;
  }
  return shortest;
}
} // namespace reparam

