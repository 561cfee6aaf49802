// Reparam - Mesh.CompoundCurvatureMetric: BAMG meshes a tube with elements
// long along its axis and 2 pi R / N around, fewer than the isotropic mesh
// of Mesh.MeshSizeFromCurvature for the same distance to the surface; the
// optimization leaves them; off by default

#include <algorithm>
#include <cmath>
#include <iostream>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "OpenFile.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamCurvatureMetric.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // The unit-radius tube along z, of the given length, open at both ends
  testTriangulation tube(int nAround, int nAlong, double length)
  {
    testTriangulation t = rectangleGrid(nAround, nAlong, 2. * M_PI, length);
    for(SPoint3 &p : t.points)
      p = SPoint3(std::cos(p.x()), std::sin(p.x()), p.y());
    return weld(t, 1e-9);
  }

  struct tubeMesh {
    std::size_t triangles = 0;
    // the largest distance of a triangle's centroid to the cylinder (its
    // sag: the input's own is 0.0005)
    double sag = 0.;
    // the mean length of the edges along the axis (within 30 degrees of
    // it) and around it (within 30 degrees of the circles)
    double along = 0., around = 0.;
    std::size_t anisotropicFaces = 0;
  };

  tubeMesh measureTube()
  {
    tubeMesh m;
    double along = 0., around = 0.;
    std::size_t nAlong = 0, nAround = 0;
    GModel *model = GModel::current();
    for(auto it = model->firstFace(); it != model->lastFace(); ++it) {
      m.anisotropicFaces += reparamAnisotropicFace(*it);
      for(MTriangle *t : (*it)->triangles) {
        m.triangles++;
        const SPoint3 g = t->barycenter();
        m.sag = std::max(m.sag, 1. - std::hypot(g.x(), g.y()));
        for(int k = 0; k < 3; k++) {
          const SVector3 e(t->getVertex(k)->point(),
                           t->getVertex((k + 1) % 3)->point());
          const double l = e.norm(), c = std::fabs(e.z()) / l;
          if(c > std::cos(M_PI / 6.)) {
            along += l;
            nAlong++;
          }
          else if(c < std::sin(M_PI / 6.)) {
            around += l;
            nAround++;
          }
        }
      }
    }
    m.along = nAlong ? along / nAlong : 0.;
    m.around = nAround ? around / nAround : 0.;
    return m;
  }

  // The recipe on the tube, sizes in [0.05, 1.2], with 20 elements per
  // circle of curvature: Gmsh's isotropic sizes with Frontal-Delaunay, or
  // Reparam's metric with `algorithm`
  tubeMesh remeshTube(bool anisotropic, int algorithm)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.05);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1.2);
    gmsh::option::setNumber("Mesh.Algorithm", algorithm);
    gmsh::option::setNumber(anisotropic ? "Mesh.CompoundCurvatureMetric" :
                                          "Mesh.MeshSizeFromCurvature",
                            20);
    addDiscreteSurface(tube(96, 60, 6.));
    // the model's scale, as Merge sets it (the sizes are bounded by it): not
    // the scale of whatever file a test before merged
    SetBoundingBox();
    gmsh::model::mesh::classifySurfaces(40. * M_PI / 180., true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::model::mesh::generate(2);
    const tubeMesh m = measureTube();
    gmsh::option::setNumber("Mesh.CompoundCurvatureMetric", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    return m;
  }

} // namespace

TEST(curvatureMetricMesh, tubeIsMeshedLongAlongItsAxis)
{
  // at the tube's own scale (its curves get Gmsh's sizes from it, a tenth
  // of its diagonal): measured isotropic 936 triangles, sag 0.0194, edges
  // 0.304 along and 0.307 around (2 pi / 20 = 0.314); anisotropic 258,
  // sag 0.0158, 0.924 along and 0.325 around (the same each run since
  // BAMG gets the nodes in the order of their numbers, patches/0025; it was
  // 260-278 triangles, 0.82-0.92 along, from run to run and environment to
  // environment)
  const tubeMesh iso = remeshTube(false, 6);
  const tubeMesh aniso = remeshTube(true, 7);
  std::cout << "isotropic: " << iso.triangles << " triangles, along "
            << iso.along << ", around " << iso.around << ", sag " << iso.sag
            << "; anisotropic: " << aniso.triangles << ", along "
            << aniso.along << ", around " << aniso.around << ", sag "
            << aniso.sag << std::endl;
  EXPECT_EQ(iso.anisotropicFaces, 0u);
  EXPECT_GT(aniso.anisotropicFaces, 0u);
  EXPECT_NEAR(iso.along / iso.around, 1., 0.1);
  EXPECT_NEAR(iso.around, 2. * M_PI / 20., 0.03);
  EXPECT_GT(aniso.along, 2.7 * aniso.around);
  EXPECT_NEAR(aniso.around, 2. * M_PI / 20., 0.02);
  // far fewer elements for about the same distance to the surface
  EXPECT_LT(aniso.triangles, 0.3 * iso.triangles);
  EXPECT_LT(aniso.sag, 1.1 * iso.sag);
}

TEST(curvatureMetricMesh, isotropicMeshersTakeTheSmallestSize)
{
  // Frontal-Delaunay with Reparam's sizes: the smallest both ways, as with
  // Gmsh's Mesh.MeshSizeFromCurvature
  const tubeMesh gmshSizes = remeshTube(false, 6);
  const tubeMesh m = remeshTube(true, 6);
  EXPECT_EQ(m.anisotropicFaces, 0u);
  EXPECT_NEAR(m.along / m.around, 1., 0.1);
  EXPECT_NEAR(m.around / gmshSizes.around, 1., 0.1);
  EXPECT_NEAR((double)m.triangles / gmshSizes.triangles, 1., 0.15);
}

TEST(curvatureMetricMesh, optionIsOffByDefaultAndNonNegative)
{
  double value = -1.;
  gmsh::option::getNumber("Mesh.CompoundCurvatureMetric", value);
  EXPECT_EQ(value, 0.);
  gmsh::logger::start();
  gmsh::option::setNumber("Mesh.CompoundCurvatureMetric", -3);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  gmsh::option::getNumber("Mesh.CompoundCurvatureMetric", value);
  EXPECT_EQ(value, 0.);
  bool said = false;
  for(const std::string &l : log)
    said = said || l.find("Mesh.CompoundCurvatureMetric must be >= 0") !=
                     std::string::npos;
  EXPECT_TRUE(said);
  gmsh::option::setNumber("Mesh.CompoundCurvatureMetric", 20);
  gmsh::option::getNumber("Mesh.CompoundCurvatureMetric", value);
  EXPECT_EQ(value, 20.);
  gmsh::option::setNumber("Mesh.CompoundCurvatureMetric", 0);
}
