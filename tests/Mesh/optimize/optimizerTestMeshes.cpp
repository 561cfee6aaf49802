// Reparam - meshes and measures the tests of Mesh/optimize share

#include <algorithm>
#include <cmath>
#include <map>
#include "meshFidelity.h"
#include "optimizerTestMeshes.h"
#include "triangleQuality.h"

namespace optimizeTest {

  optimizableMesh optimizable(const testTriangulation &t)
  {
    optimizableMesh m;
    m.points = t.points;
    m.triangles = t.triangles;
    m.movable.assign(t.points.size(), true);
    std::map<std::pair<int, int>, int> uses;
    for(const auto &tri : t.triangles)
      for(int k = 0; k < 3; k++)
        uses[std::make_pair(std::min(tri[k], tri[(k + 1) % 3]),
                            std::max(tri[k], tri[(k + 1) % 3]))]++;
    for(const auto &e : uses)
      if(e.second == 1)
        m.movable[e.first.first] = m.movable[e.first.second] = false;
    return m;
  }

  double largestDistance(const optimizableMesh &m,
                         const closestTriangleSearch &onInput)
  {
    double d = 0.;
    for(const SPoint3 &p : m.points)
      d = std::max(d, onInput.closest(p).distance);
    return d;
  }

  std::size_t againstCount(const optimizableMesh &m, const surfaceMesh &input,
                           const closestTriangleSearch &onInput)
  {
    std::size_t n = 0;
    for(const auto &t : m.triangles)
      n += triangleAgainstInput(m.points[t[0]], m.points[t[1]], m.points[t[2]],
                                input, onInput);
    return n;
  }

  testTriangulation bump(testTriangulation t)
  {
    for(SPoint3 &p : t.points)
      p = SPoint3(p.x(), p.y(), 0.3 * std::sin(2. * p.x()) * std::cos(p.y()));
    return t;
  }

  optimizableMesh bumpGridOnInput(int n, const closestTriangleSearch &onInput)
  {
    optimizableMesh m = optimizable(bump(rectangleGrid(n, n, 1., 1.)));
    for(SPoint3 &p : m.points) p = onInput.closest(p).point;
    return m;
  }

  testTriangulation roof(testTriangulation t, double slope)
  {
    for(SPoint3 &p : t.points)
      p = SPoint3(p.x(), p.y(), slope * (0.5 - std::fabs(p.x() - 0.5)));
    return t;
  }

  double ridgeDistance(const optimizableMesh &mesh, const surfaceMesh &input,
                       double from, double to, double *mean)
  {
    const closestTriangleSearch onMesh(mesh.points, mesh.triangles);
    double largest = 0., sum = 0.;
    int count = 0;
    for(const SPoint3 &p : input.points)
      if(std::fabs(p.x() - 0.5) < 1e-9 && p.y() > from && p.y() < to) {
        const double d = onMesh.closest(p).distance;
        largest = std::max(largest, d);
        sum += d;
        count++;
      }
    if(mean) *mean = count ? sum / count : 0.;
    return largest;
  }

  double meanKappa(const optimizableMesh &m)
  {
    double sum = 0.;
    for(const std::array<int, 3> &t : m.triangles)
      sum += triangleKappa(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    return sum / m.triangles.size();
  }

} // namespace optimizeTest
