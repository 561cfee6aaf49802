// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <map>
#include <string>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "meshFidelity.h"
#include "reparamNoiseFaces.h"
#include "reparamOptimizableMesh.h"

double triangulationWidth(const surfaceMesh &mesh)
{
  std::map<std::pair<int, int>, int> uses;
  double area = 0.;
  for(const std::array<int, 3> &t : mesh.triangles) {
    const SPoint3 &a = mesh.points[t[0]], &b = mesh.points[t[1]],
                  &c = mesh.points[t[2]];
    area += 0.5 * crossprod(SVector3(a, b), SVector3(a, c)).norm();
    for(int k = 0; k < 3; k++) {
      const int p = t[k], q = t[(k + 1) % 3];
      uses[std::make_pair(std::min(p, q), std::max(p, q))]++;
    }
  }
  double length = 0.;
  for(const auto &e : uses)
    if(e.second == 1)
      length +=
        mesh.points[e.first.first].distance(mesh.points[e.first.second]);
  if(!(length > 0.)) return mesh.triangles.empty() ? 0. : 1e300;
  return 2. * area / length;
}

namespace {

  // Sum and count of the edge lengths of gf's triangles
  void addEdges(const GFace *gf, double &sum, std::size_t &count)
  {
    for(const MTriangle *t : gf->triangles)
      for(int k = 0; k < 3; k++) {
        sum +=
          t->getVertex(k)->point().distance(t->getVertex((k + 1) % 3)->point());
        count++;
      }
  }

  // The mean edge of the meshes of the faces gf shares a curve with (gf's
  // own mesh when it has none): gf's own mesh is made of its curves' nodes,
  // as close as they are
  double meshSizeAround(GFace *gf)
  {
    double sum = 0.;
    std::size_t count = 0;
    std::set<GFace *> around;
    for(GEdge *ge : gf->edges())
      for(GFace *other : ge->faces())
        if(other != gf) around.insert(other);
    for(GFace *f : around) addEdges(f, sum, count);
    if(!count) addEdges(gf, sum, count);
    return count ? sum / count : 0.;
  }

} // namespace

std::set<GEdge *> reparamNoiseFaceCurves(GModel *m)
{
  std::set<GEdge *> curves;
  std::string tags;
  std::size_t faces = 0;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    if(!reparamOptimizableFace(gf)) continue;
    const double width = triangulationWidth(inputTriangulationOf(gf));
    const double size = meshSizeAround(gf);
    if(!(width < 0.25 * size)) continue;
    for(GEdge *ge : gf->edges()) {
      const std::vector<GFace *> sides = ge->faces();
      if(sides.size() == 2 && sides[0] != sides[1] &&
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
