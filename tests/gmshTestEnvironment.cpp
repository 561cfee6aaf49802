// Reparam - helpers for tests that run inside Gmsh (through its API)

#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"

using namespace reparam;

namespace {

  // The options the tests change, each put back after every test to its
  // value before the first one: a test that forgot to reset one would
  // change the tests run after it in the same process (ctest runs each
  // alone, a developer may run them all at once); the forgotten ones are
  // named on the standard error
  class optionsPutBack : public ::testing::EmptyTestEventListener {
  public:
    optionsPutBack()
    {
      for(const char *name : numbers) {
        double value;
        gmsh::option::getNumber(name, value);
        _numbers.emplace_back(name, value);
      }
      for(const char *name : strings) {
        std::string value;
        gmsh::option::getString(name, value);
        _strings.emplace_back(name, value);
      }
    }
    void OnTestEnd(const ::testing::TestInfo &test) override
    {
      for(const auto &o : _numbers) {
        double value;
        gmsh::option::getNumber(o.first, value);
        if(value == o.second) continue;
        std::cerr << test.test_suite_name() << "." << test.name() << " left "
                  << o.first << " = " << value << " (" << o.second
                  << " before): put back\n";
        gmsh::option::setNumber(o.first, o.second);
      }
      for(const auto &o : _strings) {
        std::string value;
        gmsh::option::getString(o.first, value);
        if(value == o.second) continue;
        std::cerr << test.test_suite_name() << "." << test.name() << " left "
                  << o.first << " = \"" << value << "\": put back\n";
        gmsh::option::setString(o.first, o.second);
      }
    }

  private:
    static constexpr const char *numbers[] = {"Mesh.CompoundParametrization",
                                              "Mesh.CompoundRepair",
                                              "Mesh.CompoundFillHoles",
                                              "Mesh.CompoundLayout",
                                              "Mesh.CompoundNoiseSize",
                                              "Mesh.CompoundFeatureScale",
                                              "Mesh.CompoundSplit",
                                              "Mesh.CompoundCurveCorners",
                                              "Mesh.CompoundMeshSizeGradient",
                                              "Mesh.CompoundMeshSizeFromStrips",
                                              "Mesh.CompoundCurvatureMetric",
                                              "Mesh.CompoundOptimize",
                                              "Mesh.CompoundReport",
                                              "Mesh.ReparamMaxTriangles",
                                              "Mesh.MeshSizeMin",
                                              "Mesh.MeshSizeMax",
                                              "Mesh.MeshSizeFromCurvature",
                                              "Mesh.Algorithm",
                                              "Mesh.RecombineAll",
                                              "General.NumThreads",
                                              "General.Verbosity"};
    static constexpr const char *strings[] = {"Mesh.CompoundReportFile"};
    std::vector<std::pair<std::string, double> > _numbers;
    std::vector<std::pair<std::string, std::string> > _strings;
  };

  class gmshEnvironment : public ::testing::Environment {
  public:
    void SetUp() override
    {
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
      // keep going after errors, like the gmsh executable: the tests provoke
      // some and read them from the log
      gmsh::option::setNumber("General.AbortOnError", 0);
      ::testing::UnitTest::GetInstance()->listeners().Append(
        new optionsPutBack);
    }
    void TearDown() override { gmsh::finalize(); }
  };

  ::testing::Environment *const environment =
    ::testing::AddGlobalTestEnvironment(new gmshEnvironment);

} // namespace

gmshTriangulation::gmshTriangulation(const testTriangulation &t)
{
  for(const auto &p : t.points)
    vertices.push_back(new MVertex(p.x(), p.y(), p.z()));
  for(const auto &tri : t.triangles)
    triangles.push_back(
      new MTriangle(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]));
}

gmshTriangulation::~gmshTriangulation()
{
  for(auto t : triangles) delete t;
  for(auto v : vertices) delete v;
}

gmshParametrization parametrizeWith(const std::vector<MTriangle *> &t,
                                    int choice)
{
  double previous;
  gmsh::option::getNumber("Mesh.CompoundParametrization", previous);
  gmsh::option::setNumber("Mesh.CompoundParametrization", choice);
  gmshParametrization p;
  std::vector<SPoint3> xyz;
  p.ok = computeParametrization(t, p.nodes, p.uv, xyz, p.triangles);
  gmsh::option::setNumber("Mesh.CompoundParametrization", previous);
  return p;
}

double distanceUpToOrthogonal(const std::vector<SPoint2> &a,
                              const std::vector<SPoint2> &b)
{
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  for(std::size_t i = 0; i < a.size(); i++)
    M += Eigen::Vector2d(b[i].x(), b[i].y()) *
         Eigen::Vector2d(a[i].x(), a[i].y()).transpose();
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(M, Eigen::ComputeFullU |
                                             Eigen::ComputeFullV);
  Eigen::Matrix2d Q = svd.matrixU() * svd.matrixV().transpose();
  double worst = 0.;
  for(std::size_t i = 0; i < a.size(); i++) {
    Eigen::Vector2d d = Q * Eigen::Vector2d(a[i].x(), a[i].y()) -
                        Eigen::Vector2d(b[i].x(), b[i].y());
    worst = std::max(worst, d.norm());
  }
  return worst;
}

std::string tutorialFile(const std::string &name)
{
  return std::string(REPARAM_SOURCE_DIR) + "/tutorials/" + name;
}

int addDiscreteSurface(const testTriangulation &t)
{
  int surface = gmsh::model::addDiscreteEntity(2);
  std::vector<std::size_t> tags;
  std::vector<double> coords;
  for(std::size_t i = 0; i < t.points.size(); i++) {
    tags.push_back(i + 1);
    for(int c = 0; c < 3; c++) coords.push_back(t.points[i][c]);
  }
  gmsh::model::mesh::addNodes(2, surface, tags, coords);
  std::vector<std::size_t> nodes;
  for(const auto &tri : t.triangles)
    for(int n : tri) nodes.push_back(n + 1);
  gmsh::model::mesh::addElementsByType(surface, 2, {}, nodes);
  return surface;
}

std::vector<std::string> remeshWithRecipe(const testTriangulation &t,
                                          double size, double featureAngle)
{
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  gmsh::option::setNumber("Mesh.MeshSizeMin", size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  addDiscreteSurface(t);
  gmsh::logger::start();
  gmsh::model::mesh::classifySurfaces(featureAngle * M_PI / 180, true, true,
                                      M_PI);
  gmsh::model::mesh::createGeometry();
  gmsh::model::mesh::generate(2);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  return log;
}

std::vector<std::pair<std::size_t, std::size_t> >
freeMeshEdges(std::size_t *nonManifold)
{
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  for(const auto &f : faces) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes, f.second);
    for(std::size_t i = 0; i + 2 < nodes.size(); i += 3)
      for(int k = 0; k < 3; k++) {
        std::size_t a = nodes[i + k], b = nodes[i + (k + 1) % 3];
        uses[std::make_pair(std::min(a, b), std::max(a, b))]++;
      }
  }
  std::vector<std::pair<std::size_t, std::size_t> > free;
  if(nonManifold) *nonManifold = 0;
  for(const auto &e : uses) {
    if(e.second == 1) free.push_back(e.first);
    if(e.second > 2 && nonManifold) (*nonManifold)++;
  }
  return free;
}

std::vector<int> surfacesWithoutElements()
{
  std::vector<int> empty;
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  for(const auto &f : faces) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes, f.second);
    if(tags.empty()) empty.push_back(f.second);
  }
  return empty;
}

void squareWithAShortCurve()
{
  gmsh::clear();
  std::vector<double> xs = {0., 0.02};
  for(int i = 1; i <= 40; i++) xs.push_back(0.025 * i);
  const int nx = xs.size(), ny = 41;
  auto tag = [&](int i, int j) { return (std::size_t)(j * nx + i + 1); };
  auto xyz = [&](int i, int j) {
    return std::vector<double>{xs[i], 0.025 * j, 0.};
  };
  const int corners[5][2] = {
    {0, 0}, {1, 0}, {nx - 1, 0}, {nx - 1, ny - 1}, {0, ny - 1}};
  for(int p = 0; p < 5; p++) {
    gmsh::model::addDiscreteEntity(0, p + 1);
    const int i = corners[p][0], j = corners[p][1];
    gmsh::model::mesh::addNodes(0, p + 1, {tag(i, j)}, xyz(i, j));
  }
  // each side as the grid nodes from one corner to the next
  for(int c = 0; c < 5; c++) {
    const int *a = corners[c], *b = corners[(c + 1) % 5];
    gmsh::model::addDiscreteEntity(1, c + 1, {c + 1, (c + 1) % 5 + 1});
    std::vector<std::size_t> path, inner;
    std::vector<double> coords;
    const int steps = std::abs(b[0] - a[0]) + std::abs(b[1] - a[1]);
    for(int s = 0; s <= steps; s++) {
      const int i = a[0] + (b[0] > a[0] ? s : b[0] < a[0] ? -s : 0);
      const int j = a[1] + (b[1] > a[1] ? s : b[1] < a[1] ? -s : 0);
      path.push_back(tag(i, j));
      if(s == 0 || s == steps) continue;
      inner.push_back(tag(i, j));
      for(double x : xyz(i, j)) coords.push_back(x);
    }
    gmsh::model::mesh::addNodes(1, c + 1, inner, coords);
    std::vector<std::size_t> lines;
    for(std::size_t s = 0; s + 1 < path.size(); s++) {
      lines.push_back(path[s]);
      lines.push_back(path[s + 1]);
    }
    gmsh::model::mesh::addElementsByType(c + 1, 1, {}, lines);
  }
  gmsh::model::addDiscreteEntity(2, 1, {1, 2, 3, 4, 5});
  std::vector<std::size_t> inner, triangles;
  std::vector<double> coords;
  for(int j = 1; j + 1 < ny; j++)
    for(int i = 1; i + 1 < nx; i++) {
      inner.push_back(tag(i, j));
      for(double x : xyz(i, j)) coords.push_back(x);
    }
  gmsh::model::mesh::addNodes(2, 1, inner, coords);
  for(int j = 0; j + 1 < ny; j++)
    for(int i = 0; i + 1 < nx; i++) {
      for(std::size_t n : {tag(i, j), tag(i + 1, j), tag(i + 1, j + 1)})
        triangles.push_back(n);
      for(std::size_t n : {tag(i, j), tag(i + 1, j + 1), tag(i, j + 1)})
        triangles.push_back(n);
    }
  gmsh::model::mesh::addElementsByType(1, 2, {}, triangles);
  gmsh::model::mesh::createGeometry();
}

uniformMeshSize::uniformMeshSize(double size)
{
  gmsh::option::setNumber("Mesh.MeshSizeMin", size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
}

uniformMeshSize::~uniformMeshSize()
{
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
}

GFace *meshedSquareWithAShortCurve(double size)
{
  squareWithAShortCurve();
  gmsh::option::setNumber("Mesh.MeshSizeMin", size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  return GModel::current()->getFaceByTag(1);
}
