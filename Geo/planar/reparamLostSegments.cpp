// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cstdint>
#include <mutex>
#include <string>
#include "GEdge.h"
#include "GFace.h"
#include "GmshMessage.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamLostSegments.h"
#include "reparamReport.h"
#include "reparamState.h"

namespace reparam {

void meshFaceWithLostSegments(GFace *gf)
{
  int curve = 0;
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    faceRecord *record = findFaceRecord(gf);
    if(!record) return;
    std::swap(curve, record->lostSegmentCurve);
  }
  if(!curve || gf->getNumMeshElements()) return;
  const std::string reason = "Gmsh's planar mesher could not recover the "
                             "segments of curve " +
                             std::to_string(curve) +
                             " in its (u, v) plane (a sliver of the input "
                             "thinner than the mesh size along it)";
  if(reparamMeshFaceWithItsInput(gf, SIZE_MAX, reason)) {
    gf->meshStatistics.status = GFace::DONE;
    return;
  }
  Msg::Error("Reparam: surface %d not meshed: %s, and its input triangles "
             "do not fit its curves' meshes",
             gf->tag(), reason.c_str());
}

} // namespace reparam

using namespace reparam;

bool reparamLostCurveSegment(GFace *gf, GEdge *ge)
{
  // faces Reparam parametrized, whose input is kept for the safety net
  const parametrizationRecord *record = findParametrization(gf);
  if(!record || record->map <= 0 || gf->stl_triangles.empty()) return false;
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecordOf(gf).lostSegmentCurve = ge->tag();
  lock.unlock();
  Msg::Info("Reparam: surface %d: the planar mesher cannot recover a "
            "segment of curve %d in the (u, v) plane",
            gf->tag(), ge->tag());
  return true;
}
