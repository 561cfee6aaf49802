// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <string>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "reparamLayout.h"
#include "reparamNoiseFaces.h"
#include "reparamOptimizableMesh.h"
#include "reparamSurfaceMesh.h"
#include "surfaceMesh.h"

namespace reparam {

double triangulationWidth(const surfaceMesh &mesh)
{
  std::vector<int> nodes;
  nodes.reserve(3 * mesh.triangles.size());
  for(const std::array<int, 3> &t : mesh.triangles)
    nodes.insert(nodes.end(), t.begin(), t.end());
  double area, length;
  areaAndBoundaryLength(mesh.points, nodes, area, length);
  if(!(length > 0.)) return mesh.triangles.empty() ? 0. : 1e300;
  return 2. * area / length;
}

namespace {

  // Sum and count of the edge lengths of each face's triangles
  typedef std::map<const GFace *, std::pair<double, std::size_t> > edgeSums;

  edgeSums edgeSumsOf(GModel *m)
  {
    edgeSums sums;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      std::pair<double, std::size_t> &s = sums[*it];
      s = {0., 0};
      for(const MTriangle *t : (*it)->triangles)
        for(int k = 0; k < 3; k++) {
          s.first += t->getVertex(k)->point().distance(
            t->getVertex((k + 1) % 3)->point());
          s.second++;
        }
    }
    return sums;
  }

  // The mean edge of the meshes of the faces gf shares a curve with (gf's
  // own mesh when it has none): gf's own mesh is made of its curves' nodes,
  // as close as they are
  double meshSizeAround(GFace *gf, const edgeSums &sums)
  {
    double sum = 0.;
    std::size_t count = 0;
    std::set<GFace *> around;
    for(GEdge *ge : gf->edges())
      for(GFace *other : ge->faces())
        if(other != gf) around.insert(other);
    for(GFace *f : around) {
      sum += sums.at(f).first;
      count += sums.at(f).second;
    }
    if(!count) {
      sum = sums.at(gf).first;
      count = sums.at(gf).second;
    }
    return count ? sum / count : 0.;
  }

  // How many sides of faces a curve has: a face on both sides of it counts
  // twice (Gmsh's classification leaves such a curve inside a face along a
  // fin, a triangle standing on an inner edge, that then has three sides)
  std::size_t curveSides(GEdge *ge)
  {
    std::size_t sides = 0;
    for(GFace *gf : ge->faces()) {
      const std::vector<GEdge *> &edges = gf->edges();
      sides += std::count(edges.begin(), edges.end(), ge);
    }
    return sides;
  }

} // namespace

std::set<GEdge *> reparamNoiseFaceCurves(GModel *m)
{
  std::set<GEdge *> curves;
  const edgeSums sums = edgeSumsOf(m);
  std::string tags;
  std::size_t faces = 0;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    if(!reparamOptimizableFace(gf)) continue;
    const double width = triangulationWidth(inputTriangulationOf(gf));
    const double size = meshSizeAround(gf, sums);
    if(!(width < 0.25 * size)) continue;
    for(GEdge *ge : gf->edges()) {
      const std::vector<GFace *> sides = ge->faces();
      if(sides.size() == 2 && sides[0] != sides[1] && curveSides(ge) == 2 &&
         reparamOptimizableFace(sides[0]) && reparamOptimizableFace(sides[1]))
        curves.insert(ge);
    }
    if(faces++ < 8)
      tags += (tags.empty() ? "" : ", ") + std::to_string(gf->tag());
    else if(faces == 9)
      tags += ", ...";
  }
  if(faces)
    Msg::Info("Reparam: %lu surface%s narrower than a quarter of the mesh "
              "size (%s): %lu curves to other surfaces may be crossed",
              faces, faces > 1 ? "s" : "", tags.c_str(), curves.size());
  return curves;
}
} // namespace reparam

