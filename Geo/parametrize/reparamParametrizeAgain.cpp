// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cstdio>
#include <string>
#include <vector>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "mapKind.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamParametrize.h"
#include "reparamParametrizeAgain.h"
#include "reparamReport.h"
#include "reparamState.h"

namespace reparam {

namespace {

  void addChange(std::string &list, const char *option, double was, double now)
  {
    if(was == now) return;
    char s[160];
    snprintf(s, sizeof(s), "%s%s %g -> %g", list.empty() ? "" : ", ", option,
             was, now);
    list += s;
  }

  // Gmsh's own map of the face's arrays (its triangles are gone), on nodes
  // and triangles of no entity, numbered from 1 (Gmsh's counters keep their
  // values: this runs on the main thread, before the faces are meshed)
  bool gmshMapOfArrays(const GFace *gf, std::vector<SPoint2> &uv)
  {
    const std::vector<SPoint3> &xyz = gf->stl_vertices_xyz;
    const std::vector<int> &tri = gf->stl_triangles;
    std::vector<MVertex> nodes;
    nodes.reserve(xyz.size());
    for(std::size_t i = 0; i < xyz.size(); i++)
      nodes.emplace_back(xyz[i].x(), xyz[i].y(), xyz[i].z(), nullptr, i + 1);
    std::vector<MTriangle> triangles;
    triangles.reserve(tri.size() / 3);
    for(std::size_t t = 0; t + 2 < tri.size(); t += 3)
      triangles.emplace_back(&nodes[tri[t]], &nodes[tri[t + 1]],
                             &nodes[tri[t + 2]], t / 3 + 1);
    std::vector<MTriangle *> pointers;
    for(MTriangle &t : triangles) pointers.push_back(&t);
    std::vector<MVertex *> order;
    std::vector<SPoint2> mapped;
    std::vector<SPoint3> points;
    std::vector<int> indices;
    if(!computeParametrization(pointers, order, mapped, points, indices) ||
       order.size() != xyz.size())
      return false;
    // its nodes come in the order they appear in, as the arrays' do; by
    // address all the same
    uv.assign(xyz.size(), SPoint2());
    for(std::size_t i = 0; i < order.size(); i++)
      uv[order[i] - &nodes[0]] = mapped[i];
    return true;
  }

  // The layout's options changed since ClassifySurfaces: named once
  void nameLayoutOptionsChange()
  {
    layoutRecord &layout = lastLayout();
    if(!layout.options || layout.optionsChangeNamed) return;
    const std::string change =
      layoutOptionsChange(*layout.options, currentLayoutOptions());
    if(change.empty()) return;
    layout.optionsChangeNamed = true;
    Msg::Warning("Reparam: %s since ClassifySurfaces, which reads %s: "
                 "the surfaces keep the patch layout it made (classify "
                 "again, e.g. reload the file, for the new one)",
                 change.c_str(),
                 change.find(", ") == std::string::npos ? "it" : "them");
  }

  // gf's map computed again when the options it was computed with changed;
  // true when its arrays got new (u, v)
  bool parametrizeFaceAgain(GFace *gf)
  {
    mapOptionsRecord now = currentMapOptions(), was;
    {
      std::unique_lock<std::mutex> lock = lockRecords();
      faceRecord *r = findFaceRecord(gf);
      if(!r || !r->mappedWith || mapOptionsChange(*r->mappedWith, now).empty())
        return false;
      was = *r->mappedWith;
    }
    const std::string change = mapOptionsChange(was, now);
    now.canonicalNodes = was.canonicalNodes;
    now.triangleOrder = was.triangleOrder;
    std::vector<SPoint2> uv;
    parametrizationRecord record;
    std::string why;
    int done = 0;
    if(gf->stl_triangles.empty())
      // no map took it: meshed with its input triangles
      Msg::Info("Reparam: surface %d: %s since CreateGeometry, no map of "
                "it to compute again (meshed with its input triangles)",
                gf->tag(), change.c_str());
    else {
      Msg::Info("Reparam: surface %d parametrized again: %s since "
                "CreateGeometry",
                gf->tag(), change.c_str());
      if(now.map == (int)compoundParametrization::gmsh)
        done = gmshMapOfArrays(gf, uv) ? 1 : -1;
      else
        done = reparamMapFaceArrays(gf, was, uv, record, why);
      if(done <= 0)
        Msg::Warning("Surface %d: the %s map fails%s%s%s: meshed with the "
                     "map CreateGeometry computed",
                     gf->tag(), compoundParametrizationName(now.map),
                     why.empty() ? "" : " (", why.c_str(),
                     why.empty() ? "" : ")");
    }
    std::unique_lock<std::mutex> lock = lockRecords();
    faceRecord &r = faceRecordOf(gf);
    // asked once per change of the options, whatever came of it
    r.mappedWith = std::move(now);
    if(done <= 0) return false;
    gf->stl_vertices_uv = std::move(uv);
    if(r.mappedWith->map == (int)compoundParametrization::gmsh)
      r.parametrization.reset();
    else
      r.parametrization = record;
    r.newParametrization = true;
    return true;
  }

} // namespace

mapOptionsRecord currentMapOptions()
{
  const reparamOptions &o = getReparamOptions();
  mapOptionsRecord r;
  r.map = o.parametrization;
  r.fillHoles = o.fillHoles;
  r.repair = o.repair;
  return r;
}

std::string mapOptionsChange(const mapOptionsRecord &was,
                             const mapOptionsRecord &now)
{
  std::string list;
  addChange(list, "Mesh.CompoundParametrization", was.map, now.map);
  addChange(list, "Mesh.CompoundFillHoles", was.fillHoles, now.fillHoles);
  addChange(list, "Mesh.CompoundRepair", was.repair, now.repair);
  return list;
}

layoutOptionsRecord currentLayoutOptions()
{
  const reparamOptions &o = getReparamOptions();
  layoutOptionsRecord r;
  r.layout = o.layout;
  r.split = o.split;
  r.noiseSize = o.noiseSize;
  r.featureScale = o.featureScale;
  return r;
}

std::string layoutOptionsChange(const layoutOptionsRecord &was,
                                const layoutOptionsRecord &now)
{
  std::string list;
  addChange(list, "Mesh.CompoundLayout", was.layout, now.layout);
  addChange(list, "Mesh.CompoundSplit", was.split, now.split);
  addChange(list, "Mesh.CompoundNoiseSize", was.noiseSize, now.noiseSize);
  addChange(list, "Mesh.CompoundFeatureScale", was.featureScale,
            now.featureScale);
  return list;
}

} // namespace reparam

using namespace reparam;

void reparamParametrizeAgain(GModel *m)
{
  nameLayoutOptionsChange();
  std::size_t again = 0;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it)
    if((*it)->geomType() == GEntity::DiscreteSurface)
      again += parametrizeFaceAgain(*it);
  if(again)
    Msg::Info("Reparam: %lu surface%s parametrized again", again,
              again > 1 ? "s" : "");
}

bool reparamTakeNewParametrization(GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecord *r = findFaceRecord(gf);
  if(!r || !r->newParametrization) return false;
  r->newParametrization = false;
  return true;
}
