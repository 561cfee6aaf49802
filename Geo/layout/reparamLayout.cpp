// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The hook ClassifySurfaces{..., forParametrization = 1} calls instead of
// Gmsh's split loop (patches/0006): Reparam's patch layout
// (Mesh/layout/patchLayout) on the model's triangles and sharp edges, each part
// verified with the parametrization CreateGeometry will compute for it; the
// layout is handed back to Gmsh as the mesh edges between patches, from which
// Gmsh's own classification builds exactly these patches as discrete surfaces.

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>
#include "Context.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "OS.h"
#include "edgeUses.h"
#include "patchLayout.h"
#include "reparamConePoints.h"
#include "reparamCurveMesh.h"
#include "reparamHooks.h"
#include "reparamLayout.h"
#include "reparamOptions.h"
#include "reparamParametrize.h"
#include "reparamParametrizeAgain.h"
#include "reparamState.h"
#include "reparamTrianglePatch.h"
#include "triangleAdjacency.h"

namespace reparam {

double mapCrowding(const std::vector<SPoint2> &uv,
                   const std::vector<SPoint3> &xyz,
                   const std::vector<int> &triangleNodes)
{
  const std::size_t n = triangleNodes.size() / 3;
  std::vector<double> uvArea(n), area(n);
  double uvTotal = 0., total = 0.;
  for(std::size_t t = 0; t < n; t++) {
    const int a = triangleNodes[3 * t], b = triangleNodes[3 * t + 1],
              c = triangleNodes[3 * t + 2];
    uvArea[t] = std::fabs((uv[b].x() - uv[a].x()) * (uv[c].y() - uv[a].y()) -
                          (uv[b].y() - uv[a].y()) * (uv[c].x() - uv[a].x()));
    SVector3 normal =
      crossprod(SVector3(xyz[a], xyz[b]), SVector3(xyz[a], xyz[c]));
    area[t] = normal.norm();
    uvTotal += uvArea[t];
    total += area[t];
  }
  if(!(uvTotal > 0.) || !(total > 0.)) return 0.;
  double crowding = 1e300;
  for(std::size_t t = 0; t < n; t++) {
    // slivers of the input: their own 3D area says nothing of the map
    if(area[t] < 1e-6 * total / n) continue;
    crowding = std::min(crowding, (uvArea[t] / uvTotal) / (area[t] / total));
  }
  return crowding > 1e299 ? 1. : crowding;
}

void areaAndBoundaryLength(const std::vector<SPoint3> &xyz,
                           const std::vector<int> &triangleNodes, double &area,
                           double &length)
{
  area = 0.;
  for(std::size_t t = 0; t + 2 < triangleNodes.size(); t += 3) {
    const int *n = &triangleNodes[t];
    area += 0.5 * crossprod(SVector3(xyz[n[0]], xyz[n[1]]),
                            SVector3(xyz[n[0]], xyz[n[2]]))
                    .norm();
  }
  length = 0.;
  for(const auto &e : edgesUsedOnce(triangleNodes))
    length += xyz[e.first].distance(xyz[e.second]);
}

double boundaryLargeness(const std::vector<SPoint3> &xyz,
                         const std::vector<int> &triangleNodes)
{
  double area, length;
  areaAndBoundaryLength(xyz, triangleNodes, area, length);
  if(!(length > 0.)) return 1e300; // closed
  return area / (length * length / (4. * M_PI));
}

namespace {

  // The model's triangles as plain arrays, and Gmsh's objects behind them
  struct modelTriangulation {
    layoutMesh mesh;
    std::vector<MTriangle *> triangles;
    std::vector<MVertex *> nodes;
  };

  modelTriangulation collectTriangles(GModel *gm,
                                      const std::vector<MLine *> &lines)
  {
    modelTriangulation m;
    std::unordered_map<MVertex *, int> index;
    auto nodeOf = [&](MVertex *v) {
      auto it = index.insert(std::make_pair(v, (int)m.nodes.size()));
      if(it.second) {
        m.nodes.push_back(v);
        m.mesh.points.push_back(v->point());
      }
      return it.first->second;
    };
    for(auto it = gm->firstFace(); it != gm->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles) {
        m.triangles.push_back(t);
        m.mesh.triangles.push_back({nodeOf(t->getVertex(0)),
                                    nodeOf(t->getVertex(1)),
                                    nodeOf(t->getVertex(2))});
      }
    for(MLine *l : lines) {
      auto a = index.find(l->getVertex(0)), b = index.find(l->getVertex(1));
      if(a != index.end() && b != index.end())
        m.mesh.featureEdges.push_back({a->second, b->second});
    }
    return m;
  }

  // Where a part's maps fail, in the layout's node indices (found on the
  // part's triangles)
  void placeOnLayout(const modelTriangulation &model,
                     const std::vector<int> &part, const mapFailurePlace &where,
                     partCheck &check)
  {
    if(where.through.empty() && where.apart.empty()) return;
    std::unordered_map<MVertex *, int> index;
    for(int t : part)
      for(int k = 0; k < 3; k++)
        index[model.triangles[t]->getVertex(k)] = model.mesh.triangles[t][k];
    for(MVertex *v : where.through) {
      auto it = index.find(v);
      if(it != index.end()) check.cutThrough.push_back(it->second);
    }
    std::sort(check.cutThrough.begin(), check.cutThrough.end());
    for(const auto &pr : where.apart) {
      auto a = index.find(pr[0]), b = index.find(pr[1]);
      if(a != index.end() && b != index.end())
        check.cutApart.push_back({{a->second, b->second}});
    }
  }

  double totalArea(const layoutMesh &mesh)
  {
    double sum = 0.;
    for(std::size_t t = 0; t < mesh.triangles.size(); t++)
      sum += triangleArea(mesh, (int)t);
    return sum;
  }

} // namespace

layoutParameters reparamLayoutParameters(const layoutMesh &mesh)
{
  // Noise at the mesh scale, with the mesh size unknown when
  // ClassifySurfaces runs: the size is Mesh.CompoundNoiseSize, or the edge
  // of the uniform mesh of equilateral triangles with as many triangles as
  // the input (on scans about their mean edge; on CAD triangulations far
  // below it, whose long slivers say nothing of the size of their faces).
  // Noise is a sliver: a patch narrower than an eighth of that size (width:
  // twice its area over its perimeter), whose curves would nearly touch
  // (Gmsh: "intersections in the 1D mesh") and pinch its neighbours. Small
  // patches of CAD faces are not noise: merged, their corners and creases
  // are lost (bench/README.md, "Patch layout"). A patch is
  // noise only when small against the whole surface (1 %), so that the few
  // large faces of a coarse CAD triangulation never are.
  const double area = totalArea(mesh);
  const double size =
    getReparamOptions().noiseSize > 0. ?
      getReparamOptions().noiseSize :
      std::sqrt(4. * area / (std::sqrt(3.) * mesh.triangles.size()));
  layoutParameters p;
  p.noiseTriangles = 0;
  p.noiseArea = 0.;
  p.noiseWidth = 0.125 * size;
  p.noiseWidthMaxArea = 0.01 * area;
  // Off by default: the radius that smooths voxel staircases away smooths
  // the small features of CAD parts too (bench/README.md, "Features at the
  // mesh's scale")
  p.featureRadius = getReparamOptions().featureScale * size;
  return p;
}

namespace {

  // The part's points and its triangles' indices into them
  void pointsOfPart(const std::vector<MTriangle *> &triangles,
                    std::vector<SPoint3> &xyz, std::vector<int> &nodes)
  {
    std::unordered_map<MVertex *, int> index;
    for(MTriangle *t : triangles)
      for(int k = 0; k < 3; k++) {
        MVertex *v = t->getVertex(k);
        auto it = index.insert(std::make_pair(v, (int)xyz.size()));
        if(it.second) xyz.push_back(v->point());
        nodes.push_back(it.first->second);
      }
  }

  // The tests a part fails whatever its map, before the map (a solve of
  // seconds on a part of 100k triangles, on a scan of a million only to
  // cut it: 40 s of the layout of a vessel's 964k triangles); the patch the
  // map takes is built for them (once for both)
  bool failsBeforeTheMap(const std::vector<MTriangle *> &triangles,
                         trianglePatch &patch, partCheck &check)
  {
    if(getReparamOptions().parametrization ==
       (int)compoundParametrization::gmsh)
      return false;
    std::vector<SPoint3> xyz;
    std::vector<int> nodes;
    pointsOfPart(triangles, xyz, nodes);
    // A patch much larger than its boundary (a sock: a tube closed at one
    // end): the planar mesher starts from the boundary nodes and measures
    // edges by their chords, so it leaves the patch nearly empty
    // (bench/README.md, "Patch layout")
    const double largeness = boundaryLargeness(xyz, nodes);
    char s[128];
    if(largeness > reparamMaxLargeness) {
      snprintf(s, sizeof(s),
               "it is %.3g times larger than the disk its boundary bounds",
               largeness);
      check.reason = s;
    }
    else if(!reparamHolesFillable(patch = patchOfTriangles(triangles)))
      check.reason = "a hole of it cannot be filled";
    else
      return false;
    check.ok = false;
    lastLayout().refusedBeforeTheMap++;
    return true;
  }

} // namespace

partCheck reparamVerifyPart(const std::vector<MTriangle *> &triangles,
                            mapFailurePlace *where)
{
  std::vector<SPoint2> uv;
  std::vector<SPoint3> xyz;
  std::vector<int> nodes;
  partCheck check;
  trianglePatch patch;
  if(failsBeforeTheMap(triangles, patch, check)) return check;
  int done =
    reparamTryParametrization(triangles, uv, xyz, nodes, check.reason, where,
                              patch.nodes.empty() ? nullptr : &patch);
  if(done <= 0) {
    check.ok = false;
    return check;
  }
  // The map squeezes part of the patch into a sliver of the (u, v) plane:
  // the planar mesher then works at the limit of its precision (aorta as one
  // face: parts meshed far too coarsely, 12 % Hausdorff distance)
  double crowding = mapCrowding(uv, xyz, nodes);
  if(crowding < reparamMinCrowding) {
    check.ok = false;
    char s[128];
    snprintf(s, sizeof(s), "its map crowds it (area ratio %.2g)", crowding);
    check.reason = s;
  }
  return check;
}

namespace {

  // The cuts of the layout that are no sharp edge, boundary nor
  // non-manifold edge: the curve meshes leave their turns alone; and those
  // edges, that the optimization across cuts keeps
  void recordSmoothCuts(const modelTriangulation &model,
                        const layoutResult &layout)
  {
    std::set<std::array<int, 2> > sharp;
    for(const auto &e : layout.features)
      sharp.insert({{std::min(e[0], e[1]), std::max(e[0], e[1])}});
    const triangleAdjacency adjacency =
      makeTriangleAdjacency(model.mesh.triangles);
    std::vector<std::array<SPoint3, 2> > smooth, fixed;
    for(const auto &e : layout.features)
      fixed.push_back({{model.mesh.points[e[0]], model.mesh.points[e[1]]}});
    for(std::size_t edge = 0; edge < adjacency.edges.size(); edge++)
      if(adjacency.numTriangles((int)edge) != 2) {
        const std::array<int, 2> &e = adjacency.edges[edge];
        fixed.push_back({{model.mesh.points[e[0]], model.mesh.points[e[1]]}});
      }
    reparamRecordFixedEdges(fixed);
    for(const auto &e : layout.cutEdges) {
      const std::array<int, 2> key = {
        {std::min(e[0], e[1]), std::max(e[0], e[1])}};
      const int edge = adjacency.find(key[0], key[1]);
      if(sharp.count(key) || edge < 0 || adjacency.numTriangles(edge) != 2)
        continue;
      smooth.push_back({{model.mesh.points[e[0]], model.mesh.points[e[1]]}});
    }
    reparamRecordSmoothCuts(smooth);
  }

  // The nodes where three cut edges or more meet: where two boundary loops
  // touch, or a cut ends on another. Gmsh ends its curves
  // only where the edges of one pair of faces branch, so two curves could
  // pass through such a node without a model point there, and their meshes
  // would not meet: Gmsh's classification asks reparamBreakCurveAt
  void recordJunctions(const modelTriangulation &model,
                       const layoutResult &layout)
  {
    std::set<const MVertex *> &junctions = lastLayout().junctions;
    junctions.clear();
    std::vector<int> degree(model.nodes.size(), 0);
    for(const auto &e : layout.cutEdges) {
      degree[e[0]]++;
      degree[e[1]]++;
    }
    for(std::size_t i = 0; i < degree.size(); i++)
      if(degree[i] >= 3) junctions.insert(model.nodes[i]);
  }

  // The sharp edges the noise merge took inside a patch: their corners are
  // kept as mesh nodes (Geo/layout/reparamConePoints.cpp)
  void recordMergedCreases(const modelTriangulation &model,
                           const layoutResult &layout, double size)
  {
    std::set<std::array<int, 2> > cuts;
    for(const auto &e : layout.cutEdges)
      cuts.insert({{std::min(e[0], e[1]), std::max(e[0], e[1])}});
    std::vector<std::array<SPoint3, 2> > merged;
    for(const auto &e : layout.features)
      if(!cuts.count({{std::min(e[0], e[1]), std::max(e[0], e[1])}}))
        merged.push_back({{model.mesh.points[e[0]], model.mesh.points[e[1]]}});
    reparamRecordMergedCreases(merged, size);
  }

} // namespace

} // namespace reparam

using namespace reparam;

bool reparamBreakCurveAt(MVertex *v)
{
  return lastLayout().junctions.count(v) > 0;
}

namespace reparam {

void reparamForgetJunctions() { lastLayout().junctions.clear(); }

} // namespace reparam

int reparamLayoutPatches(GModel *gm, std::vector<MLine *> &lines)
{
  // what an earlier layout left (its junctions, maps, cuts and creases)
  // and gm's crease curves go, also when Gmsh's split loop makes the patches
  beginLayoutRecords(gm);
  lastLayout().options = currentLayoutOptions();
  const reparamOptions &options = getReparamOptions();
  if(options.parametrization == (int)compoundParametrization::gmsh ||
     !options.layout)
    return 0;
  double t0 = TimeOfDay();
  modelTriangulation model = collectTriangles(gm, lines);
  if(model.triangles.empty()) return 0;
  layoutParameters parameters = reparamLayoutParameters(model.mesh);
  // General.NumThreads (Gmsh built with OpenMP); the maps and their checks
  // keep their state per thread
  parameters.threads = std::max(1, Msg::GetMaxThreads());
  const int maxTriangles = CTX::instance()->mesh.reparamMaxTriangles;
  partVerifier verify = [&model, maxTriangles](const std::vector<int> &part) {
    // Gmsh's own bound on a patch, Mesh.ReparamMaxTriangles
    if(maxTriangles > 1 && (int)part.size() > maxTriangles)
      return partCheck{false,
                       "it has more than Mesh.ReparamMaxTriangles = " +
                         std::to_string(maxTriangles) + " triangles",
                       true};
    std::vector<MTriangle *> t(part.size());
    for(std::size_t i = 0; i < part.size(); i++)
      t[i] = model.triangles[part[i]];
    mapFailurePlace where;
    partCheck check = reparamVerifyPart(t, &where);
    placeOnLayout(model, part, where, check);
    return check;
  };
  layoutResult layout = computePatchLayout(model.mesh, parameters, verify);

  // The cuts of the layout as lines: Gmsh's classification then grows
  // exactly these patches (sharp edges merged away with noise are no
  // longer cuts)
  for(MLine *l : lines) delete l;
  lines.clear();
  for(const auto &e : layout.cutEdges)
    lines.push_back(new MLine(model.nodes[e[0]], model.nodes[e[1]]));

  recordSmoothCuts(model, layout);
  recordJunctions(model, layout);
  recordMergedCreases(model, layout, 8. * parameters.noiseWidth);

  for(const layoutSplit &s : layout.splits)
    Msg::Info("Reparam: - level %d part of %lu triangles split in %lu parts "
              "because %s%s%s",
              s.depth, s.triangles, s.parts, s.reason.c_str(),
              s.atFailure ? " (cut where its maps fail)" : "",
              s.movedFans ? (" (the cut moved off " +
                             std::to_string(s.movedFans) + " pinched nodes)")
                              .c_str() :
                            "");
  if(layout.featuresBelowScale)
    Msg::Info("Reparam: %lu of %lu sharp edges no features: seen over a "
              "radius of %g (Mesh.CompoundFeatureScale), less than half "
              "their angle remains",
              layout.featuresBelowScale, model.mesh.featureEdges.size(),
              parameters.featureRadius);
  Msg::Info(
    "Reparam: layout of %lu triangles: %d feature patches, %d noise "
    "patches merged (size %g), %d splits, %d patches (clean %.3g s, "
    "split and verify %.3g s%s, %lu parts refused before their map, total "
    "%.3g s)",
    model.triangles.size(), layout.featurePatches, layout.mergedNoise,
    8. * parameters.noiseWidth, (int)layout.splits.size(), layout.numPatches,
    layout.cleanTime, layout.splitTime,
    parameters.threads > 1 ?
      (" on " + std::to_string(parameters.threads) + " threads").c_str() :
      "",
    lastLayout().refusedBeforeTheMap.load(), TimeOfDay() - t0);
  for(const auto &u : layout.unverified)
    // CreateGeometry then keeps its input triangles, with a warning naming
    // the surface
    Msg::Info("Reparam: a patch of the layout cannot be parametrized as it "
              "is (%s)",
              u.second.c_str());
  return 1;
}
