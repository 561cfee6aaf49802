// Reparam - CreateGeometry takes the maps the patch layout computed for the
// same parts: every face of a remeshed sphere gets its map from the layout,
// and that map is the one CreateGeometry computes itself, to the last bit

#include <cmath>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamParametrize.h"
#include "reparamReport.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  struct faceMaps {
    std::size_t faces = 0, fromLayout = 0;
    std::vector<std::vector<SPoint2> > uv;
  };

  // The sphere classified and its geometry created; with forget, the
  // layout's maps dropped in between
  faceMaps createSphere(bool forget)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    addDiscreteSurface(sphere(48, 24));
    gmsh::model::mesh::classifySurfaces(40. * M_PI / 180., true, true, M_PI);
    if(forget) reparamForgetLayoutMaps();
    gmsh::model::mesh::createGeometry();
    faceMaps f;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      const parametrizationRecord *r = findParametrization(*it);
      if(!r) continue;
      f.faces++;
      f.fromLayout += r->fromLayout;
      f.uv.push_back((*it)->stl_vertices_uv);
    }
    return f;
  }

} // namespace

TEST(layoutMaps, createGeometryTakesTheLayoutsMaps)
{
  const faceMaps reused = createSphere(false);
  const faceMaps computed = createSphere(true);
  ASSERT_GE(reused.faces, 2u); // the closed sphere is cut into disks
  EXPECT_EQ(reused.fromLayout, reused.faces);
  EXPECT_EQ(computed.fromLayout, 0u);
  ASSERT_EQ(reused.uv.size(), computed.uv.size());
  for(std::size_t f = 0; f < reused.uv.size(); f++) {
    ASSERT_EQ(reused.uv[f].size(), computed.uv[f].size());
    for(std::size_t i = 0; i < reused.uv[f].size(); i++) {
      EXPECT_EQ(reused.uv[f][i].x(), computed.uv[f][i].x());
      EXPECT_EQ(reused.uv[f][i].y(), computed.uv[f][i].y());
    }
  }
}
