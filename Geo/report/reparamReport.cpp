// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The stages' records for the report (Geo/report/reparamReport.h), measured as the
// faces are meshed and printed once the model is oriented.

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MElement.h"
#include "OS.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamNoiseFaces.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "reparamState.h"
#include "reparamSurfaceMesh.h"

namespace reparam {

namespace {

  bool sameMesh(const faceReport &r, const GFace *gf)
  {
    return r.face == gf && gf->getNumMeshElements() == r.elements &&
           r.elements && gf->getMeshElement(0) == r.firstElement;
  }

} // namespace

void recordParametrization(const GFace *gf, const parametrizationRecord *record)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  if(record)
    faceRecordOf(gf).parametrization = *record;
  else if(faceRecord *r = findFaceRecord(gf))
    r->parametrization.reset();
}

const parametrizationRecord *findParametrization(const GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  const faceRecord *f = findFaceRecord(gf);
  if(!f || !f->parametrization) return nullptr;
  // a face created where a deleted one was, with a parametrization read
  // from a file, is not the one recorded
  const parametrizationRecord &r = *f->parametrization;
  if(r.nodes != gf->stl_vertices_uv.size() ||
     r.triangles != gf->stl_triangles.size() / 3)
    return nullptr;
  return &r;
}

faceReport *findFaceReport(const GFace *gf)
{
  for(faceReport &r : pendingFaceReports())
    if(sameMesh(r, gf)) return &r;
  return nullptr;
}

faceReport *findFaceReportOfFace(const GFace *gf)
{
  for(faceReport &r : pendingFaceReports())
    if(r.face == gf) return &r;
  return nullptr;
}

void recordOptimization(const GFace *gf, const optimizationRecord &record)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecordOf(gf).optimization = record;
}

const optimizationRecord *findOptimization(const GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  const faceRecord *found = findFaceRecord(gf);
  if(!found || !found->optimization) return nullptr;
  // kept until the face is meshed again: the mesh it left must be there
  GFace *f = const_cast<GFace *>(gf);
  const optimizationRecord &r = *found->optimization;
  if(!r.elements || f->getNumMeshElements() != r.elements ||
     f->getMeshElement(0) != r.firstElement)
    return nullptr;
  return &r;
}

bool takeOptimizationCount(const GFace *gf, std::size_t &inverted)
{
  const optimizationRecord *found = findOptimization(gf);
  std::unique_lock<std::mutex> lock = lockRecords();
  if(!found || found->countTaken || !gf->quadrangles.empty()) return false;
  optimizationRecord &r = *faceRecordOf(gf).optimization;
  r.countTaken = true;
  inverted = r.reversed ? r.elements - r.againstAfter : r.againstAfter;
  return true;
}

void forgetOptimization(const GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  if(faceRecord *r = findFaceRecord(gf)) r->optimization.reset();
}

} // namespace reparam

using namespace reparam;

void reparamReportMeshedFace(GFace *gf, double seconds)
{
  if(!getReparamOptions().report) return;
  faceReport r;
  const optimizationRecord *optimization = findOptimization(gf);
  if(optimization) r.optimization = *optimization;
  r.tag = gf->tag();
  const parametrizationRecord *p = findParametrization(gf);
  if(p) {
    r.reparametrized = true;
    r.parametrization = *p;
  }
  else {
    r.parametrization.nodes = gf->stl_vertices_uv.size();
    r.parametrization.triangles = gf->stl_triangles.size() / 3;
  }
  r.meshTime = seconds;
  r.quality = computeFaceQuality({gf});
  r.poorTriangles = countPoorTriangleCauses(gf);
  r.face = gf;
  r.elements = gf->getNumMeshElements();
  r.firstElement = r.elements ? gf->getMeshElement(0) : nullptr;
  if(!gf->stl_triangles.empty() && r.elements) {
    // Kept for the distances, measured for all faces at once after meshing;
    // a compound hands its elements back to its parts before that. The
    // orientation vote needs the inverted elements now
    // (Geo/report/reparamOrient.cpp): the optimizer counted them, else searched
    r.hasInput = true;
    for(const SPoint3 &x : gf->stl_vertices_xyz) r.inputBox += x;
    r.input = inputTriangulationOf(gf);
    r.output = surfaceMeshOf(gf);
    r.fidelity.elements = r.output.numElements();
    r.fidelity.diagonal = r.inputBox.diag();
    if(optimization && gf->quadrangles.empty())
      r.fidelity.inverted =
        optimization->reversed ?
          gf->triangles.size() - optimization->againstAfter :
          optimization->againstAfter;
    else
      r.fidelity.inverted = countInverted(r.input, r.output);
  }
  // a face meshed twice before the report: keep the last mesh; faces may be
  // meshed in parallel (OpenMP builds)
  std::unique_lock<std::mutex> lock = lockReports();
  std::vector<faceReport> &reports = pendingFaceReports();
  reports.erase(
    std::remove_if(reports.begin(), reports.end(),
                   [gf](const faceReport &x) { return x.face == gf; }),
    reports.end());
  reports.push_back(r);
}

namespace reparam {

std::vector<int> unparametrizedFaces(GModel *m)
{
  // A discrete face whose CreateGeometry failed has lost its triangles and
  // has no (u, v): the planar mesher skips it, leaving a hole in the mesh
  std::vector<int> tags;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    if(gf->geomType() == GEntity::DiscreteSurface && gf->compound.empty() &&
       gf->stl_triangles.empty() && !gf->getNumMeshElements())
      tags.push_back(gf->tag());
  }
  return tags;
}

namespace {

  // The distances of the faces' meshes to their inputs, each face's
  // samples against all the faces' inputs and meshes taken together (one
  // search), set in each report; the whole model's (null with one face:
  // its own)
  std::unique_ptr<meshFidelity>
  measureDistances(std::vector<faceReport> &reports)
  {
    std::vector<surfaceMesh> inputs, outputs;
    std::vector<faceReport *> measured;
    for(faceReport &r : reports) {
      if(!r.hasInput) continue;
      inputs.push_back(r.input);
      outputs.push_back(r.output);
      measured.push_back(&r);
    }
    if(measured.empty()) return nullptr;
    std::vector<meshFidelity> perFace;
    meshFidelity whole = compareDistancesToInput(inputs, outputs, &perFace);
    for(std::size_t i = 0; i < measured.size(); i++) {
      meshFidelity &f = measured[i]->fidelity;
      f.hausdorff = perFace[i].hausdorff;
      f.meanDistance = perFace[i].meanDistance;
      f.farthest = perFace[i].farthest;
      f.farthestOnInput = perFace[i].farthestOnInput;
    }
    if(measured.size() < 2) return nullptr;
    return std::unique_ptr<meshFidelity>(new meshFidelity(whole));
  }

  // The faces whose input is narrower (twice its area over its boundary's
  // length) than a quarter of the mesh size asked at its middle: no inner
  // node fits, their triangles are as thin as the face (the kappa of a
  // triangle across a strip of a quarter of its edge is 0.53 at best)
  std::set<int> narrowFaces(GModel *m, const std::vector<faceReport> &reports)
  {
    std::set<int> narrow;
    for(const faceReport &r : reports) {
      GFace *gf = m->getFaceByTag(r.tag);
      if(!gf || !r.hasInput || r.input.points.empty()) continue;
      const SPoint3 middle = r.inputBox.center();
      const double size = reparamUngradedMeshSize(gf, middle);
      if(triangulationWidth(r.input) < 0.25 * size) narrow.insert(r.tag);
    }
    return narrow;
  }

} // namespace

} // namespace reparam

void reparamReportMeshedModel(GModel *m)
{
  std::vector<faceReport> &reports = pendingFaceReports();
  if(!getReparamOptions().report) {
    reports.clear(); // measured before the report was turned off
    return;
  }
  const std::vector<int> missing = unparametrizedFaces(m);
  const std::vector<int> kept = facesKeptAsInput(m);
  if(reports.empty() && missing.empty() && kept.empty()) return;
  if(!kept.empty()) {
    std::string list;
    for(int tag : kept)
      list += (list.empty() ? "" : ", ") + std::to_string(tag);
    Msg::Info("Reparam: %lu surface%s meshed with their input triangles: %s",
              kept.size(), kept.size() > 1 ? "s" : "", list.c_str());
  }
  if(!missing.empty()) {
    std::string list;
    for(int tag : missing)
      list += (list.empty() ? "" : ", ") + std::to_string(tag);
    Msg::Warning("Reparam: %lu discrete surface%s without a parametrization "
                 "left unmeshed (a hole in the mesh): %s",
                 missing.size(), missing.size() > 1 ? "s" : "", list.c_str());
  }
  double t0 = TimeOfDay();
  for(faceReport &r : reports) {
    if(!r.hasInput || r.oriented) continue;
    // Oriented by Gmsh (its own map, or a compound's elements handed back to
    // its parts): count against the final orientation when the mesh is
    // still there, else assume Gmsh chose the majority
    GFace *gf = m->getFaceByTag(r.tag);
    if(gf && sameMesh(r, gf))
      r.fidelity.inverted =
        countInverted(inputTriangulationOf(gf), surfaceMeshOf(gf));
    else
      r.fidelity.inverted = std::min(r.fidelity.inverted,
                                     r.fidelity.elements - r.fidelity.inverted);
    r.oriented = true;
  }
  std::unique_ptr<meshFidelity> whole = measureDistances(reports);
  if(!reports.empty())
    for(const std::string &line : reportTable(reports, whole.get()))
      Msg::Info("Reparam: %s", line.c_str());
  const std::string poor = poorTrianglesLine(reports);
  if(!poor.empty()) Msg::Info("Reparam: %s", poor.c_str());
  const std::set<int> narrow = narrowFaces(m, reports);
  const std::string narrowLine = narrowFacesLine(reports, narrow);
  if(!narrowLine.empty()) Msg::Info("Reparam: %s", narrowLine.c_str());
  const std::string optimization = optimizationLine(reports);
  if(!optimization.empty()) Msg::Info("Reparam: %s", optimization.c_str());
  const std::string farthest = farthestPointLine(reports, whole.get());
  if(!farthest.empty()) Msg::Info("Reparam: %s", farthest.c_str());
  const std::string &file = getReparamOptions().reportFile;
  if(!file.empty()) {
    FILE *fp = Fopen(file.c_str(), "w");
    if(!fp)
      Msg::Error("Cannot write Mesh.CompoundReportFile '%s': %s", file.c_str(),
                 std::strerror(errno));
    else {
      std::string json =
        reportJson(reports, missing, whole.get(), kept, narrow);
      fwrite(json.data(), 1, json.size(), fp);
      fclose(fp);
      Msg::Info("Reparam: report written to '%s'", file.c_str());
    }
  }
  Msg::Debug("Reparam: report in %g s", TimeOfDay() - t0);
  reports.clear();
}

