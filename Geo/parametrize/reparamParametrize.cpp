// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The hook Gmsh's computeParametrization() calls first (patches/0001): turns
// Gmsh's triangles into a patch, runs the chosen map and hands (u, v) back in
// Gmsh's layout. Used by discrete faces' CreateGeometry, by Compound Surface
// meshing and by the patch checks of ClassifySurfaces.

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <string>
#include <unordered_map>
#include "GEntity.h"
#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "OS.h"
#include "discretePatch.h"
#include "holeFilling.h"
#include "mapChain.h"
#include "reparamConePoints.h"
#include "reparamCreaseCurves.h"
#include "reparamInputMesh.h"
#include "reparamLayout.h"
#include "reparamOptions.h"
#include "reparamParametrize.h"
#include "reparamReport.h"

namespace reparam {

namespace {

  // Per thread: the patch layout verifies its parts on several threads
  // (General.NumThreads, Mesh/layout/patchLayout.h).
  // Set while ClassifySurfaces asks whether a patch can be parametrized
  // (reparamCheckParametrizable, the patch layout): a failure there splits
  // the patch, it is not an error of the model
  thread_local bool checkingPatch = false;
  // Set while the patch layout tries a part: no log at all (a layout tries
  // hundreds of parts), the reason of a failure kept for its own message
  thread_local bool quiet = false;
  // Set while a discrete face's CreateGeometry parametrizes it: a failure
  // is an Info, the safety net's warning gives it (Geo/parametrize/reparamInputMesh)
  thread_local GFace *creatingFace = nullptr;
  thread_local std::string lastFailure;

  void failure(const char *format, ...)
  {
    char message[1024];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof(message), format, args);
    va_end(args);
    lastFailure = message;
    if(quiet) return;
    if(checkingPatch || creatingFace)
      Msg::Info("Reparam: %s", message);
    else
      Msg::Error("%s", message);
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
    if(quiet) return;
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

  // canonical[i]: the rank of nodes[i] among the nodes sorted by number
  std::vector<int> canonicalNodeOrder(const std::vector<MVertex *> &nodes)
  {
    std::vector<int> order(nodes.size());
    for(std::size_t i = 0; i < nodes.size(); i++) order[i] = (int)i;
    std::sort(order.begin(), order.end(), [&nodes](int a, int b) {
      return nodes[a]->getNum() < nodes[b]->getNum();
    });
    std::vector<int> canonical(nodes.size());
    for(std::size_t k = 0; k < order.size(); k++) canonical[order[k]] = (int)k;
    return canonical;
  }

  std::vector<SPoint3> permutedPoints(const std::vector<SPoint3> &points,
                                      const std::vector<int> &canonical)
  {
    std::vector<SPoint3> p(points.size());
    for(std::size_t i = 0; i < points.size(); i++) p[canonical[i]] = points[i];
    return p;
  }

  // The triangles in the order of their Gmsh numbers, on canonical nodes
  std::vector<std::array<int, 3> >
  canonicalTriangles(const std::vector<MTriangle *> &triangles,
                     const std::vector<std::array<int, 3> > &tris,
                     const std::vector<int> &canonical)
  {
    std::vector<int> order(tris.size());
    for(std::size_t t = 0; t < tris.size(); t++) order[t] = (int)t;
    std::sort(order.begin(), order.end(), [&triangles](int a, int b) {
      return triangles[a]->getNum() < triangles[b]->getNum();
    });
    std::vector<std::array<int, 3> > sorted(tris.size());
    for(std::size_t k = 0; k < order.size(); k++)
      for(int j = 0; j < 3; j++) sorted[k][j] = canonical[tris[order[k]][j]];
    return sorted;
  }

  // The maps the patch layout computed while verifying its parts, for
  // CreateGeometry, which parametrizes the same parts again: the same
  // triangles on the same nodes, canonical, so the same patch to the last
  // bit (a 1.4M-triangle scan: 10.7 of its 93 s were CreateGeometry's maps).
  // Keyed by two hashes of the patch's coordinates and triangles, the map
  // choice and the repair option; an entry is used once
  struct cachedMap {
    std::size_t points = 0, triangles = 0;
    std::uint64_t hash[2] = {0, 0};
    int choice = -1;
    bool repair = false;
    checkedMap result;
  };

  std::vector<cachedMap> &mapCache()
  {
    static std::vector<cachedMap> cache;
    return cache;
  }

  std::mutex &mapCacheMutex()
  {
    static std::mutex m;
    return m;
  }

  // FNV-1a over the patch's bytes, from two offsets
  void hashOf(const discretePatch &patch, std::uint64_t hash[2])
  {
    const std::uint64_t seeds[2] = {1469598103934665603ull,
                                    0x9e3779b97f4a7c15ull};
    for(int k = 0; k < 2; k++) {
      std::uint64_t h = seeds[k];
      auto add = [&h](const void *data, std::size_t bytes) {
        const unsigned char *c = (const unsigned char *)data;
        for(std::size_t i = 0; i < bytes; i++)
          h = (h ^ c[i]) * 1099511628211ull;
      };
      for(const SPoint3 &p : patch.points) add(p.data(), 3 * sizeof(double));
      add(patch.triangles.data(),
          patch.triangles.size() * sizeof(std::array<int, 3>));
      hash[k] = h;
    }
  }

  // runMapChain, or the map the layout computed for the same patch
  checkedMap mapChainOf(const discretePatch &patch, int choice,
                        const std::vector<mapStep> &steps, bool repair,
                        bool &fromLayout)
  {
    fromLayout = false;
    cachedMap key;
    key.points = patch.points.size();
    key.triangles = patch.triangles.size();
    hashOf(patch, key.hash);
    key.choice = choice;
    key.repair = repair;
    {
      std::lock_guard<std::mutex> lock(mapCacheMutex());
      std::vector<cachedMap> &cache = mapCache();
      for(std::size_t i = 0; i < cache.size(); i++) {
        const cachedMap &c = cache[i];
        if(c.points != key.points || c.triangles != key.triangles ||
           c.hash[0] != key.hash[0] || c.hash[1] != key.hash[1] ||
           c.choice != choice || c.repair != repair)
          continue;
        checkedMap found = std::move(cache[i].result);
        cache.erase(cache.begin() + i);
        fromLayout = true;
        return found;
      }
    }
    checkedMap result = runMapChain(patch, steps, repair);
    // only the layout's (quiet) tries: it drops them when it starts again;
    // Gmsh's own split loop (Mesh.CompoundLayout = 0) would pile them up
    if(checkingPatch && quiet) {
      key.result = result;
      std::lock_guard<std::mutex> lock(mapCacheMutex());
      mapCache().push_back(std::move(key));
    }
    return result;
  }

  // The patch of Gmsh's triangles: nodes numbered in order of first
  // appearance, as Gmsh's own code does (nodes, points, tris), then sorted
  // by their Gmsh numbers (canonical) for the maps: the same triangles
  // given in another order (the patch layout verifies a part, CreateGeometry
  // later gets it in the order of Gmsh's flood fill) then get the same (u,
  // v), flips and folds to the last bit
  reparamError patchOfTriangles(const std::vector<MTriangle *> &triangles,
                                std::vector<MVertex *> &nodes,
                                std::vector<SPoint3> &points,
                                std::vector<std::array<int, 3> > &tris,
                                std::vector<int> &canonical,
                                discretePatch &patch)
  {
    std::unordered_map<MVertex *, int> nodeIndex;
    nodeIndex.reserve(triangles.size());
    tris.resize(triangles.size());
    for(std::size_t t = 0; t < triangles.size(); t++) {
      for(int j = 0; j < 3; j++) {
        MVertex *v = triangles[t]->getVertex(j);
        auto it = nodeIndex.insert(std::make_pair(v, (int)nodes.size()));
        if(it.second) {
          nodes.push_back(v);
          points.push_back(v->point());
        }
        tris[t][j] = it.first->second;
      }
    }
    canonical = canonicalNodeOrder(nodes);
    return makeDiscretePatch(permutedPoints(points, canonical),
                             canonicalTriangles(triangles, tris, canonical),
                             patch);
  }

  // The patch and the triangles filling its holes as one patch
  reparamError extendedPatch(const discretePatch &patch,
                             const holeFilling &filling,
                             discretePatch &extended)
  {
    std::vector<std::array<int, 3> > all = patch.triangles;
    all.insert(all.end(), filling.triangles.begin(), filling.triangles.end());
    return makeDiscretePatch(patch.points, std::move(all), extended);
  }

} // namespace

void reparamForgetLayoutMaps()
{
  std::lock_guard<std::mutex> lock(mapCacheMutex());
  mapCache().clear();
}

} // namespace reparam

using namespace reparam;

int reparamComputeParametrization(const std::vector<MTriangle *> &triangles,
                                  std::vector<MVertex *> &nodes,
                                  std::vector<SPoint2> &stl_vertices_uv,
                                  std::vector<SPoint3> &stl_vertices_xyz,
                                  std::vector<int> &stl_triangles)
{
  // (the layout's parts, on several threads, belong to no face)
  creatingFace = quiet ? nullptr : reparamTakeFaceInCreation();
  // the curves are made once faces get their geometry: the layout's
  // junctions are of no more use (and their nodes may go)
  if(creatingFace) reparamForgetJunctions();
  lastFailure.clear();
  const int choice = getReparamOptions().parametrization;
  // whatever happens below, an earlier record for these arrays is stale
  recordParametrization(stl_vertices_uv, nullptr);
  if(choice == (int)compoundParametrization::gmsh) return 0;

  stl_vertices_uv.clear();
  stl_vertices_xyz.clear();
  stl_triangles.clear();
  nodes.clear();
  if(triangles.empty()) return -1;

  double t0 = TimeOfDay();
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > tris;
  std::vector<int> canonical;
  discretePatch patch;
  reparamError err =
    patchOfTriangles(triangles, nodes, points, tris, canonical, patch);
  // Gmsh's callers read the outputs whatever the result (the patch check of
  // ClassifySurfaces indexes the (u, v) by the triangles): they stay empty
  // unless the map succeeds
  std::vector<int> triangleNodes(3 * tris.size());
  for(std::size_t t = 0; t < tris.size(); t++)
    for(int j = 0; j < 3; j++) triangleNodes[3 * t + j] = tris[t][j];
  double t1 = TimeOfDay();
  if(!err.ok()) {
    std::string where;
    if(err.node >= 0 && err.node < (int)nodes.size()) {
      // the patch numbers nodes from 0: tell the user Gmsh's tag and where
      MVertex *v =
        nodes[std::find(canonical.begin(), canonical.end(), err.node) -
              canonical.begin()];
      char s[128];
      snprintf(s, sizeof(s), " at node %lu (%g, %g, %g)", v->getNum(), v->x(),
               v->y(), v->z());
      where = s;
    }
    failure("Cannot parametrize triangulation (%lu triangles)%s: %s",
            triangles.size(), where.c_str(), err.what().c_str());
    lastFailure = err.what(); // the layout names the part itself
    nodes.clear();
    return -1;
  }
  if(patch.numReorientedTriangles && !quiet)
    Msg::Warning("Triangulation (%lu triangles) is not consistently oriented: "
                 "%lu triangles taken reversed for the parametrization",
                 triangles.size(), patch.numReorientedTriangles);

  // Holes filled on an extended patch with the same nodes: its (u, v) are
  // the patch's
  const discretePatch *mapped = &patch;
  discretePatch extended;
  int filledHoles = 0;
  if(getReparamOptions().fillHoles && patch.boundaryLoops.size() > 1) {
    holeFilling filling = fillHoles(patch);
    if(filling.skippedHoles && !quiet)
      Msg::Warning("Triangulation (%lu triangles): %d of its %lu holes cannot "
                   "be filled on their mean plane, left as free boundaries",
                   triangles.size(), filling.skippedHoles,
                   patch.boundaryLoops.size() - 1);
    if(!filling.triangles.empty()) {
      const reparamError fillErr = extendedPatch(patch, filling, extended);
      if(fillErr.ok()) {
        mapped = &extended;
        filledHoles = filling.filledHoles;
      }
      else if(!quiet)
        Msg::Warning("Triangulation (%lu triangles): filling its holes gives "
                     "an invalid patch (%s), holes left as free boundaries",
                     triangles.size(), fillErr.what().c_str());
    }
  }
  double t2 = TimeOfDay();

  std::vector<mapStep> steps = mapChain(choice);
  if(steps.empty()) {
    failure("Mesh.CompoundParametrization = %d (%s) is not implemented: "
            "use 0 to 6",
            choice, compoundParametrizationName(choice));
    nodes.clear();
    return -1;
  }
  bool fromLayout = false;
  checkedMap result =
    mapChainOf(*mapped, choice, steps, getReparamOptions().repair, fromLayout);
  const std::string surface = surfaceName(nodes, triangles.size());
  for(const mapAttempt &a : result.attempts) logAttempt(surface, a);
  if(result.chosen < 0) {
    failure("%s map of %s failed: %s", compoundParametrizationName(choice),
            surface.c_str(), result.map.error.what().c_str());
    nodes.clear();
    return -1;
  }
  if(!result.bijective && choice != (int)compoundParametrization::automatic &&
     choice != (int)compoundParametrization::meanValue) {
    // A flipped or folded (u, v) can make the planar mesher loop for ever
    // (gmsh2x_implant with LSCM: MeshAdapt on a face with 14 flipped
    // triangles never ends): a map chosen by hand falls back to the mean
    // value map, one-to-one on a convex boundary
    const mapAttempt &failed = result.attempts[result.chosen];
    checkedMap fallback =
      runMapChain(*mapped, mapChain((int)compoundParametrization::meanValue),
                  getReparamOptions().repair);
    for(const mapAttempt &a : fallback.attempts) logAttempt(surface, a);
    if(fallback.chosen >= 0 && fallback.bijective) {
      if(!quiet)
        Msg::Warning("%s map of %s is not one-to-one (%lu flipped triangles, "
                     "%lu folds): using the mean value map instead",
                     compoundParametrizationName(choice), surface.c_str(),
                     failed.flippedAfter, failed.foldsAfter);
      result.chosen = (int)result.attempts.size() + fallback.chosen;
      result.attempts.insert(result.attempts.end(), fallback.attempts.begin(),
                             fallback.attempts.end());
      result.map = std::move(fallback.map);
      result.bijective = true;
    }
  }
  const mapAttempt &chosen = result.attempts[result.chosen];
  if(!result.bijective) {
    // Never a folded or flipped map to the planar mesher in automatic mode;
    // when even the mean value map is not one-to-one by hand, it is kept,
    // with a warning
    if(choice == (int)compoundParametrization::automatic) {
      failure("No one-to-one parametrization of %s: every map of the "
              "automatic chain flips or folds",
              surface.c_str());
      nodes.clear();
      return -1;
    }
    if(!quiet)
      Msg::Warning(
        "%s map of %s is not one-to-one (%lu flipped triangles, %lu "
        "folds): the mesh may be invalid; Mesh.CompoundParametrization "
        "= 6 tries the maps in turn",
        compoundParametrizationName(choice), surface.c_str(),
        chosen.flippedAfter, chosen.foldsAfter);
  }
  else if(chosen.degenerateAfter && !quiet)
    Msg::Warning("%s map of %s: %lu triangles have a numerically degenerate "
                 "image",
                 compoundParametrizationName(chosen.map), surface.c_str(),
                 chosen.degenerateAfter);
  const patchMap &map = result.map;

  stl_triangles = std::move(triangleNodes);
  stl_vertices_xyz = std::move(points);
  stl_vertices_uv.resize(nodes.size());
  for(std::size_t i = 0; i < nodes.size(); i++)
    stl_vertices_uv[i] =
      SPoint2(map.uv[2 * canonical[i]], map.uv[2 * canonical[i] + 1]);
  double checkTime = 0.;
  for(const mapAttempt &a : result.attempts) checkTime += a.checkTime;
  parametrizationRecord record;
  for(std::size_t i = 0; i < result.attempts.size(); i++) {
    record.mapsTried.push_back(result.attempts[i].map);
    if((int)i != result.chosen)
      record.fallbackTime += result.attempts[i].mapTime;
  }
  record.map = chosen.map;
  record.bijective = result.bijective;
  record.nodes = nodes.size();
  record.triangles = triangles.size();
  record.holes = patch.boundaryLoops.size() - 1;
  record.filledHoles = filledHoles;
  record.patchTime = t1 - t0;
  record.fillTime = t2 - t1;
  record.assembleTime = map.assembleTime;
  record.solveTime = map.solveTime;
  record.checkTime = checkTime;
  record.fromLayout = fromLayout;
  recordParametrization(stl_vertices_uv, &record);
  // the face's tips become mesh nodes (points embedded in it)...
  if(creatingFace) {
    reparamEmbedConePoints(creatingFace, nodes, stl_vertices_xyz,
                           stl_triangles);
    // and its sharp creases left inside it become embedded curves
    reparamEmbedCreaseCurves(creatingFace, nodes, stl_vertices_xyz,
                             stl_triangles);
  }
  if(!quiet)
    Msg::Info("Reparam: %s map of %lu nodes, %lu triangles, %lu hole%s "
              "(%d filled): patch %.3g s, fill %.3g s, assemble %.3g s, solve "
              "%.3g s, checks %.3g s%s",
              compoundParametrizationName(chosen.map), nodes.size(),
              triangles.size(), patch.boundaryLoops.size() - 1,
              patch.boundaryLoops.size() == 2 ? "" : "s", filledHoles, t1 - t0,
              t2 - t1, map.assembleTime, map.solveTime, checkTime,
              fromLayout ? " (computed by the layout)" : "");
  return 1;
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
  checkingPatch = true;
  int done = reparamComputeParametrization(triangles, nodes, uv, xyz, tri);
  checkingPatch = false;
  const parametrizationRecord *record = findParametrization(uv);
  // The automatic chain ends on mean value when both conformal maps fold or
  // flip: the patch winds around or is too elongated for a free boundary,
  // and mean value on a circle squeezes it so much that the planar mesher
  // may fail (gmsh2x_king_ascii: Frontal-Delaunay gave up, MeshAdapt left
  // 1764 invalid elements). Smaller parts flatten conformally.
  const bool wound = done > 0 && record &&
                     choice == (int)compoundParametrization::automatic &&
                     record->map == (int)compoundParametrization::meanValue &&
                     record->mapsTried.size() > 1;
  recordParametrization(uv, nullptr); // local arrays: nothing to keep
  // Gmsh's own test: a (u, v) triangle below 1e-8 (twice its area, the
  // image being about the unit disk) means a patch so stretched that parts
  // of it would be meshed far too coarsely (aorta as one face: Hausdorff
  // 12 % of the diagonal, 293 inverted elements)
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

namespace reparam {

int reparamTryParametrization(const std::vector<MTriangle *> &triangles,
                              std::vector<SPoint2> &uv,
                              std::vector<SPoint3> &xyz, std::vector<int> &tri,
                              std::string &why)
{
  std::vector<MVertex *> nodes;
  checkingPatch = quiet = true;
  lastFailure.clear();
  int done = reparamComputeParametrization(triangles, nodes, uv, xyz, tri);
  checkingPatch = quiet = false;
  const parametrizationRecord *record = findParametrization(uv);
  if(done > 0 && record && !record->bijective) {
    why = "its map is not one-to-one";
    done = -1;
  }
  else if(done > 0 && record &&
          getReparamOptions().parametrization ==
            (int)compoundParametrization::automatic &&
          record->map == (int)compoundParametrization::meanValue) {
    // both conformal maps fold or flip: the part winds around, and mean
    // value on a circle squeezes it so much that Frontal-Delaunay fails and
    // MeshAdapt takes over (gmsh2x_king_ascii: one face of 36703 triangles
    // of kappa mean 0.25, 4808 against the input, 45 s); its parts map
    // conformally (0 against the input, 7 s in all)
    why = "its conformal maps fold (it winds around)";
    done = -1;
  }
  else if(done > 0 && record && getReparamOptions().fillHoles &&
          record->filledHoles < record->holes) {
    // a loop that cannot be filled on its mean plane winds around a tube:
    // left free, it leaves a conformal map badly squeezed (gmsh2x_linkrod2:
    // Hausdorff 10 % of the face's size), and a cut across the tube removes
    // it
    why = "a hole of it cannot be filled on its mean plane";
    done = -1;
  }
  else if(done <= 0)
    why = lastFailure;
  recordParametrization(uv, nullptr); // local arrays: nothing to keep
  return done;
}

std::string reparamLastFailure() { return lastFailure; }

bool reparamHolesFillable(const std::vector<MTriangle *> &triangles)
{
  if(!getReparamOptions().fillHoles) return true;
  std::vector<MVertex *> nodes;
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > tris;
  std::vector<int> canonical;
  discretePatch patch;
  // an invalid patch is the maps' failure to tell
  if(!patchOfTriangles(triangles, nodes, points, tris, canonical, patch).ok() ||
     patch.boundaryLoops.size() < 2)
    return true;
  const holeFilling filling = fillHoles(patch);
  discretePatch extended;
  return !filling.skippedHoles && !filling.triangles.empty() &&
         extendedPatch(patch, filling, extended).ok();
}
} // namespace reparam

