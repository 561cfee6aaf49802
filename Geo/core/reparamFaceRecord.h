// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam keeps of one GFace between Gmsh's calls, each part written
// by one stage and read by the later ones; Geo/core/reparamState.h owns the
// records, says when they start anew and which thread touches what.

#ifndef REPARAM_FACE_RECORD_H
#define REPARAM_FACE_RECORD_H

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "SPoint3.h"
#include "curvatureMetric.h"
#include "surfaceMesh.h"

class GEdge;
class MElement;

namespace reparam {

// What reparamComputeFaceParametrization did
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

// The options a face's map was computed with (Mesh.CompoundParametrization,
// FillHoles, Repair) and the order its patch took the nodes and triangles
// of the face's arrays in (Geo/parametrize/reparamTrianglePatch.h; empty
// after Gmsh's own map): the map is computed again before the face is
// meshed when the options changed since
// (Geo/parametrize/reparamParametrizeAgain.h)
struct mapOptionsRecord {
  int map = -1;
  bool fillHoles = true, repair = true;
  std::vector<int> canonicalNodes, triangleOrder;
};

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

// A face's mesh told by its element count and first element: Gmsh changes
// meshes without telling, so a record made of a mesh holds while it is there
struct meshIdentity {
  std::size_t elements = 0;
  const MElement *first = nullptr;
  bool operator==(const meshIdentity &o) const
  {
    return elements == o.elements && first == o.first;
  }
  bool operator!=(const meshIdentity &o) const { return !(*this == o); }
};

// A face's input triangles, kept for its mesh when no map takes it
// (Geo/parametrize/reparamInputMesh.h: Gmsh deletes them when it meshes)
struct inputTriangulation : surfaceMesh {
  std::vector<int> labels; // the curve or corner of each point
  std::size_t leftOut = 0; // triangles with invalid coordinates
};

// A face's curvature field (Geo/sizes/reparamCurvatureMetric.h) and the
// sizes it was built for: built again when they change
struct curvatureFieldRecord {
  double n = 0., hMin = 0., hMax = 0., gradation = 0.;
  std::size_t inputTriangles = 0;
  std::unique_ptr<curvatureMetricField> field;
};

struct faceRecord {
  // CreateGeometry (Geo/parametrize): the map, the options it was computed
  // with, why it failed (for the safety net's warning), the input
  // triangles kept when it failed
  std::optional<parametrizationRecord> parametrization;
  std::optional<mapOptionsRecord> mappedWith;
  // its (u, v) were computed again in its arrays, and its parametric
  // triangles are not yet made of them (reparamTakeNewParametrization)
  bool newParametrization = false;
  std::string failure;
  std::optional<inputTriangulation> keptInput;
  // Its meshes (Geo/planar, Geo/optimize, Geo/quad): what the
  // optimization did, the mesh made of its input after meshing
  // (reparamMeshFaceWithItsInput), the mesh its quadrangles were smoothed
  // to (Geo/quad/reparamSmoothQuads.cpp), whether BAMG failed on it, the
  // curve of a segment the planar mesher could not recover (0: none; reset
  // once the face is meshed, Geo/planar/reparamLostSegments.h), the crease
  // curves taken out while it is recombined
  std::optional<optimizationRecord> optimization;
  std::optional<meshIdentity> meshedWithInput;
  std::optional<meshIdentity> smoothedQuads;
  bool bamgFailed = false;
  int lostSegmentCurve = 0;
  std::vector<GEdge *> hiddenCreases;
  // Its sizes (Geo/sizes)
  curvatureFieldRecord curvature;
};

} // namespace reparam

#endif
