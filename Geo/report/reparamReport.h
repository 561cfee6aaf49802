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
#include <set>
#include <string>
#include <vector>
#include "SBoundingBox3d.h"
#include "SPoint2.h"
#include "faceQuality.h"
#include "meshFidelity.h"
#include "reparamFaceRecord.h"
#include "reparamPoorTriangles.h"

class GFace;
class GModel;
class MElement;

namespace reparam {

// Records gf's parametrization (in its face record,
// Geo/core/reparamState.h); forgets an earlier one when record is null
// (Gmsh's own map, or none).
void recordParametrization(const GFace *gf, const parametrizationRecord *record);

// The record of gf's current parametrization, or null
const parametrizationRecord *findParametrization(const GFace *gf);

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

// The report's line on the faces narrower than a quarter of the size asked
// (tags in `narrow`): their triangles' kappa mean and the others', the
// input's feature that bounds the mean (empty without such faces or
// without others): "kappa mean 0.916: 0.654 on the 60 surfaces narrower
// than ... (12, 15, ...; 1787 triangles), 0.932 on the others"
std::string narrowFacesLine(const std::vector<faceReport> &reports,
                            const std::set<int> &narrow);

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
// `narrow`: the faces narrower than a quarter of the size asked
// (narrowFacesLine), listed as narrowSurfaces
std::string reportJson(const std::vector<faceReport> &reports,
                       const std::vector<int> &unmeshed = {},
                       const meshFidelity *whole = nullptr,
                       const std::vector<int> &keptAsInput = {},
                       const std::set<int> &narrow = {});

} // namespace reparam

#endif
