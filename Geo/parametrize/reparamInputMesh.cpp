// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include <cstdint>
#include <mutex>
#include <set>
#include <unordered_map>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GVertex.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "SBoundingBox3d.h"
#include "boundaryStitch.h"
#include "meshFidelity.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamOptions.h"
#include "reparamParametrize.h"
#include "reparamState.h"
#include "reparamSurfaceMesh.h"

namespace reparam {

namespace {

  // A curve's or a corner's label for boundaryStitch (0: the face)
  int label(const GEntity *ge)
  {
    if(!ge) return 0;
    if(ge->dim() == 1) return 2 * ge->tag();
    if(ge->dim() == 0) return 2 * ge->tag() + 1;
    return 0;
  }

  // A curve's node goes to the curve or its ends, a corner's to the corner
  std::vector<int> labelsOfNode(const MVertex *v)
  {
    GEntity *ge = v->onWhat();
    std::vector<int> labels = {label(ge)};
    if(ge && ge->dim() == 1) {
      GEdge *edge = static_cast<GEdge *>(ge);
      for(GVertex *gv : {edge->getBeginVertex(), edge->getEndVertex()})
        if(gv) labels.push_back(label(gv));
    }
    return labels;
  }

  bool isFinite(const SPoint3 &p)
  {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  }

  // A node with a NaN or infinite coordinate goes to the mean of its finite
  // neighbours; the triangles of one with none are left out (counted)
  void repairInvalidPoints(inputTriangulation &input)
  {
    std::vector<SPoint3> sum(input.points.size(), SPoint3(0., 0., 0.));
    std::vector<int> count(input.points.size(), 0);
    for(const auto &t : input.triangles)
      for(int j = 0; j < 3; j++)
        for(int k = 0; k < 3; k++)
          if(k != j && !isFinite(input.points[t[j]]) &&
             isFinite(input.points[t[k]])) {
            sum[t[j]] += input.points[t[k]];
            count[t[j]]++;
          }
    for(std::size_t i = 0; i < input.points.size(); i++)
      if(!isFinite(input.points[i]) && count[i])
        input.points[i] = sum[i] * (1. / count[i]);
    std::vector<std::array<int, 3> > valid;
    for(const auto &t : input.triangles) {
      if(isFinite(input.points[t[0]]) && isFinite(input.points[t[1]]) &&
         isFinite(input.points[t[2]]))
        valid.push_back(t);
      else
        input.leftOut++;
    }
    input.triangles.swap(valid);
  }

  inputTriangulation copyOfTriangles(GFace *gf)
  {
    inputTriangulation input;
    std::unordered_map<const MVertex *, int> index;
    for(MTriangle *t : gf->triangles) {
      std::array<int, 3> tri;
      for(int j = 0; j < 3; j++) {
        const MVertex *v = t->getVertex(j);
        auto it = index.insert({v, (int)input.points.size()});
        if(it.second) {
          input.points.push_back(v->point());
          input.labels.push_back(label(v->onWhat()));
        }
        tri[j] = it.first->second;
      }
      input.triangles.push_back(tri);
    }
    repairInvalidPoints(input);
    return input;
  }

  // The nodes of the 1D meshes around gf, each once
  std::vector<MVertex *> curveNodes(GFace *gf)
  {
    std::vector<MVertex *> nodes;
    std::set<MVertex *> seen;
    auto add = [&](MVertex *v) {
      if(seen.insert(v).second) nodes.push_back(v);
    };
    std::vector<GEdge *> edges = gf->edges();
    std::vector<GEdge *> embedded = gf->getEmbeddedEdges();
    edges.insert(edges.end(), embedded.begin(), embedded.end());
    for(GEdge *ge : edges) {
      for(GVertex *gv : {ge->getBeginVertex(), ge->getEndVertex()})
        if(gv)
          for(MVertex *v : gv->mesh_vertices) add(v);
      for(MVertex *v : ge->mesh_vertices) add(v);
    }
    return nodes;
  }

  // gf's mesh: the stitched triangles, on new nodes for the input's inner
  // nodes and on the curves' nodes for the others
  void addTriangles(GFace *gf, const inputTriangulation &input,
                    const stitchedTriangulation &stitched,
                    const std::vector<MVertex *> &onCurves)
  {
    gf->deleteMesh();
    const std::size_t numInput = input.points.size();
    std::vector<MVertex *> nodes(numInput, nullptr);
    for(const auto &t : stitched.triangles) {
      MVertex *v[3];
      for(int j = 0; j < 3; j++) {
        const std::size_t n = t[j];
        if(n >= numInput) {
          v[j] = onCurves[n - numInput];
          continue;
        }
        if(!nodes[n]) {
          const SPoint3 &p = input.points[n];
          nodes[n] = new MVertex(p.x(), p.y(), p.z(), gf);
          gf->mesh_vertices.push_back(nodes[n]);
        }
        v[j] = nodes[n];
      }
      gf->triangles.push_back(new MTriangle(v[0], v[1], v[2]));
    }
  }

  // gf's input stitched to the nodes of its curves' 1D meshes (returned in
  // `boundary`), told apart by curve where the input has labels
  stitchedTriangulation stitchToCurves(GFace *gf,
                                       const inputTriangulation &input,
                                       std::vector<MVertex *> &boundary)
  {
    boundary = curveNodes(gf);
    std::vector<SPoint3> points;
    std::vector<std::vector<int> > labels;
    for(MVertex *v : boundary) {
      points.push_back(v->point());
      if(!input.labels.empty()) labels.push_back(labelsOfNode(v));
    }
    SBoundingBox3d box;
    for(const SPoint3 &p : input.points) box += p;
    // the curves' nodes lie on the input's boundary edges to rounding
    return stitchToBoundaryNodes(input.points, input.triangles, points,
                                 1e-6 * box.diag(), input.labels, labels);
  }

  // gf's mesh: the stitched triangles (addTriangles), meshed
  void meshWithStitched(GFace *gf, const inputTriangulation &input,
                        const stitchedTriangulation &stitched,
                        const std::vector<MVertex *> &boundary)
  {
    addTriangles(gf, input, stitched, boundary);
    gf->meshStatistics.status = GFace::DONE;
    gf->meshStatistics.nbTriangle = gf->triangles.size();
  }

} // namespace

} // namespace reparam

using namespace reparam;

bool reparamTakesPoorInput(GFace *gf, double minGamma)
{
  if(getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return false;
  Msg::Info("Reparam: surface %d: input triangles of gamma down to %g, "
            "parametrized all the same",
            gf->tag(), minGamma);
  return true;
}

void reparamBeginFaceGeometry(GFace *gf) { beginFaceRecord(gf); }

bool reparamKeepInputMesh(GFace *gf)
{
  const std::string reason = reparamLastFailure(gf);
  if(getReparamOptions().parametrization ==
       (int)compoundParametrization::gmsh ||
     gf->triangles.empty())
    return false;
  inputTriangulation copy = copyOfTriangles(gf);
  std::unique_lock<std::mutex> lock = lockRecords();
  // (a record stays where it is while others come and go)
  const inputTriangulation &input =
    *(faceRecordOf(gf).keptInput = std::move(copy));
  lock.unlock();
  std::string leftOut;
  if(input.leftOut)
    leftOut = " (" + std::to_string(input.leftOut) +
              " with invalid coordinates left out)";
  Msg::Warning("Reparam: surface %d cannot be parametrized (%s): its %lu "
               "input triangles are kept in the mesh%s",
               gf->tag(), reason.c_str(), input.triangles.size(),
               leftOut.c_str());
  return true;
}

namespace reparam {

bool keptAsInput(const GFace *gf)
{
  // faces are meshed in parallel (OpenMP builds), and a face's fallback to
  // its input (reparamMeshFaceWithItsInput) records it while another
  // face's optimization asks
  std::unique_lock<std::mutex> lock = lockRecords();
  const faceRecord *r = findFaceRecord(gf);
  if(!r) return false;
  if(r->keptInput) return true;
  if(!r->meshedWithInput) return false;
  // kept as input while the mesh made of it is gf's
  GFace *f = const_cast<GFace *>(gf);
  return f->getNumMeshElements() == r->meshedWithInput->elements &&
         f->getNumMeshElements() &&
         f->getMeshElement(0) == r->meshedWithInput->first;
}

bool reparamMeshFaceWithItsInput(GFace *gf, std::size_t against,
                                 const std::string &reason)
{
  if(gf->stl_triangles.empty() || !gf->quadrangles.empty()) return false;
  inputTriangulation input;
  static_cast<surfaceMesh &>(input) = inputTriangulationOf(gf);
  std::vector<MVertex *> boundary;
  const stitchedTriangulation stitched = stitchToCurves(gf, input, boundary);
  // (SIZE_MAX: gf has no other mesh, its stitching may turn triangles)
  if(stitched.unplacedNodes || stitched.keptInputNodes ||
     (stitched.turnedTriangles && against != SIZE_MAX) ||
     stitched.triangles.empty())
    return false;
  // no more triangles against the input than the planar mesh kept (where
  // the input itself folds, the test finds its own triangles against it;
  // the planar mesh would go to MeshAdapt, which leaves more)
  surfaceMesh candidate;
  candidate.points = input.points;
  for(MVertex *v : boundary) candidate.points.push_back(v->point());
  candidate.triangles = stitched.triangles;
  if(countInverted(input, candidate) > against) return false;
  meshWithStitched(gf, input, stitched, boundary);
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    faceRecordOf(gf).meshedWithInput =
      meshIdentity{gf->getNumMeshElements(), gf->getMeshElement(0)};
  }
  Msg::Warning("Reparam: surface %d meshed with its %lu input triangles, "
               "stitched to its curves: %s",
               gf->tag(), input.triangles.size(), reason.c_str());
  return true;
}

bool reparamMeshFaceWithItsInput(GFace *gf, std::size_t against)
{
  if(!against) return false;
  return reparamMeshFaceWithItsInput(
    gf, against,
    "its planar mesh kept " + std::to_string(against) +
      " triangles against the input (a fold of the input, or a strip "
      "narrower than the mesh size)");
}

} // namespace reparam

bool reparamMeshFromInput(GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  const faceRecord *r = findFaceRecord(gf);
  if(!r || !r->keptInput || gf->haveParametrization()) return false;
  // (a record stays where it is while others come and go)
  const inputTriangulation &input = *r->keptInput;
  lock.unlock();
  std::vector<MVertex *> boundary;
  const stitchedTriangulation stitched = stitchToCurves(gf, input, boundary);
  meshWithStitched(gf, input, stitched, boundary);
  if(stitched.unplacedNodes || stitched.keptInputNodes)
    Msg::Info("Reparam: surface %d: %lu nodes of its curves off its input "
              "boundary, %lu input boundary nodes kept",
              gf->tag(), stitched.unplacedNodes, stitched.keptInputNodes);
  Msg::Info("Reparam: surface %d meshed with its %lu input triangles, "
            "stitched to its curves (%lu triangles, %lu turned)",
            gf->tag(), input.triangles.size(), gf->triangles.size(),
            stitched.turnedTriangles);
  return true;
}

namespace reparam {

std::vector<int> facesKeptAsInput(GModel *m)
{
  std::vector<int> tags;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it)
    if(keptAsInput(*it) && (*it)->getNumMeshElements())
      tags.push_back((*it)->tag());
  return tags;
}
} // namespace reparam

