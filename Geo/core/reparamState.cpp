// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "reparamReport.h"
#include "reparamState.h"

namespace reparam {

namespace {

  // Every record, found by its face or model: never iterated (their order
  // is the pointers'), so nothing depends on where Gmsh allocated them
  struct reparamState {
    std::mutex recordsMutex, reportsMutex, curvatureMutex;
    std::map<const GFace *, faceRecord> faces;
    std::map<const GModel *, modelRecord> models;
    std::unique_ptr<layoutRecord> layout{new layoutRecord};
    std::vector<faceReport> reports;
    std::shared_mutex curves;
    savedOptions options;
  };

  reparamState &state()
  {
    static reparamState s;
    return s;
  }

} // namespace

std::unique_lock<std::mutex> lockRecords()
{
  return std::unique_lock<std::mutex>(state().recordsMutex);
}

faceRecord &faceRecordOf(const GFace *gf) { return state().faces[gf]; }

faceRecord *findFaceRecord(const GFace *gf)
{
  auto it = state().faces.find(gf);
  return it == state().faces.end() ? nullptr : &it->second;
}

modelRecord &modelRecordOf(const GModel *m) { return state().models[m]; }

modelRecord *findModelRecord(const GModel *m)
{
  auto it = state().models.find(m);
  return it == state().models.end() ? nullptr : &it->second;
}

layoutRecord &lastLayout() { return *state().layout; }

void beginLayoutRecords(const GModel *m)
{
  state().layout.reset(new layoutRecord);
  std::lock_guard<std::mutex> lock(state().recordsMutex);
  state().models.erase(m);
}

void beginFaceRecord(const GFace *gf)
{
  std::lock_guard<std::mutex> lock(state().recordsMutex);
  state().faces.erase(gf);
}

std::vector<faceReport> &pendingFaceReports() { return state().reports; }

std::unique_lock<std::mutex> lockReports()
{
  return std::unique_lock<std::mutex>(state().reportsMutex);
}

std::unique_lock<std::mutex> lockCurvatureFields()
{
  return std::unique_lock<std::mutex>(state().curvatureMutex);
}

faceMeshingContext &thisThreadsFaceMeshing()
{
  thread_local faceMeshingContext context;
  return context;
}

std::shared_mutex &curvesLock() { return state().curves; }

savedOptions &savedGmshOptions() { return state().options; }

} // namespace reparam
