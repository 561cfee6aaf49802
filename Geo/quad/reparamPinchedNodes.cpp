// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include "GEdge.h"
#include "GFace.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "pinchedNodes.h"
#include "quadQuality.h"
#include "reparamFaceEdits.h"
#include "reparamPinchedNodes.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  // Where an element of the joined mesh is in its face
  struct elementPlace {
    GFace *face;
    bool quadrangle;
    std::size_t index; // into the face's triangles or quadrangles
  };

  // The faces' elements as one mesh: every face's triangles, then every
  // face's quadrangles, in the mesh's order of elements
  struct joinedMesh {
    surfaceMesh mesh;
    std::vector<MVertex *> nodes;
    std::vector<elementPlace> places;
  };

  joinedMesh joinedMeshOf(const std::vector<GFace *> &faces)
  {
    joinedMesh j;
    j.mesh = reparamMeshOfFaces(faces, j.nodes);
    for(GFace *gf : faces)
      for(std::size_t i = 0; i < gf->triangles.size(); i++)
        j.places.push_back({gf, false, i});
    for(GFace *gf : faces)
      for(std::size_t i = 0; i < gf->quadrangles.size(); i++)
        j.places.push_back({gf, true, i});
    return j;
  }

  // An inner node of one of the faces, or a node of one of the cuts
  // between them: only their elements have it
  bool removable(MVertex *v, const std::set<GFace *> &faces,
                 const std::set<GEdge *> &cuts)
  {
    GEntity *e = v->onWhat();
    if(e->dim() == 2) return faces.count((GFace *)e) > 0;
    if(e->dim() != 1 || !cuts.count((GEdge *)e)) return false;
    for(GFace *gf : ((GEdge *)e)->faces())
      if(!faces.count(gf)) return false;
    return true;
  }

  // Whether each triangle left of p's quadrangles points the way the
  // quadrangle did
  bool keepsItsWay(const joinedMesh &j, const pinchedNode &p)
  {
    const std::vector<SPoint3> &x = j.mesh.points;
    for(std::size_t k = 0; k < p.triangles.size(); k++) {
      const int e = p.elements[p.from[k]] - (int)j.mesh.triangles.size();
      const SVector3 was = quadNormal(j.mesh.quadrangles[e], x);
      const std::array<int, 3> &t = p.triangles[k];
      const SVector3 now =
        crossprod(SVector3(x[t[0]], x[t[1]]), SVector3(x[t[0]], x[t[2]]));
      if(!(dot(was, now) > 0.)) return false;
    }
    return true;
  }

  // ge's two segments at v become one
  void joinSegmentsAt(GEdge *ge, MVertex *v)
  {
    int into = -1, from = -1; // v's segment ending at it, starting at it
    for(std::size_t i = 0; i < ge->lines.size(); i++) {
      if(ge->lines[i]->getVertex(1) == v) into = (int)i;
      if(ge->lines[i]->getVertex(0) == v) from = (int)i;
    }
    if(into >= 0 && from >= 0) {
      MLine *joined =
        new MLine(ge->lines[into]->getVertex(0), ge->lines[from]->getVertex(1));
      delete ge->lines[into];
      delete ge->lines[from];
      ge->lines[std::min(into, from)] = joined;
      ge->lines.erase(ge->lines.begin() + std::max(into, from));
    }
    ge->deleteVertexArrays();
  }

  // v out of its entity's nodes (and its curve's segments), then deleted
  void removeNode(MVertex *v)
  {
    GEntity *e = v->onWhat();
    if(e->dim() == 1) joinSegmentsAt((GEdge *)e, v);
    std::vector<MVertex *> &own = e->mesh_vertices;
    own.erase(std::remove(own.begin(), own.end(), v), own.end());
    delete v;
  }

} // namespace

std::size_t reparamRemovePinchedNodes(const std::vector<GFace *> &faces,
                                      const std::set<GEdge *> &cuts,
                                      std::set<GFace *> &changed)
{
  const joinedMesh j = joinedMeshOf(faces);
  const std::set<GFace *> faceSet(faces.begin(), faces.end());
  std::vector<bool> canGo(j.nodes.size());
  for(std::size_t i = 0; i < j.nodes.size(); i++)
    canGo[i] = removable(j.nodes[i], faceSet, cuts);
  std::map<GFace *, std::vector<bool> > trianglesGone, quadranglesGone;
  for(GFace *gf : faces) {
    trianglesGone[gf].assign(gf->triangles.size(), false);
    quadranglesGone[gf].assign(gf->quadrangles.size(), false);
  }
  std::vector<MVertex *> gone;
  std::vector<std::pair<GFace *, MTriangle *> > added;
  for(const pinchedNode &p : pinchedNodes(j.mesh, canGo)) {
    if(!keepsItsWay(j, p)) continue;
    for(int e : p.elements) {
      const elementPlace &at = j.places[e];
      (at.quadrangle ? quadranglesGone : trianglesGone)[at.face][at.index] =
        true;
      changed.insert(at.face);
    }
    for(std::size_t k = 0; k < p.triangles.size(); k++) {
      const std::array<int, 3> &t = p.triangles[k];
      added.push_back(std::make_pair(
        j.places[p.elements[p.from[k]]].face,
        new MTriangle(j.nodes[t[0]], j.nodes[t[1]], j.nodes[t[2]])));
    }
    gone.push_back(j.nodes[p.node]);
  }
  if(gone.empty()) return 0;
  for(GFace *gf : faces) {
    reparamDropMarked(gf->triangles, trianglesGone[gf]);
    reparamDropMarked(gf->quadrangles, quadranglesGone[gf]);
  }
  for(auto &a : added) a.first->triangles.push_back(a.second);
  for(MVertex *v : gone) removeNode(v);
  for(GFace *gf : changed) gf->deleteVertexArrays();
  Msg::Info("Reparam: surface%s %s: %lu pinched node%s removed (two "
            "elements sharing both its edges, folded onto each other or "
            "lying on each other)",
            faces.size() > 1 ? "s" : "", reparamTagList(faces).c_str(),
            gone.size(), gone.size() > 1 ? "s" : "");
  return gone.size();
}
} // namespace reparam

