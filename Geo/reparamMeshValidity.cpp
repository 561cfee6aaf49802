// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "GFace.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "reparamMeshValidity.h"
#include "reparamReport.h"

std::size_t countElementsAgainstFaceNormals(GFace *gf)
{
  std::size_t against = 0;
  for(MTriangle *t : gf->triangles) {
    SVector3 n(0., 0., 0.);
    for(int k = 0; k < 3; k++) {
      SPoint2 uv;
      reparamMeshVertexOnFace(t->getVertex(k), gf, uv);
      n += gf->normal(uv);
    }
    SVector3 d1(t->getVertex(0)->point(), t->getVertex(1)->point());
    SVector3 d2(t->getVertex(0)->point(), t->getVertex(2)->point());
    if(dot(n, crossprod(d1, d2)) < 0.) against++;
  }
  return std::min(against, gf->triangles.size() - against);
}

bool reparamKeepPlanarMesh(GFace *gf)
{
  // Reparam's own maps only: Gmsh's map keeps Gmsh's behaviour (reference)
  const parametrizationRecord *record = findParametrization(gf);
  if(!record || record->map <= 0 || gf->triangles.empty()) return false;
  const std::size_t against = countElementsAgainstFaceNormals(gf);
  if(100 * against > gf->triangles.size()) return false;
  Msg::Info("Reparam: surface %d: mesh kept with %lu of its %lu elements "
            "against the input normals (no MeshAdapt remesh)",
            gf->tag(), against, gf->triangles.size());
  return true;
}
