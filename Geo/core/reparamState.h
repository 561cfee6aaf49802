// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The one owner of what Reparam keeps between Gmsh's calls: a record per
// face (Geo/core/reparamFaceRecord.h), a record per model, the record of
// the last patch layout, the face reports waiting for the model's report,
// and each thread's context of the face it meshes. Records are made on
// first use and start anew at these points of the pipeline (the hooks of
// Geo/reparamHooks.h):
// - the layout's start (reparamLayoutPatches): the last layout's record
//   and the model's record;
// - the start of a face's CreateGeometry (reparamBeginFaceGeometry): the
//   face's record;
// - the end of the model's report (reparamReportMeshedModel): the face
//   reports go.
// A record made of a face's mesh also keeps that mesh's identity
// (meshIdentity): Gmsh changes meshes without a hook.
//
// Threads. Gmsh's main thread runs every hook but those of a face's planar
// mesh, which OpenMP runs on several threads at once with General.NumThreads
// > 1, each thread for its own face (Geo/planar/reparamFaceMeshing.cpp:
// Reparam keeps them on one thread for quadrangles, the anisotropic metric
// and BAMG); the layout verifies its parts on several threads.
// - Face and model records: made, found and reset under lockRecords();
//   CreateGeometry (main thread) writes what a face's geometry makes, the
//   thread meshing a face what its meshes make, and any thread may read
//   them. A record stays in place while others are made: what was found
//   under the lock may be used after it, until the record starts anew.
// - The layout record: the main thread (the layout's own threads touch its
//   map cache, which locks itself, and its atomic count).
// - Face reports: under lockReports() (a face reports from its thread).
// - faceMeshingContext: its thread's own.
// - savedOptions: global, as Gmsh's options are; set only while the faces
//   are meshed on one thread.

#ifndef REPARAM_STATE_H
#define REPARAM_STATE_H

#include <array>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <shared_mutex>
#include <utility>
#include <vector>
#include "edgeByCoordinates.h"
#include "gradedBoundarySize.h"
#include "mapCache.h"
#include "reparamFaceRecord.h"

class GEdge;
class GFace;
class GModel;
class MVertex;

namespace reparam {

struct faceReport; // Geo/report/reparamReport.h

// A node of the input taken as a corner by a curve's mesh
// (Geo/curves/reparamCurveMesh.cpp): which curve, of which model
struct cornerOwner {
  const GModel *model = nullptr;
  int tag = 0;
  const GEdge *curve = nullptr;
};
typedef std::array<double, 3> pointByCoordinates;

// The options only the patch layout reads (Mesh.CompoundLayout, Split,
// NoiseSize, FeatureScale)
struct layoutOptionsRecord {
  bool layout = true, split = false;
  double noiseSize = 0., featureScale = 0.;
};

// What the last patch layout (Geo/layout) hands to the later stages
struct layoutRecord {
  // The options it ran with (none before a layout), and whether a change
  // of them since was named (Geo/parametrize/reparamParametrizeAgain.h)
  std::optional<layoutOptionsRecord> options;
  bool optionsChangeNamed = false;
  // The nodes where three cut edges or more meet (reparamBreakCurveAt),
  // until the faces get their geometry
  std::set<const MVertex *> junctions;
  // The maps it verified its parts with, for CreateGeometry
  mapCache maps;
  // Its cuts across smooth parts, the input edges no mesh may cross, and
  // the sharp edges it merged away with noise (edges by coordinates)
  std::set<edgeByCoordinates> smoothCuts, fixedEdges, mergedCreases;
  double noiseSize = 0.; // the size it measured noise with
  // The input nodes the curves' meshes took as corners
  std::map<pointByCoordinates, cornerOwner> takenCorners;
  // Its parts refused before their map (counted on its threads)
  std::atomic<std::size_t> refusedBeforeTheMap{0};
};

// The sizes along a model's discrete curves while they are meshed
// (Geo/sizes/reparamSizeGrading.cpp): graded from the sources; the curves
// along narrow strips, and those with a fold beside them, which keep the
// sizes without the strips'
struct curveSizeGrading {
  std::unique_ptr<gradedBoundarySize> size, withoutStrips;
  std::set<const GEdge *> alongStrips, folded;
};

// What Reparam keeps of one GModel
struct modelRecord {
  // The crease curves CreateGeometry embedded in its faces
  // (Geo/layout/reparamCreaseCurves.cpp), and those taken out for their size
  std::set<const GEdge *> creaseCurves;
  std::set<GEdge *> smallCreases;
  // Between reparamBegin/EndCurveSizeGrading (null size: not graded)
  curveSizeGrading curveSizes;
  // Curves refused for their size, with their meshing method, restored
  // after Mesh1D; the surfaces on them, restored after Mesh2D
  std::vector<std::pair<GEdge *, int> > refusedCurves;
  std::vector<std::pair<GFace *, int> > refusedSurfaces;
};

// Held while face or model records are made, found or reset, and while
// their fields are read or written where another thread may touch them
std::unique_lock<std::mutex> lockRecords();
// gf's record, made on first use; or null if there is none
faceRecord &faceRecordOf(const GFace *gf);
faceRecord *findFaceRecord(const GFace *gf);
// m's record, made on first use; or null if there is none
modelRecord &modelRecordOf(const GModel *m);
modelRecord *findModelRecord(const GModel *m);
// The last layout's record (an empty one before any layout)
layoutRecord &lastLayout();

// The layout of m starts: a new layout record, a new record for m
void beginLayoutRecords(const GModel *m);
// gf's geometry starts: its record goes (the records of its earlier
// geometry and meshes)
void beginFaceRecord(const GFace *gf);

// The face reports gathered since the last model report, in the order the
// faces were meshed (Geo/report/reparamReport.cpp), and their lock
std::vector<faceReport> &pendingFaceReports();
std::unique_lock<std::mutex> lockReports();

// Held while a face's curvature field is found or built (seconds: not
// under lockRecords)
std::unique_lock<std::mutex> lockCurvatureFields();

// The face whose sizes are graded from its boundary
// (Geo/sizes/reparamSizeGrading.h), its own setting of
// Mesh.MeshSizeExtendFromBoundary (restored after) and the graded sizes
struct faceSizeGrading {
  GFace *face = nullptr;
  int meshSizeFromBoundary = -1;
  std::unique_ptr<gradedBoundarySize> size;
};

// What a thread does for the face it meshes (Geo/planar, Geo/sizes)
struct faceMeshingContext {
  // reparamBeginFaceMeshing calls not yet ended on this thread (a face may
  // be meshed again inside another's meshing): it reads the curves'
  // meshes meanwhile (curvesLock, shared)
  int meshing = 0;
  bool splittingCurves = false; // it holds curvesLock alone
  faceSizeGrading grading;
  bool ungradedSize = false; // a size without the grading is asked for
  // The face is meshed again by another mesher
  // (Geo/planar/reparamMesherFallback.h)
  bool tryingOtherMesher = false;
};
faceMeshingContext &thisThreadsFaceMeshing();

// The lock of the curves' meshes: shared while faces are meshed, alone
// while Gmsh splits curve segments (Geo/planar/reparamFaceMeshing.cpp)
std::shared_mutex &curvesLock();

// Gmsh's options Reparam changes while a face is meshed, with their user
// values (-1: not changed)
struct savedOptions {
  int crossFieldClosestPoint = -1; // Mesh.CrossFieldClosestPoint
  double smoothRatio = -1.; // Mesh.SmoothRatio
};
savedOptions &savedGmshOptions();

} // namespace reparam

#endif
