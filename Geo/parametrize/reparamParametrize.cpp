// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The hooks through which Gmsh asks for a parametrization (patches/0001):
// Gmsh's triangles become a patch (reparamTrianglePatch.h), the stage's entry
// parametrize() (Mesh/maps/parametrize.h) maps it, and the result is logged
// as the caller needs and handed back in Gmsh's arrays. Used by discrete
// faces' CreateGeometry, by Compound Surface meshing, by the patch checks of
// ClassifySurfaces and by the patch layout's verification of its parts.

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>
#include "Context.h"
#include "GEntity.h"
#include "GFace.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "OS.h"
#include "parametrize.h"
#include "planeProjection.h"
#include "reparamConePoints.h"
#include "reparamCreaseCurves.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamLayout.h"
#include "reparamOptions.h"
#include "reparamParametrize.h"
#include "reparamParametrizeAgain.h"
#include "reparamReport.h"
#include "reparamState.h"
#include "reparamTrianglePatch.h"

namespace reparam {

namespace {

  // Who asks for the map decides what the log says of it
  enum class mapCaller {
    gmsh, // Gmsh's own code (its split test): a failure is an error
    face, // a discrete face's CreateGeometry: a failure is an Info, the
          // safety net warns (Geo/parametrize/reparamInputMesh.h)
    patchCheck, // ClassifySurfaces' test of a patch: a failure splits it
    layout, // the patch layout tries a part: no log (it tries hundreds),
            // the reason kept for its own message, the map kept for
            // CreateGeometry
  };

  struct mapRequest {
    mapCaller caller = mapCaller::gmsh;
    GFace *face = nullptr; // with mapCaller::face
    // why the map failed: the layout's reason, the safety net's warning
    std::string failure;
    // for the layout: where the maps not kept fail
    mapFailurePlace failed;
    bool quiet() const { return caller == mapCaller::layout; }
  };

  std::string formatted(const char *format, va_list args)
  {
    char message[1024];
    vsnprintf(message, sizeof(message), format, args);
    return message;
  }

  void failure(mapRequest &r, const char *format, ...)
  {
    va_list args;
    va_start(args, format);
    r.failure = formatted(format, args);
    va_end(args);
    if(r.quiet()) return;
    if(r.caller == mapCaller::gmsh)
      Msg::Error("%s", r.failure.c_str());
    else
      Msg::Info("Reparam: %s", r.failure.c_str());
  }

  // "surface 12" from the nodes' classification (the hook only gets the
  // triangles), else "triangulation (N triangles)"
  std::string surfaceName(const std::vector<MVertex *> &nodes,
                          std::size_t numTriangles)
  {
    for(MVertex *v : nodes) {
      GEntity *ge = v->onWhat();
      if(ge && ge->dim() == 2) return "surface " + std::to_string(ge->tag());
    }
    return "triangulation (" + std::to_string(numTriangles) + " triangles)";
  }

  void logAttempt(const std::string &surface, const mapAttempt &a)
  {
    const char *name = compoundParametrizationName(a.map);
    if(!a.error.ok()) {
      Msg::Info("Reparam: %s: %s map failed (%s), %.3g s", surface.c_str(),
                name, a.error.what().c_str(), a.mapTime);
      return;
    }
    std::string repair;
    if(a.repairTried)
      repair = ", repair moved " + std::to_string(a.repair.movedNodes) +
               " nodes in " + std::to_string(a.repair.passes) + " passes";
    Msg::Info("Reparam: %s: %s map: %lu flipped, %lu folds, %lu degenerate%s "
              "-> %s (%lu flipped, %lu folds), map %.3g s, checks %.3g s",
              surface.c_str(), name, a.flipped, a.folds, a.degenerate,
              repair.c_str(), a.bijective() ? "one-to-one" : "not one-to-one",
              a.flippedAfter, a.foldsAfter, a.mapTime, a.checkTime);
  }

  // The patch's failure, with Gmsh's tag and place of the node at fault
  void invalidPatch(mapRequest &r, const trianglePatch &p)
  {
    std::string where;
    MVertex *v = p.error.node >= 0 ? nodeOfPatch(p, p.error.node) : nullptr;
    if(v) {
      char s[128];
      snprintf(s, sizeof(s), " at node %lu (%g, %g, %g)", v->getNum(), v->x(),
               v->y(), v->z());
      where = s;
    }
    failure(r, "Cannot parametrize triangulation (%lu triangles)%s: %s",
            p.triangles.size(), where.c_str(), p.error.what().c_str());
    r.failure = p.error.what(); // the layout names the part itself
  }

  // The warnings of the hole filling (before the maps' lines)
  void logHoles(const parametrization &m, std::size_t numTriangles)
  {
    if(m.skippedHoles)
      Msg::Warning("Triangulation (%lu triangles): %d of its %lu holes cannot "
                   "be filled, left as free boundaries",
                   numTriangles, m.skippedHoles, m.holes);
    if(!m.fillError.ok())
      Msg::Warning("Triangulation (%lu triangles): filling its holes gives "
                   "an invalid patch (%s), holes left as free boundaries",
                   numTriangles, m.fillError.what().c_str());
  }

  // The maps' lines, then what the result means for the planar mesher;
  // false if it may not be meshed
  bool logMaps(mapRequest &r, const parametrization &m, int choice,
               const std::string &surface)
  {
    const std::vector<mapAttempt> &attempts = m.result.attempts;
    const std::size_t tried = m.usedFallback ?
                                attempts.size() - m.fallbackAttempts.size() :
                                attempts.size();
    if(!r.quiet()) {
      for(std::size_t i = 0; i < tried; i++) logAttempt(surface, attempts[i]);
      for(const mapAttempt &a : m.fallbackAttempts) logAttempt(surface, a);
    }
    if(m.outcome == parametrizeOutcome::notImplemented) {
      failure(r, "Mesh.CompoundParametrization = %d (%s) is not implemented: "
              "use 0 to 6", choice, compoundParametrizationName(choice));
      return false;
    }
    if(m.outcome == parametrizeOutcome::mapFailed) {
      failure(r, "%s map of %s failed: %s", compoundParametrizationName(choice),
              surface.c_str(), m.result.map.error.what().c_str());
      return false;
    }
    if(m.outcome == parametrizeOutcome::noBijectiveMap) {
      failure(r, "No one-to-one parametrization of %s: every map of the "
              "automatic chain flips or folds", surface.c_str());
      return false;
    }
    if(r.quiet()) return true;
    const mapAttempt &chosen = m.chosen();
    if(m.usedFallback) {
      const mapAttempt &failed = attempts[m.failedChoice];
      Msg::Warning("%s map of %s is not one-to-one (%lu flipped triangles, "
                   "%lu folds): using the mean value map instead",
                   compoundParametrizationName(choice), surface.c_str(),
                   failed.flippedAfter, failed.foldsAfter);
    }
    if(!m.result.bijective)
      Msg::Warning(
        "%s map of %s is not one-to-one (%lu flipped triangles, %lu "
        "folds): the mesh may be invalid; Mesh.CompoundParametrization "
        "= 6 tries the maps in turn",
        compoundParametrizationName(choice), surface.c_str(),
        chosen.flippedAfter, chosen.foldsAfter);
    // a plane projection's degenerate images are the input's own slivers,
    // which Gmsh's planar face meshes over
    else if(chosen.degenerateAfter &&
            chosen.map != (int)compoundParametrization::plane)
      Msg::Warning("%s map of %s: %lu triangles have a numerically degenerate "
                   "image",
                   compoundParametrizationName(chosen.map), surface.c_str(),
                   chosen.degenerateAfter);
    return true;
  }

  // What the report and the later stages know of the parametrization
  parametrizationRecord recordOf(const trianglePatch &p,
                                 const parametrization &m, double patchTime)
  {
    parametrizationRecord record;
    double checkTime = 0.;
    for(std::size_t i = 0; i < m.result.attempts.size(); i++) {
      const mapAttempt &a = m.result.attempts[i];
      checkTime += a.checkTime;
      record.mapsTried.push_back(a.map);
      if((int)i != m.result.chosen) record.fallbackTime += a.mapTime;
    }
    record.map = m.chosen().map;
    record.bijective = m.result.bijective;
    record.nodes = p.points.size();
    record.triangles = p.triangles.size();
    record.holes = m.holes;
    record.filledHoles = m.filledHoles;
    record.patchTime = patchTime;
    record.fillTime = m.fillTime;
    record.assembleTime = m.result.map.assembleTime;
    record.solveTime = m.result.map.solveTime;
    record.checkTime = checkTime;
    record.fromLayout = m.fromCache;
    return record;
  }

  void logDone(const parametrizationRecord &record, std::size_t loops)
  {
    Msg::Info("Reparam: %s map of %lu nodes, %lu triangles, %lu hole%s "
              "(%d filled): patch %.3g s, fill %.3g s, assemble %.3g s, solve "
              "%.3g s, checks %.3g s%s",
              compoundParametrizationName(record.map), record.nodes,
              record.triangles, loops - 1, loops == 2 ? "" : "s",
              (int)record.filledHoles, record.patchTime, record.fillTime,
              record.assembleTime, record.solveTime, record.checkTime,
              record.fromLayout ? " (computed by the layout)" : "");
  }

  // Where the maps not kept fail, on Gmsh's nodes (not those the hole
  // filling adds)
  mapFailurePlace failurePlace(const trianglePatch &p, const parametrization &m)
  {
    mapFailurePlace place;
    const auto &attempts = m.result.attempts;
    bool failed = false;
    for(std::size_t a = 0; a < attempts.size(); a++)
      failed |=
        (int)a != m.result.chosen &&
        !(attempts[a].failedNodes.empty() && attempts[a].foldPairs.empty());
    if(!failed) return place; // (most parts: no index to build)
    std::vector<int> nodeOf(p.canonical.size(), -1);
    for(std::size_t i = 0; i < p.canonical.size(); i++)
      if(p.canonical[i] >= 0 && p.canonical[i] < (int)nodeOf.size())
        nodeOf[p.canonical[i]] = (int)i;
    auto gmshNode = [&](int n) -> MVertex * {
      return n >= 0 && n < (int)nodeOf.size() && nodeOf[n] >= 0 ?
               p.nodes[nodeOf[n]] :
               nullptr;
    };
    for(std::size_t a = 0; a < attempts.size(); a++) {
      if((int)a == m.result.chosen) continue;
      for(int n : attempts[a].failedNodes)
        if(MVertex *v = gmshNode(n)) place.through.push_back(v);
      for(const auto &pr : attempts[a].foldPairs) {
        MVertex *u = gmshNode(pr[0]), *v = gmshNode(pr[1]);
        if(u && v) place.apart.push_back({{u, v}});
      }
    }
    std::sort(place.through.begin(), place.through.end());
    place.through.erase(std::unique(place.through.begin(), place.through.end()),
                        place.through.end());
    return place;
  }

  // Gmsh's arrays: the nodes in order of first appearance, their (u, v)
  void writeOutputs(trianglePatch &p, const parametrization &m,
                    std::vector<MVertex *> &nodes, std::vector<SPoint2> &uv,
                    std::vector<SPoint3> &xyz, std::vector<int> &tri)
  {
    const std::vector<double> &map = m.result.map.uv;
    tri.resize(3 * p.triangles.size());
    for(std::size_t t = 0; t < p.triangles.size(); t++)
      for(int j = 0; j < 3; j++) tri[3 * t + j] = p.triangles[t][j];
    xyz = std::move(p.points);
    nodes = std::move(p.nodes);
    uv.resize(xyz.size());
    for(std::size_t i = 0; i < uv.size(); i++)
      uv[i] = SPoint2(map[2 * p.canonical[i]], map[2 * p.canonical[i] + 1]);
  }

  // The map of patch `p` (of `numTriangles` triangles) as `r` asks for it:
  // 1 done (outputs written, `record` filled), -1 failed (outputs empty; why
  // in r.failure and the log). `result` gets parametrize's result.
  int mapPatch(mapRequest &r, trianglePatch &p, std::size_t numTriangles,
               double patchTime, std::vector<MVertex *> &nodes,
               std::vector<SPoint2> &uv, std::vector<SPoint3> &xyz,
               std::vector<int> &tri, parametrizationRecord &record,
               parametrization &result)
  {
    // Gmsh's callers read the outputs whatever the result (the patch check
    // of ClassifySurfaces indexes the (u, v) by the triangles): they stay
    // empty unless the map succeeds
    if(!p.error.ok()) {
      invalidPatch(r, p);
      return -1;
    }
    if(p.patch.numReorientedTriangles && !r.quiet())
      Msg::Warning("Triangulation (%lu triangles) is not consistently "
                   "oriented: %lu triangles taken reversed for the "
                   "parametrization",
                   numTriangles, p.patch.numReorientedTriangles);
    const reparamOptions &options = getReparamOptions();
    parametrizeOptions o;
    o.map = options.parametrization;
    o.fillHoles = options.fillHoles;
    o.repair = options.repair;
    // what Gmsh's discrete faces take for planar (discreteFace.cpp)
    o.planeTolerance = CTX::instance()->geom.matchMeshTolerance;
    // the maps the layout verified its parts with: CreateGeometry
    // parametrizes the same parts again (a 1.4M-triangle scan: a tenth of
    // its run, bench/README.md)
    o.cache = &lastLayout().maps;
    o.keepInCache = r.caller == mapCaller::layout;
    result = parametrize(p.patch, o);
    if(r.quiet()) r.failed = failurePlace(p, result);
    if(!r.quiet()) logHoles(result, numTriangles);
    const std::string surface = p.nodes.empty() && r.face ?
                                  "surface " + std::to_string(r.face->tag()) :
                                  surfaceName(p.nodes, numTriangles);
    if(!logMaps(r, result, o.map, surface)) return -1;
    record = recordOf(p, result, patchTime);
    writeOutputs(p, result, nodes, uv, xyz, tri);
    if(!r.quiet()) logDone(record, p.patch.boundaryLoops.size());
    return 1;
  }

  // The same of `triangles`, 0 with Gmsh's own map. `built`:
  // patchOfTriangles(triangles) if the caller has it (taken), made in
  // `builtSeconds`.
  int mapTriangles(mapRequest &r, const std::vector<MTriangle *> &triangles,
                   std::vector<MVertex *> &nodes, std::vector<SPoint2> &uv,
                   std::vector<SPoint3> &xyz, std::vector<int> &tri,
                   parametrizationRecord &record, parametrization &result,
                   trianglePatch *built = nullptr, double builtSeconds = 0.)
  {
    r.failure.clear();
    if(getReparamOptions().parametrization ==
       (int)compoundParametrization::gmsh)
      return 0;
    uv.clear();
    xyz.clear();
    tri.clear();
    nodes.clear();
    if(triangles.empty()) return -1;
    const double t0 = TimeOfDay();
    trianglePatch p = built ? std::move(*built) : patchOfTriangles(triangles);
    return mapPatch(r, p, triangles.size(), builtSeconds + TimeOfDay() - t0,
                    nodes, uv, xyz, tri, record, result);
  }

} // namespace

void reparamForgetLayoutMaps() { lastLayout().maps.clear(); }

int reparamTryParametrization(const std::vector<MTriangle *> &triangles,
                              std::vector<SPoint2> &uv,
                              std::vector<SPoint3> &xyz, std::vector<int> &tri,
                              std::string &why, mapFailurePlace *where,
                              trianglePatch *patch)
{
  std::vector<MVertex *> nodes;
  parametrizationRecord record;
  parametrization result;
  mapRequest r;
  r.caller = mapCaller::layout;
  int done =
    mapTriangles(r, triangles, nodes, uv, xyz, tri, record, result, patch);
  if(done > 0 && !record.bijective) {
    why = "its map is not one-to-one";
    done = -1;
  }
  else if(done > 0 &&
          getReparamOptions().parametrization ==
            (int)compoundParametrization::automatic &&
          record.map == (int)compoundParametrization::meanValue) {
    // both conformal maps fold or flip: the part winds around, and mean
    // value on a circle squeezes it so much that Frontal-Delaunay fails and
    // MeshAdapt takes over; its parts map conformally (bench/README.md,
    // Patch layout)
    why = "its conformal maps fold (it winds around)";
    done = -1;
    if(where) *where = r.failed;
  }
  else if(done > 0 && getReparamOptions().fillHoles &&
          record.map != (int)compoundParametrization::plane &&
          record.filledHoles < record.holes) {
    // a loop that cannot be filled winds around a tube:
    // left free, it leaves a conformal map badly squeezed, and a cut across
    // the tube removes it (bench/README.md, Patch layout)
    why = "a hole of it cannot be filled";
    done = -1;
  }
  else if(done <= 0)
    why = r.failure;
  return done;
}

int reparamMapFaceArrays(GFace *gf, const mapOptionsRecord &orders,
                         std::vector<SPoint2> &uv,
                         parametrizationRecord &record, std::string &why)
{
  mapRequest r;
  r.caller = mapCaller::face;
  r.face = gf;
  const double t0 = TimeOfDay();
  trianglePatch p = patchOfArrays(gf->stl_vertices_xyz, gf->stl_triangles,
                                  orders.canonicalNodes, orders.triangleOrder);
  std::vector<MVertex *> nodes;
  std::vector<SPoint3> xyz;
  std::vector<int> tri;
  parametrization result;
  const int done =
    mapPatch(r, p, gf->stl_triangles.size() / 3, TimeOfDay() - t0, nodes, uv,
             xyz, tri, record, result);
  why = r.failure;
  return done;
}

std::string reparamLastFailure(const GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  const faceRecord *r = findFaceRecord(gf);
  return r ? r->failure : std::string();
}

bool reparamHolesFillable(const std::vector<MTriangle *> &triangles)
{
  return !getReparamOptions().fillHoles ||
         reparamHolesFillable(patchOfTriangles(triangles));
}

bool reparamHolesFillable(const trianglePatch &p)
{
  if(!getReparamOptions().fillHoles) return true;
  // an invalid patch is the maps' failure to tell; a planar one whose
  // projection is one-to-one is meshed on its plane with its holes (tested
  // only with holes: the layout asks of every part before its map)
  const double planar = CTX::instance()->geom.matchMeshTolerance;
  return !p.error.ok() || p.patch.boundaryLoops.size() < 2 ||
         (patchIsPlanar(p.patch, planar) &&
          planeProjection(p.patch, planar).bijective) ||
         holesFillable(p.patch);
}

} // namespace reparam

using namespace reparam;

int reparamComputeFaceParametrization(GFace *gf,
                                      const std::vector<MTriangle *> &triangles,
                                      std::vector<MVertex *> &nodes,
                                      std::vector<SPoint2> &stl_vertices_uv,
                                      std::vector<SPoint3> &stl_vertices_xyz,
                                      std::vector<int> &stl_triangles)
{
  mapRequest r;
  r.caller = mapCaller::face;
  r.face = gf;
  // the curves are made once faces get their geometry: the layout's
  // junctions are of no more use (and their nodes may go)
  reparamForgetJunctions();
  // whatever happens below, an earlier record of gf is stale
  recordParametrization(gf, nullptr);
  parametrizationRecord record;
  parametrization result;
  // the options and orders the map is computed with, for the face's map
  // to be computed again when the options change (reparamParametrizeAgain)
  mapOptionsRecord with = currentMapOptions();
  std::optional<trianglePatch> p;
  double patchTime = 0.;
  if(with.map != (int)compoundParametrization::gmsh && !triangles.empty()) {
    const double t0 = TimeOfDay();
    p = patchOfTriangles(triangles);
    with.canonicalNodes = p->canonical;
    with.triangleOrder = p->triangleOrder;
    patchTime = TimeOfDay() - t0;
  }
  const int done =
    mapTriangles(r, triangles, nodes, stl_vertices_uv, stl_vertices_xyz,
                 stl_triangles, record, result, p ? &*p : nullptr, patchTime);
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    faceRecord &f = faceRecordOf(gf);
    f.failure = r.failure;
    f.mappedWith = std::move(with);
  }
  if(done <= 0) return done;
  recordParametrization(gf, &record);
  // the face's tips become mesh nodes (points embedded in it), and its
  // sharp creases left inside it embedded curves
  reparamEmbedConePoints(gf, nodes, stl_vertices_xyz, stl_triangles);
  reparamEmbedCreaseCurves(gf, nodes, stl_vertices_xyz, stl_triangles);
  return 1;
}

int reparamComputeParametrization(const std::vector<MTriangle *> &triangles,
                                  std::vector<MVertex *> &nodes,
                                  std::vector<SPoint2> &stl_vertices_uv,
                                  std::vector<SPoint3> &stl_vertices_xyz,
                                  std::vector<int> &stl_triangles)
{
  // triangles of no face: no record (a face's own map is recorded by
  // reparamComputeFaceParametrization)
  mapRequest r; // mapCaller::gmsh
  parametrizationRecord record;
  parametrization result;
  return mapTriangles(r, triangles, nodes, stl_vertices_uv, stl_vertices_xyz,
                      stl_triangles, record, result);
}

int reparamCheckParametrizable(const std::vector<MTriangle *> &triangles,
                               std::string &why)
{
  // Mesh.CompoundSplit = 0: Gmsh's own test, on Reparam's map
  const int choice = getReparamOptions().parametrization;
  if(choice == (int)compoundParametrization::gmsh || !getReparamOptions().split)
    return 0;
  std::vector<MVertex *> nodes;
  std::vector<SPoint2> uv;
  std::vector<SPoint3> xyz;
  std::vector<int> tri;
  parametrizationRecord record;
  parametrization result;
  mapRequest r;
  r.caller = mapCaller::patchCheck;
  int done = mapTriangles(r, triangles, nodes, uv, xyz, tri, record, result);
  // The automatic chain ends on mean value when both conformal maps fold or
  // flip: the patch winds around or is too elongated for a free boundary,
  // and mean value on a circle squeezes it so much that the planar mesher
  // may fail. Smaller parts flatten conformally.
  const bool wound = done > 0 &&
                     choice == (int)compoundParametrization::automatic &&
                     record.map == (int)compoundParametrization::meanValue &&
                     record.mapsTried.size() > 1;
  // Gmsh's own test: a (u, v) triangle below 1e-8 (twice its area, the
  // image being about the unit disk) means a patch so stretched that parts
  // of it would be meshed far too coarsely
  double smallest = 1.;
  for(std::size_t i = 0; done > 0 && i + 2 < tri.size(); i += 3) {
    const SPoint2 &a = uv[tri[i]], &b = uv[tri[i + 1]], &c = uv[tri[i + 2]];
    smallest = std::min(smallest, std::fabs((b.x() - a.x()) * (c.y() - a.y()) -
                                            (b.y() - a.y()) * (c.x() - a.x())));
  }
  // A part too small to split further keeps what it has (mean value), or
  // fails when CreateGeometry parametrizes it, with the reason
  if((done > 0 && !wound && smallest >= 1e-8) || triangles.size() < 4) return 1;
  why = done <= 0 ? "Reparam cannot parametrize it" :
        wound     ? "its conformal maps fold (Reparam)" :
                    "parametrized triangles are too small (Reparam)";
  return 2;
}
