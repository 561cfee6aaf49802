// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The hook Gmsh's computeParametrization() calls first (patches/0001): turns
// Gmsh's triangles into a patch, runs the chosen map and hands (u, v) back in
// Gmsh's layout. Used by discrete faces' CreateGeometry, by Compound Surface
// meshing and by the patch checks of ClassifySurfaces.

#include <cstdio>
#include <string>
#include <unordered_map>
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "OS.h"
#include "discretePatch.h"
#include "meanValueMap.h"
#include "reparamOptions.h"

int reparamComputeParametrization(const std::vector<MTriangle *> &triangles,
                                  std::vector<MVertex *> &nodes,
                                  std::vector<SPoint2> &stl_vertices_uv,
                                  std::vector<SPoint3> &stl_vertices_xyz,
                                  std::vector<int> &stl_triangles)
{
  const int choice = getReparamOptions().parametrization;
  if(choice == (int)compoundParametrization::gmsh) return 0;

  stl_vertices_uv.clear();
  stl_vertices_xyz.clear();
  stl_triangles.clear();
  nodes.clear();
  if(triangles.empty()) return -1;

  double t0 = TimeOfDay();
  // Nodes numbered in order of first appearance, as Gmsh's own code does, so
  // that both give the same node order
  std::unordered_map<MVertex *, int> nodeIndex;
  nodeIndex.reserve(triangles.size());
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > tris(triangles.size());
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
  // Gmsh's callers read the outputs whatever the result (the patch check of
  // ClassifySurfaces indexes the (u, v) by the triangles): they stay empty
  // unless the map succeeds
  std::vector<int> triangleNodes(3 * tris.size());
  for(std::size_t t = 0; t < tris.size(); t++)
    for(int j = 0; j < 3; j++) triangleNodes[3 * t + j] = tris[t][j];

  discretePatch patch;
  reparamError err = makeDiscretePatch(std::move(points), std::move(tris), patch);
  double t1 = TimeOfDay();
  if(!err.ok()) {
    std::string where;
    if(err.node >= 0 && err.node < (int)nodes.size()) {
      // the patch numbers nodes from 0: tell the user Gmsh's tag and where
      MVertex *v = nodes[err.node];
      char s[128];
      snprintf(s, sizeof(s), " at node %lu (%g, %g, %g)", v->getNum(), v->x(),
               v->y(), v->z());
      where = s;
    }
    Msg::Error("Cannot parametrize triangulation (%lu triangles)%s: %s",
               triangles.size(), where.c_str(), err.what().c_str());
    nodes.clear();
    return -1;
  }
  if(patch.numReorientedTriangles)
    Msg::Warning("Triangulation (%lu triangles) is not consistently oriented: "
                 "%lu triangles taken reversed for the parametrization",
                 triangles.size(), patch.numReorientedTriangles);

  patchMap map;
  switch((compoundParametrization)choice) {
  case compoundParametrization::meanValue: map = meanValueMap(patch); break;
  default:
    Msg::Error("Mesh.CompoundParametrization = %d (%s) is not implemented "
               "yet: use 0 (Gmsh) or 3 (mean value)",
               choice, compoundParametrizationName(choice));
    nodes.clear();
    return -1;
  }
  if(!map.error.ok()) {
    Msg::Error("%s map of triangulation (%lu triangles) failed: %s",
               compoundParametrizationName(choice), triangles.size(),
               map.error.what().c_str());
    nodes.clear();
    return -1;
  }

  stl_triangles = std::move(triangleNodes);
  stl_vertices_xyz = patch.points;
  stl_vertices_uv.resize(nodes.size());
  for(std::size_t i = 0; i < nodes.size(); i++)
    stl_vertices_uv[i] = SPoint2(map.uv[2 * i], map.uv[2 * i + 1]);
  Msg::Info("Reparam: %s map of %lu nodes, %lu triangles, %lu hole%s: "
            "patch %.3g s, assemble %.3g s, solve %.3g s",
            compoundParametrizationName(choice), nodes.size(),
            triangles.size(), patch.boundaryLoops.size() - 1,
            patch.boundaryLoops.size() == 2 ? "" : "s", t1 - t0,
            map.assembleTime, map.solveTime);
  return 1;
}
