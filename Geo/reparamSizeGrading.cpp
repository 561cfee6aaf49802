// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <map>
#include <memory>
#include "BackgroundMeshTools.h"
#include "GEdge.h"
#include "GFace.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MVertex.h"
#include "gradedBoundarySize.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"

namespace {

  // Boundary nodes whose segments are this close to the size asked are
  // left out: they would barely change it, and every query goes through
  // the nodes smaller than the size it finds
  const double nearlyTheSize = 0.9;

  // One face at a time per thread: Gmsh meshes each face on one thread
  struct grading {
    GFace *face = nullptr;
    int meshSizeFromBoundary = -1; // the face's own setting, restored
    std::unique_ptr<gradedBoundarySize> size;
  };
  thread_local grading current;

  // The nodes of gf's curves (embedded ones too) whose shortest segment is
  // shorter than the size asked there, with that length (Gmsh's size of a
  // boundary node, meshGFace.cpp)
  std::unique_ptr<gradedBoundarySize> boundarySizes(GFace *gf, double gradient)
  {
    std::map<MVertex *, int> index;
    std::vector<SPoint3> nodes;
    std::vector<std::pair<int, int> > segments;
    std::vector<GEdge *> edges = gf->edges();
    for(GEdge *ge : gf->embeddedEdges()) edges.push_back(ge);
    for(GEdge *ge : edges) {
      for(MLine *l : ge->lines) {
        int ends[2];
        for(int k = 0; k < 2; k++) {
          MVertex *v = l->getVertex(k);
          auto it = index.emplace(v, (int)nodes.size()).first;
          if(it->second == (int)nodes.size()) nodes.push_back(v->point());
          ends[k] = it->second;
        }
        segments.push_back({ends[0], ends[1]});
      }
    }
    const std::vector<double> shortest =
      shortestSegmentAtNodes(nodes, segments);
    std::vector<SPoint3> small;
    std::vector<double> sizes;
    for(std::size_t i = 0; i < nodes.size(); i++) {
      const SPoint3 &p = nodes[i];
      if(shortest[i] <= 0. ||
         shortest[i] >=
           nearlyTheSize * BGM_MeshSize(gf, 0., 0., p.x(), p.y(), p.z()))
        continue;
      small.push_back(p);
      sizes.push_back(shortest[i]);
    }
    return std::unique_ptr<gradedBoundarySize>(
      new gradedBoundarySize(small, sizes, gradient));
  }

} // namespace

void reparamBeginSizeGrading(GFace *gf)
{
  // Reparam's maps only: Gmsh's own (0) keeps Gmsh's sizes (the reference)
  const parametrizationRecord *map = findParametrization(gf);
  const double gradient = getReparamOptions().meshSizeGradient;
  if(!map || map->map <= 0 || gradient <= 0. ||
     !gf->getMeshSizeFromBoundary())
    return;
  current.size = boundarySizes(gf, gradient);
  current.face = gf;
  current.meshSizeFromBoundary = gf->meshAttributes.meshSizeFromBoundary;
  gf->setMeshSizeFromBoundary(0);
  Msg::Debug("Reparam: surface %d: sizes of %lu boundary nodes graded by %g",
             gf->tag(), current.size->size(), gradient);
}

void reparamEndSizeGrading(GFace *gf)
{
  if(current.face != gf) return;
  gf->setMeshSizeFromBoundary(current.meshSizeFromBoundary);
  current = grading();
}

double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size)
{
  if(!current.face || ge != current.face) return size;
  return (*current.size)(SPoint3(x, y, z), size);
}
