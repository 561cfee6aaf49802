// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "SVector3.h"
#include "edgeByCoordinates.h"
#include "edgeUses.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamOverlappingFaces.h"
#include "reparamReport.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  typedef std::pair<std::size_t, std::size_t> nodePair;

  nodePair sideOf(const MVertex *a, const MVertex *b)
  {
    return std::minmax(a->getNum(), b->getNum());
  }

  // The input's own edges of more than two triangles (two of one face and
  // two of another), which the mesh of a curve along one keeps in pieces
  std::vector<std::array<SPoint3, 2> > inputNonManifoldEdges(GModel *m)
  {
    std::map<edgeByCoordinates, int> uses;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      const std::vector<SPoint3> &x = (*it)->stl_vertices_xyz;
      const std::vector<int> &t = (*it)->stl_triangles;
      for(std::size_t i = 0; i + 2 < t.size(); i += 3)
        for(int k = 0; k < 3; k++)
          uses[byCoordinates(x[t[i + k]], x[t[i + (k + 1) % 3]])]++;
    }
    std::vector<std::array<SPoint3, 2> > edges;
    for(const auto &u : uses)
      if(u.second > 2)
        edges.push_back({{SPoint3(u.first[0], u.first[1], u.first[2]),
                          SPoint3(u.first[3], u.first[4], u.first[5])}});
    return edges;
  }

  double distanceToSegment(const SPoint3 &p, const std::array<SPoint3, 2> &s)
  {
    const SVector3 d(s[0], s[1]), v(s[0], p);
    const double l = dot(d, d);
    const double t = l > 0. ? std::max(0., std::min(1., dot(v, d) / l)) : 0.;
    return p.distance(s[0] + SPoint3(d.x(), d.y(), d.z()) * t);
  }

  // Whether the segment a-b lies along one of `edges` (within `tolerance`)
  bool along(const SPoint3 &a, const SPoint3 &b,
             const std::vector<std::array<SPoint3, 2> > &edges,
             double tolerance)
  {
    for(const auto &e : edges)
      if(distanceToSegment(a, e) < tolerance &&
         distanceToSegment(b, e) < tolerance)
        return true;
    return false;
  }

  // Whether another face's elements use nodes of gf's mesh: the
  // optimization across the cuts moves triangles from face to face, and
  // meshing gf again (its mesh deleted) would leave theirs on deleted nodes
  bool nodesUsedByOtherFaces(GFace *gf)
  {
    std::set<MVertex *> own(gf->mesh_vertices.begin(), gf->mesh_vertices.end());
    if(own.empty()) return false;
    GModel *m = gf->model();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      if(*it == gf) continue;
      for(std::size_t i = 0; i < (*it)->getNumMeshElements(); i++) {
        MElement *e = (*it)->getMeshElement(i);
        for(std::size_t j = 0; j < e->getNumVertices(); j++)
          if(own.count(e->getVertex(j))) return true;
      }
    }
    return false;
  }

  bool meshedWithInput(GFace *gf, GFace *other, std::size_t overlaps)
  {
    if(nodesUsedByOtherFaces(gf)) return false;
    if(!reparamMeshFaceWithItsInput(
         gf, 0,
         "its mesh lay on surface " + std::to_string(other->tag()) + "'s (" +
           std::to_string(overlaps) +
           " edges inside both or triangles of both: a part thinner than the "
           "mesh size)"))
      return false;
    // the report's record of the face made again for its new mesh (the
    // faces are all meshed: the report is made of the records)
    const faceReport *report = findFaceReportOfFace(gf);
    if(report) reparamReportMeshedFace(gf, report->meshTime);
    return true;
  }

} // namespace

namespace {

  typedef std::map<std::pair<GFace *, GFace *>, std::size_t> overlapCounts;

  void addOverlap(GFace *a, GFace *b, overlapCounts &shared)
  {
    shared[a->tag() < b->tag() ? std::make_pair(a, b) : std::make_pair(b, a)]++;
  }

  // Edges of two triangles of one face (inside it) and two of another, not
  // along the input's own non-manifold edges
  void sharedInnerEdges(GModel *m, overlapCounts &shared)
  {
    // the faces of each edge's triangles, one entry per triangle
    std::map<nodePair, std::vector<GFace *> > uses;
    std::map<nodePair, std::array<SPoint3, 2> > places;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(const MTriangle *t : (*it)->triangles)
        for(int k = 0; k < 3; k++) {
          const MVertex *a = t->getVertex(k), *b = t->getVertex((k + 1) % 3);
          std::vector<GFace *> &f = uses[sideOf(a, b)];
          f.push_back(*it);
          if(f.size() == 3) places[sideOf(a, b)] = {{a->point(), b->point()}};
        }
    const std::vector<std::array<SPoint3, 2> > input = inputNonManifoldEdges(m);
    const double tolerance = 1e-9 * m->bounds().diag();
    for(auto &u : uses) {
      std::vector<GFace *> &f = u.second;
      if(f.size() <= 2) continue;
      const std::array<SPoint3, 2> &at = places[u.first];
      if(along(at[0], at[1], input, tolerance)) continue;
      std::sort(f.begin(), f.end(),
                [](GFace *a, GFace *b) { return a->tag() < b->tag(); });
      std::vector<GFace *> inside;
      for(std::size_t i = 0; i + 1 < f.size(); i++)
        if(f[i] == f[i + 1] && (inside.empty() || inside.back() != f[i]))
          inside.push_back(f[i]);
      for(std::size_t i = 0; i < inside.size(); i++)
        for(std::size_t j = i + 1; j < inside.size(); j++)
          addOverlap(inside[i], inside[j], shared);
    }
  }

  typedef std::array<std::array<double, 3>, 3> cornersByCoordinates;

  cornersByCoordinates cornersOf(const SPoint3 &a, const SPoint3 &b,
                                 const SPoint3 &c)
  {
    cornersByCoordinates t = {{{{a.x(), a.y(), a.z()}},
                               {{b.x(), b.y(), b.z()}},
                               {{c.x(), c.y(), c.z()}}}};
    std::sort(t.begin(), t.end());
    return t;
  }

  // The input's own triangles of the same three points (a sheet doubled)
  std::set<cornersByCoordinates> inputDoubledTriangles(GModel *m)
  {
    std::map<cornersByCoordinates, int> count;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      const std::vector<SPoint3> &x = (*it)->stl_vertices_xyz;
      const std::vector<int> &t = (*it)->stl_triangles;
      for(std::size_t i = 0; i + 2 < t.size(); i += 3)
        count[cornersOf(x[t[i]], x[t[i + 1]], x[t[i + 2]])]++;
    }
    std::set<cornersByCoordinates> doubled;
    for(const auto &c : count)
      if(c.second > 1) doubled.insert(c.first);
    return doubled;
  }

  // Triangles of the same three nodes in two faces (a part of three nodes:
  // no edge inside either), not where the input has two such
  void sharedTriangles(GModel *m, overlapCounts &shared)
  {
    const std::set<cornersByCoordinates> input = inputDoubledTriangles(m);
    std::map<std::array<std::size_t, 3>, GFace *> owner;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(const MTriangle *t : (*it)->triangles) {
        std::array<std::size_t, 3> n = {{t->getVertex(0)->getNum(),
                                         t->getVertex(1)->getNum(),
                                         t->getVertex(2)->getNum()}};
        std::sort(n.begin(), n.end());
        GFace *other = owner.insert(std::make_pair(n, *it)).first->second;
        if(other != *it && !input.count(cornersOf(t->getVertex(0)->point(),
                                                  t->getVertex(1)->point(),
                                                  t->getVertex(2)->point())))
          addOverlap(other, *it, shared);
      }
  }

} // namespace

std::vector<overlappingFaces> facesMeshedOntoEachOther(GModel *m)
{
  overlapCounts shared;
  sharedInnerEdges(m, shared);
  sharedTriangles(m, shared);
  std::vector<overlappingFaces> pairs;
  for(const auto &s : shared)
    pairs.push_back({s.first.first, s.first.second, s.second});
  return pairs;
}

namespace {

  bool stillOverlap(GModel *m, const overlappingFaces &p)
  {
    for(const overlappingFaces &q : facesMeshedOntoEachOther(m))
      if(q.first == p.first && q.second == p.second) return true;
    return false;
  }

  // The worst kappa of gf's input triangles
  double inputKappaMin(const GFace *gf)
  {
    const std::vector<SPoint3> &x = gf->stl_vertices_xyz;
    const std::vector<int> &t = gf->stl_triangles;
    double worst = 1.;
    for(std::size_t i = 0; i + 2 < t.size(); i += 3)
      worst = std::min(worst, triangleKappa(x[t[i]], x[t[i + 1]], x[t[i + 2]]));
    return worst;
  }

  // A face's input of slivers (sliverKappa) is no mesh to give it (a CAD
  // triangulation's fans of triangles of kappa 2e-5: bench/README.md, "Bad
  // input"); the flat pair is left, with a warning

  // Whether gf's input has a node off its boundary: one without gives the
  // same triangles between its curves' nodes (a pocket of two input
  // triangles a side)
  bool inputHasInnerNode(const GFace *gf)
  {
    const std::vector<int> &t = gf->stl_triangles;
    std::set<int> boundary, all(t.begin(), t.end());
    for(const auto &u : edgeUsesOf(t))
      if(u.second == 1) {
        boundary.insert(u.first.first);
        boundary.insert(u.first.second);
      }
    return all.size() > boundary.size();
  }

  // One face of p (the one of fewer input triangles first, not one kept
  // as its input already, nor one whose input has slivers or no node
  // inside) meshed with its input triangles, if that parts them
  bool separate(GModel *m, const overlappingFaces &p)
  {
    GFace *order[2] = {p.first, p.second};
    if(p.second->stl_triangles.size() < p.first->stl_triangles.size())
      std::swap(order[0], order[1]);
    for(int k = 0; k < 2; k++)
      if(!keptAsInput(order[k]) && inputHasInnerNode(order[k]) &&
         inputKappaMin(order[k]) >= sliverKappa &&
         meshedWithInput(order[k], order[1 - k], p.overlaps) &&
         !stillOverlap(m, p))
        return true;
    return false;
  }

} // namespace

std::size_t reparamSeparateOverlappingFaces(GModel *m, bool warn)
{
  std::size_t remeshed = 0;
  std::set<GFace *> done;
  std::vector<std::string> left;
  for(const overlappingFaces &p : facesMeshedOntoEachOther(m)) {
    if(done.count(p.first) || done.count(p.second)) continue;
    if(separate(m, p)) {
      done.insert(p.first);
      done.insert(p.second);
      remeshed++;
      continue;
    }
    left.push_back(std::to_string(p.first->tag()) + " and " +
                   std::to_string(p.second->tag()));
  }
  if(warn && !left.empty()) {
    std::string list;
    for(std::size_t i = 0; i < left.size() && i < 8; i++)
      list += (i ? ", " : "") + left[i];
    if(left.size() > 8) list += ", ...";
    Msg::Warning("Reparam: %lu pair%s of surfaces meshed onto each other (%s): "
                 "parts thinner than the mesh size, their inputs slivers or "
                 "no better; sizes below their thickness (Mesh.MeshSizeMin, "
                 "Mesh.MeshSizeFromCurvature) separate them",
                 left.size(), left.size() > 1 ? "s" : "", list.c_str());
  }
  return remeshed;
}
} // namespace reparam

