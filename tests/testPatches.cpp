// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include "surfaceMesh.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace reparam;

testTriangulation
polarDiskWithHoles(int rings, int sectors,
                   const std::vector<std::array<int, 4> > &holes)
{
  testTriangulation t;
  t.points.push_back(SPoint3(0., 0., 0.));
  for(int i = 1; i <= rings; i++) {
    for(int j = 0; j < sectors; j++) {
      double r = (double)i / rings;
      double a = 2. * M_PI * j / sectors;
      t.points.push_back(SPoint3(r * std::cos(a), r * std::sin(a), 0.));
    }
  }
  auto id = [&](int i, int j) {
    return i == 0 ? 0 :
                    1 + (i - 1) * sectors + ((j % sectors) + sectors) % sectors;
  };
  auto inHole = [&](int i, int j) {
    for(const auto &h : holes)
      if(i >= h[0] && i < h[1] && j >= h[2] && j < h[3]) return true;
    return false;
  };
  for(int j = 0; j < sectors; j++)
    t.triangles.push_back({id(0, 0), id(1, j), id(1, j + 1)});
  for(int i = 1; i < rings; i++) {
    for(int j = 0; j < sectors; j++) {
      if(inHole(i, j)) continue;
      int a = id(i, j), b = id(i, j + 1), c = id(i + 1, j),
          d = id(i + 1, j + 1);
      if((i + j) % 2) {
        t.triangles.push_back({a, c, d});
        t.triangles.push_back({a, d, b});
      }
      else {
        t.triangles.push_back({a, c, b});
        t.triangles.push_back({b, c, d});
      }
    }
  }
  // drop the nodes inside the holes
  std::vector<int> newIndex(t.points.size(), -1);
  for(const auto &tri : t.triangles)
    for(int v : tri) newIndex[v] = 0;
  std::vector<SPoint3> kept;
  for(std::size_t i = 0; i < t.points.size(); i++) {
    if(newIndex[i] < 0) continue;
    newIndex[i] = (int)kept.size();
    kept.push_back(t.points[i]);
  }
  for(auto &tri : t.triangles)
    for(int &v : tri) v = newIndex[v];
  t.points = kept;
  return t;
}

testTriangulation polarDisk(int rings, int sectors, double radialExponent,
                            double twist)
{
  testTriangulation t = polarDiskWithHoles(rings, sectors, {});
  for(int i = 1; i <= rings; i++) {
    for(int j = 0; j < sectors; j++) {
      double r = std::pow((double)i / rings, radialExponent);
      double a = 2. * M_PI * (j + twist * i) / sectors;
      t.points[1 + (i - 1) * sectors + j] =
        SPoint3(r * std::cos(a), r * std::sin(a), 0.);
    }
  }
  return t;
}

testTriangulation hemisphere(int rings, int sectors)
{
  testTriangulation t = polarDisk(rings, sectors);
  for(auto &p : t.points) {
    // angle from the pole proportional to the planar radius: well-shaped
    double theta = 0.5 * M_PI * std::sqrt(p.x() * p.x() + p.y() * p.y());
    double a = std::atan2(p.y(), p.x());
    p = SPoint3(std::sin(theta) * std::cos(a), std::sin(theta) * std::sin(a),
                std::cos(theta));
  }
  return t;
}

testTriangulation sliverGrid(int n, double gap)
{
  testTriangulation t;
  const double h = 1. / n;
  for(int i = 0; i <= n; i++) {
    for(int j = 0; j <= n; j++) {
      double x = j * h;
      if(j == n / 2) x = (j - 1) * h + gap * h; // squeeze this column
      t.points.push_back(SPoint3(x, i * h, 0.));
    }
  }
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for(int i = 0; i < n; i++) {
    for(int j = 0; j < n; j++) {
      t.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      t.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  return t;
}

testTriangulation liftPlanar(testTriangulation t, double amplitude)
{
  for(auto &p : t.points)
    p = SPoint3(p.x(), p.y(),
                amplitude * std::sin(2. * p.x()) * std::cos(3. * p.y()));
  return t;
}

discretePatch makePatchOrDie(const testTriangulation &t)
{
  discretePatch patch;
  reparamError err = makeDiscretePatch(t.points, t.triangles, patch);
  if(!err.ok()) throw std::runtime_error(err.what());
  return patch;
}

double uvArea2(const std::vector<double> &uv, const std::array<int, 3> &t)
{
  return signedArea2(uv[2 * t[0]], uv[2 * t[0] + 1], uv[2 * t[1]],
                     uv[2 * t[1] + 1], uv[2 * t[2]], uv[2 * t[2] + 1]);
}

double minKappa(const testTriangulation &t)
{
  double k = 1.;
  for(const auto &tri : t.triangles)
    k = std::min(
      k, triangleKappa(t.points[tri[0]], t.points[tri[1]], t.points[tri[2]]));
  return k;
}

testTriangulation rectangleGrid(int nx, int ny, double lx, double ly)
{
  testTriangulation t;
  for(int j = 0; j <= ny; j++)
    for(int i = 0; i <= nx; i++)
      t.points.push_back(SPoint3(lx * i / nx, ly * j / ny, 0.));
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for(int j = 0; j < ny; j++) {
    for(int i = 0; i < nx; i++) {
      int a = id(i, j), b = id(i + 1, j), c = id(i, j + 1),
          d = id(i + 1, j + 1);
      if((i + j) % 2) {
        t.triangles.push_back({a, b, d});
        t.triangles.push_back({a, d, c});
      }
      else {
        t.triangles.push_back({a, b, c});
        t.triangles.push_back({b, d, c});
      }
    }
  }
  return t;
}

testTriangulation halfCylinder(int nAround, int nAlong, double length)
{
  testTriangulation t = rectangleGrid(nAround, nAlong, M_PI, length);
  for(auto &p : t.points) p = SPoint3(std::cos(p.x()), std::sin(p.x()), p.y());
  return t;
}

testTriangulation sphericalCap(int rings, int sectors, double angle)
{
  testTriangulation t = polarDisk(rings, sectors);
  for(auto &p : t.points) {
    double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    double phi = std::atan2(p.y(), p.x()), theta = r * angle;
    p = SPoint3(std::sin(theta) * std::cos(phi),
                std::sin(theta) * std::sin(phi), std::cos(theta));
  }
  return t;
}

testTriangulation saddleStrip(int nx, int ny, double length, double amplitude)
{
  testTriangulation t = rectangleGrid(nx, ny, length, 1.);
  for(auto &p : t.points) {
    double x = p.x() - 0.5 * length, y = p.y() - 0.5;
    p = SPoint3(p.x(), p.y(), amplitude * (x * x - y * y));
  }
  return t;
}

testTriangulation helicoidStrip(int nAround, int nAcross, double turns,
                                double r1, double r2, double pitch)
{
  testTriangulation t = rectangleGrid(nAround, nAcross, 1., 1.);
  for(auto &p : t.points) {
    double phi = 2. * M_PI * turns * p.x(), r = r1 + (r2 - r1) * p.y();
    p = SPoint3(r * std::cos(phi), r * std::sin(phi), pitch * turns * p.x());
  }
  return t;
}

testTriangulation jitteredGrid(int n, double amount, unsigned seed)
{
  testTriangulation t = rectangleGrid(n, n, 1., 1.);
  unsigned state = seed;
  auto random = [&]() { // in [-0.5, 0.5)
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24) - 0.5;
  };
  for(auto &p : t.points) {
    if(p.x() <= 0. || p.x() >= 1. || p.y() <= 0. || p.y() >= 1.) continue;
    double dy = amount * random() / n;
    double dx = amount * random() / n;
    p = SPoint3(p.x() + dx, p.y() + dy, 0.);
  }
  return t;
}

testTriangulation weld(testTriangulation t, double tol)
{
  std::map<std::array<long long, 3>, int> cells;
  std::vector<int> index(t.points.size(), -1);
  std::vector<SPoint3> kept;
  for(const auto &tri : t.triangles)
    for(int i : tri) {
      if(index[i] >= 0) continue;
      std::array<long long, 3> key;
      for(int c = 0; c < 3; c++) key[c] = std::llround(t.points[i][c] / tol);
      auto it = cells.insert(std::make_pair(key, (int)kept.size()));
      if(it.second) kept.push_back(t.points[i]);
      index[i] = it.first->second;
    }
  std::vector<std::array<int, 3> > triangles;
  for(auto tri : t.triangles) {
    for(int &v : tri) v = index[v];
    if(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0])
      triangles.push_back(tri);
  }
  t.points = kept;
  t.triangles = triangles;
  return t;
}

testTriangulation torus(int nAround, int nTube, double R, double r)
{
  testTriangulation t = rectangleGrid(nAround, nTube, 1., 1.);
  for(auto &p : t.points) {
    double phi = 2. * M_PI * p.x(), theta = 2. * M_PI * p.y();
    double rho = R + r * std::cos(theta);
    p = SPoint3(rho * std::cos(phi), rho * std::sin(phi), r * std::sin(theta));
  }
  return weld(t, 1e-9);
}

testTriangulation sphere(int nLongitude, int nLatitude)
{
  testTriangulation t = rectangleGrid(nLongitude, nLatitude, 1., 1.);
  for(auto &p : t.points) {
    double phi = 2. * M_PI * p.x(), theta = M_PI * p.y();
    p = SPoint3(std::sin(theta) * std::cos(phi),
                std::sin(theta) * std::sin(phi), -std::cos(theta));
  }
  return weld(t, 1e-9);
}

surfaceMesh asSurfaceMesh(const testTriangulation &t)
{
  surfaceMesh m;
  m.points = t.points;
  m.triangles = t.triangles;
  return m;
}

double quadAreaXY(const surfaceMesh &m, const std::array<int, 4> &q)
{
  double a = 0.;
  for(int k = 0; k < 4; k++) {
    const SPoint3 &p = m.points[q[k]], &r = m.points[q[(k + 1) % 4]];
    a += p.x() * r.y() - r.x() * p.y();
  }
  return 0.5 * a;
}

surfaceMesh quadGrid(int n)
{
  surfaceMesh m;
  for(int j = 0; j <= n; j++)
    for(int i = 0; i <= n; i++) m.points.push_back(SPoint3(i, j, 0.));
  for(int j = 0; j < n; j++)
    for(int i = 0; i < n; i++) {
      const int a = i + (n + 1) * j;
      m.quadrangles.push_back({{a, a + 1, a + n + 2, a + n + 1}});
    }
  return m;
}

// An 8 x 8 grid of the unit square whose edge ab of the cells (4, 4) and
// (4, 3) is split by a node m at its midpoint moved by `offset`: the
// triangle (b, a, m) degenerate (no offset) or a sliver
testTriangulation gridWithSplitEdge(const SPoint3 &offset)
{
  testTriangulation t = rectangleGrid(8, 8, 1., 1.);
  auto id = [](int i, int j) { return j * 9 + i; };
  const int a = id(4, 4), b = id(5, 4), below = id(4, 3);
  const int m = (int)t.points.size();
  t.points.push_back((t.points[a] + t.points[b]) * 0.5 + offset);
  auto it = std::find(t.triangles.begin(), t.triangles.end(),
                      std::array<int, 3>{{below, b, a}});
  if(it == t.triangles.end()) return t;
  *it = {{below, b, m}};
  t.triangles.push_back({{below, m, a}});
  t.triangles.push_back({{b, a, m}});
  return t;
}
