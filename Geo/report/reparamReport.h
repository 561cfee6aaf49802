// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The report after meshing (Mesh.CompoundReport, Mesh.CompoundReportFile):
// what each stage did to each compound or discrete face, gathered as the
// stages run (parametrization at CreateGeometry, planar mesh, orientation)
// and printed once the model is meshed and oriented, when the inverted
// elements are final.

#ifndef REPARAM_REPORT_H
#define REPARAM_REPORT_H

#include <cstdio>
#include <string>
#include <vector>
#include "SBoundingBox3d.h"
#include "SPoint2.h"
#include "faceQuality.h"
#include "meshFidelity.h"
#include "reparamPoorTriangles.h"

class GFace;
class GModel;
class MElement;

namespace reparam {

// What reparamComputeParametrization did
struct parametrizationRecord {
  std::vector<int> mapsTried; // Mesh.CompoundParametrization values, in turn
  int map = -1; // the one kept
  bool bijective = false;
  std::size_t nodes = 0, triangles = 0, holes = 0, filledHoles = 0;
  double patchTime = 0., fillTime = 0., assembleTime = 0., solveTime = 0.,
         checkTime = 0.;
  double fallbackTime = 0.; // the maps tried before the one kept
  // the map the patch layout computed for the same part, taken as it is
  // (its times are the layout's)
  bool fromLayout = false;
};

// Records the parametrization written into `uv` (the stl_vertices_uv of the
// face being created: Gmsh's hook gets the arrays, not the face); forgets
// any earlier record for `uv` when record is null (Gmsh's own map).
void recordParametrization(const std::vector<SPoint2> &uv,
                           const parametrizationRecord *record);

// The record of gf's current parametrization, or null
const parametrizationRecord *findParametrization(const GFace *gf);
// The record of the parametrization written into `uv`, or null
const parametrizationRecord *
findParametrization(const std::vector<SPoint2> &uv);

// What Mesh.CompoundOptimize did to a face's new mesh
struct optimizationRecord {
  bool done = false;
  double kappaMinBefore = 1., seconds = 0.;
  std::size_t inserted = 0, splits = 0, collapses = 0, flips = 0, moves = 0;
  std::size_t againstBefore = 0, againstAfter = 0;
  bool reversed = false; // the mesh turns against the input (most of it)
  // made by the optimization of the faces a patch was cut into, together
  // (Geo/optimize/reparamOptimizeAcrossCuts.h)
  bool acrossCuts = false;
  int group = 0; // then: the tag of the first face of that group
  bool countTaken = false; // by takeOptimizationCount
  // the mesh it left, to tell whether it is still gf's
  std::size_t elements = 0;
  const MElement *firstElement = nullptr;
};

// Records the optimization of gf's new mesh, for its report and benches
void recordOptimization(const GFace *gf, const optimizationRecord &record);
// The record of the optimization of gf's current mesh, or null
const optimizationRecord *findOptimization(const GFace *gf);
// The record's count of gf's elements against the input, the first time it
// is asked for the current mesh (the orientation vote, Geo/report/reparamOrient.h;
// a later call, after elements were edited in place, must count again)
bool takeOptimizationCount(const GFace *gf, std::size_t &inverted);
// Forgets it: gf's mesh was changed since (same element count or not)
void forgetOptimization(const GFace *gf);

// One line of the report
struct faceReport {
  int tag = 0;
  bool reparametrized = false; // by Reparam (else Gmsh's own map)
  parametrizationRecord parametrization;
  double meshTime = 0.; // planar mesher and optimization
  optimizationRecord optimization;
  faceQuality quality;
  // triangles below kappa 0.3 by cause (Mesh/quality/poorTriangleCause.h)
  poorTriangleCounts poorTriangles{};
  bool hasInput = false; // fidelity measured against an input triangulation
  // inverted: against the final orientation; the distances are measured
  // for all faces at once by reparamReportMeshedModel
  meshFidelity fidelity;
  // the face's input and new mesh, as meshed (a compound's hands its
  // elements back to its parts), for the distances
  surfaceMesh input, output;
  SBoundingBox3d inputBox; // to relate the distances of several faces
  bool oriented = false; // fidelity.inverted is after orientation
  // to tell whether the mesh measured is still the face's mesh
  const GFace *face = nullptr;
  const MElement *firstElement = nullptr;
  std::size_t elements = 0;
};

// The reports gathered since the last reparamReportMeshedModel
std::vector<faceReport> &pendingFaceReports();

// The pending report of gf if its mesh is still the one measured, else null
faceReport *findFaceReport(const GFace *gf);
// The pending report of gf, whatever mesh it was made of (null if none)
faceReport *findFaceReportOfFace(const GFace *gf);

// The discrete faces of m without a parametrization nor a mesh (their
// CreateGeometry failed): holes in the mesh, named by the report
std::vector<int> unparametrizedFaces(GModel *m);

// The report's line on the causes of the triangles below kappa 0.3 (empty
// without any): "12 triangles below kappa 0.3: 8 where curves meet at a
// sharp angle, ..."
std::string poorTrianglesLine(const std::vector<faceReport> &reports);

// The report's line on Mesh.CompoundOptimize (empty if it did nothing):
// "optimization on the input: kappa min A -> B, ..."
std::string optimizationLine(const std::vector<faceReport> &reports);

// The table lines and the JSON text of `reports` (for the hook and tests);
// the JSON lists `unmeshed` faces and the faces meshed with their input
// triangles (`keptAsInput`) too. The total's distances are `whole`'s
// when given (the faces' meshes against their inputs taken together), else
// the largest and the element-weighted mean of the faces'.
std::vector<std::string> reportTable(const std::vector<faceReport> &reports,
                                     const meshFidelity *whole = nullptr);
// Where the total's Hausdorff distance is reached, for the log: "largest
// distance to the input D (P % of the diagonal) at (x, y, z): an input point
// far from the mesh" (or "a mesh point far from the input"); empty without
// an input
std::string farthestPointLine(const std::vector<faceReport> &reports,
                              const meshFidelity *whole = nullptr);
std::string reportJson(const std::vector<faceReport> &reports,
                       const std::vector<int> &unmeshed = {},
                       const meshFidelity *whole = nullptr,
                       const std::vector<int> &keptAsInput = {});

} // namespace reparam

#endif
