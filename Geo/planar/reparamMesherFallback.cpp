// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "Context.h"
#include "GFace.h"
#include "GmshDefines.h"
#include "GmshMessage.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "meshFidelity.h"
#include "meshGFace.h"
#include "reparamHooks.h"
#include "reparamMeshValidity.h"
#include "reparamMesherFallback.h"
#include "reparamReport.h"
#include "reparamState.h"
#include "reparamSurfaceMesh.h"

namespace reparam {

namespace {

  // A face's mesh taken out of it (Gmsh's mesher deletes what the face
  // holds)
  struct detachedMesh {
    std::vector<MTriangle *> triangles;
    std::vector<MQuadrangle *> quadrangles;
    std::vector<MVertex *> nodes;
  };

  detachedMesh detach(GFace *gf)
  {
    detachedMesh m;
    m.triangles.swap(gf->triangles);
    m.quadrangles.swap(gf->quadrangles);
    m.nodes.swap(gf->mesh_vertices);
    gf->deleteVertexArrays();
    return m;
  }

  void destroy(detachedMesh &m)
  {
    for(MTriangle *t : m.triangles) delete t;
    for(MQuadrangle *q : m.quadrangles) delete q;
    for(MVertex *v : m.nodes) delete v;
    m = detachedMesh();
  }

  // gf's mesh replaced by m
  void attach(GFace *gf, detachedMesh &m)
  {
    gf->deleteMesh();
    gf->triangles.swap(m.triangles);
    gf->quadrangles.swap(m.quadrangles);
    gf->mesh_vertices.swap(m.nodes);
    gf->meshStatistics.status = GFace::DONE;
  }

  const char *algorithmName(int algorithm)
  {
    switch(algorithm) {
    case ALGO_2D_MESHADAPT: return "MeshAdapt";
    case ALGO_2D_DELAUNAY: return "Delaunay";
    case ALGO_2D_FRONTAL: return "Frontal-Delaunay";
    default: return "another algorithm";
    }
  }

} // namespace

std::string meshDefectsText(const meshDefects &d, const char *element)
{
  std::string text;
  if(d.unusedCurveSegments)
    text = std::to_string(d.unusedCurveSegments) + " segment" +
           (d.unusedCurveSegments == 1 ? "" : "s") + " of its curves unused, ";
  if(d.againstInput == (std::size_t)-1)
    text += std::string(element) + "s against the input not counted";
  else
    text += std::to_string(d.againstInput) + " " + element +
            (d.againstInput == 1 ? "" : "s") + " against the input";
  if(d.longEdges)
    text +=
      ", " + std::to_string(d.longEdges) + " edges longer than twice the size";
  return text;
}

bool reparamTryingOtherMesher()
{
  return thisThreadsFaceMeshing().tryingOtherMesher;
}

std::size_t countTrianglesAgainstInput(GFace *gf)
{
  const optimizationRecord *o = findOptimization(gf);
  if(o && gf->quadrangles.empty()) return o->againstAfter;
  const std::size_t raw =
    countInverted(inputTriangulationOf(gf), surfaceMeshOf(gf));
  return std::min(raw, gf->getNumMeshElements() - raw);
}

bool reparamTryOtherMesher(GFace *gf, const meshDefects &current, int algorithm)
{
  const char *element = gf->quadrangles.empty() ? "triangle" : "element";
  int other = algorithm;
  if(!other)
    other = gf->getMeshingAlgo() == ALGO_2D_DELAUNAY ? ALGO_2D_FRONTAL :
                                                       ALGO_2D_DELAUNAY;
  detachedMesh kept = detach(gf);
  bool &trying = thisThreadsFaceMeshing().tryingOtherMesher;
  trying = true;
  gf->setMeshingAlgo(other);
  // Gmsh's meshers read the global algorithm too: under BAMG's, Delaunay's
  // point insertion takes no size field (meshGFaceDelaunayInsertion.cpp;
  // bench/README.md, "BAMG") nor MeshAdapt's the curves' sizes. The other mesher's, for this
  // mesh (BAMG's faces are meshed on one thread: Geo/planar/reparamFaceMeshing.h)
  const int global = CTX::instance()->mesh.algo2d;
  if(global == ALGO_2D_BAMG) CTX::instance()->mesh.algo2d = other;
  meshGFace()(gf, false);
  CTX::instance()->mesh.algo2d = global;
  gf->unsetMeshingAlgo();
  trying = false;
  reparamOptimizeMeshedFace(gf);
  meshDefects found;
  found.unusedCurveSegments = countUnusedCurveSegments(gf);
  found.againstInput = countTrianglesAgainstInput(gf);
  found.longEdges = countLongEdges(gf);
  if(gf->getNumMeshElements() && found < current) {
    destroy(kept);
    Msg::Info("Reparam: surface %d: remeshed with %s: %s -> %s", gf->tag(),
              algorithmName(other), meshDefectsText(current, element).c_str(),
              meshDefectsText(found, element).c_str());
    return true;
  }
  forgetOptimization(gf);
  attach(gf, kept);
  Msg::Info("Reparam: surface %d: %s left %s: mesh kept", gf->tag(),
            algorithmName(other), meshDefectsText(found, element).c_str());
  return false;
}
} // namespace reparam

