// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A MeshAdapt mesh of a face Reparam parametrized, checked as the
// Delaunay-based meshers' are (Geo/planar/reparamMeshValidity.h). Gmsh tests only
// those (and remeshes a failed one with MeshAdapt); a mesh the user asked
// MeshAdapt for was kept whatever it was, with dozens of triangles against
// the input where a hole runs close along a border, while Delaunay's mesh
// of that face has none (bench/README.md, MeshAdapt's meshes checked).

#include "GFace.h"
#include "GmshDefines.h"
#include "GmshMessage.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamMesherFallback.h"
#include "reparamMeshValidity.h"
#include "reparamReport.h"

namespace reparam {

namespace {

  meshDefects defectsOf(GFace *gf)
  {
    meshDefects d;
    d.unusedCurveSegments = countUnusedCurveSegments(gf);
    d.againstInput = countTrianglesAgainstInput(gf);
    return d;
  }

  bool whole(const meshDefects &d)
  {
    return !d.unusedCurveSegments && !d.againstInput;
  }

} // namespace

} // namespace reparam

using namespace reparam;

bool reparamCheckMeshAdaptMesh(GFace *gf)
{
  if(reparamTryingOtherMesher() || gf->getMeshingAlgo() != ALGO_2D_MESHADAPT)
    return false;
  const parametrizationRecord *record = findParametrization(gf);
  if(!record || record->map <= 0 || !gf->getNumMeshElements()) return false;
  const bool triangles = gf->quadrangles.empty();
  // recorded for this mesh: the hook after the mesher does not redo it
  if(triangles) reparamOptimizeMeshedFace(gf);
  meshDefects defects = defectsOf(gf);
  if(whole(defects)) return false;
  defects.longEdges = countLongEdges(gf);
  Msg::Info("Reparam: surface %d: MeshAdapt leaves %s: the other planar "
            "meshers tried",
            gf->tag(), meshDefectsText(defects, "element").c_str());
  bool replaced = false;
  for(int other : {ALGO_2D_DELAUNAY, ALGO_2D_FRONTAL}) {
    if(!reparamTryOtherMesher(gf, defects, other)) continue;
    replaced = true;
    defects = defectsOf(gf);
    if(whole(defects)) return true;
    defects.longEdges = countLongEdges(gf);
  }
  if(gf->quadrangles.empty() && !defects.unusedCurveSegments)
    replaced |= reparamMeshFaceWithItsInput(gf, defects.againstInput);
  return replaced;
}

