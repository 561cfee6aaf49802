// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <numeric>
#include "gradedBoundarySize.h"

gradedBoundarySize::gradedBoundarySize(const std::vector<SPoint3> &nodes,
                                       const std::vector<double> &sizes,
                                       double gradient)
  : _gradient(gradient)
{
  std::vector<std::size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return sizes[a] < sizes[b]; });
  for(std::size_t i : order) {
    _nodes.push_back(nodes[i]);
    _sizes.push_back(sizes[i]);
  }
}

double gradedBoundarySize::operator()(const SPoint3 &x, double bound) const
{
  double best = bound;
  for(std::size_t i = 0; i < _sizes.size() && _sizes[i] < best; i++)
    best = std::min(best, _sizes[i] + _gradient * x.distance(_nodes[i]));
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
