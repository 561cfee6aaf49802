// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <vector>
#include <map>
#include <utility>
#include "GFace.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "faceMeshEdit.h"
#include "invertedElementRepair.h"

namespace reparam {

namespace {

  // A local change of the mesh: triangles out, triangles in (owned until
  // applied), and the new node if any
  struct localChange {
    MTriangle *out[2] = {nullptr, nullptr};
    std::vector<MTriangle *> in;
    MFaceVertex *node = nullptr;
    std::size_t bad = 0; // of `in`
    void discard()
    {
      for(MTriangle *t : in) delete t;
      delete node;
      in.clear();
      node = nullptr;
    }
  };

  double signedUvArea(GFace *gf, MVertex *a, MVertex *b, MVertex *c)
  {
    SPoint2 pa = meshNodeUv(gf, a), pb = meshNodeUv(gf, b), pc = meshNodeUv(gf, c);
    return (pb.x() - pa.x()) * (pc.y() - pa.y()) -
           (pb.y() - pa.y()) * (pc.x() - pa.x());
  }

  // The corner of t that is not a or b
  MVertex *opposite(MTriangle *t, MVertex *a, MVertex *b)
  {
    for(int k = 0; k < 3; k++)
      if(t->getVertex(k) != a && t->getVertex(k) != b) return t->getVertex(k);
    return nullptr;
  }

  // Edge (a, b) of the two triangles `pair` split at its (u, v) midpoint
  bool splitChange(GFace *gf, MVertex *a, MVertex *b, MTriangle *const *pair,
                   localChange &c)
  {
    SPoint2 ua = meshNodeUv(gf, a), ub = meshNodeUv(gf, b);
    const double u = 0.5 * (ua.x() + ub.x()), v = 0.5 * (ua.y() + ub.y());
    c.node = newFaceNode(gf, u, v);
    if(!c.node) return false;
    for(int i = 0; i < 2; i++) {
      c.out[i] = pair[i];
      splitTriangleAt(pair[i], a, b, c.node, c.in);
    }
    return true;
  }

  // Edge (a, b) of the two triangles `pair` flipped, if both new triangles
  // keep the (u, v) orientation of the old ones
  bool flipChange(GFace *gf, MVertex *a, MVertex *b, MTriangle *const *pair,
                  const std::map<meshEdgeKey, std::vector<MTriangle *> > &edges,
                  localChange &c)
  {
    MVertex *p = opposite(pair[0], a, b), *q = opposite(pair[1], a, b);
    // the new edge must not be in the mesh already (it would get four
    // triangles): possible where the (u, v) mesh folds at a boundary
    if(!p || !q || p == q || edges.count(meshEdge(p, q))) return false;
    // pair[0] in its own order: (a, b, p) or (b, a, p)
    int ia = 0;
    while(pair[0]->getVertex(ia) != a) ia++;
    const bool abp = pair[0]->getVertex((ia + 1) % 3) == b;
    MVertex *first[3] = {abp ? a : b, abp ? b : a, p};
    const double sign = signedUvArea(gf, first[0], first[1], first[2]);
    // (a, b, p) becomes (a, q, p) and (q, b, p), in the same turn
    MTriangle *t1 = new MTriangle(first[0], q, first[2]);
    MTriangle *t2 = new MTriangle(q, first[1], first[2]);
    if(signedUvArea(gf, first[0], q, first[2]) * sign <= 0. ||
       signedUvArea(gf, q, first[1], first[2]) * sign <= 0.) {
      delete t1;
      delete t2;
      return false;
    }
    c.out[0] = pair[0];
    c.out[1] = pair[1];
    c.in = {t1, t2};
    return true;
  }

  // The change around t, among the splits and flips of its inner edges,
  // that leaves the fewest triangles against the input, if fewer than the
  // two it replaces
  bool bestChange(GFace *gf, MTriangle *t,
                  std::map<meshEdgeKey, std::vector<MTriangle *> > &edges,
                  const std::function<bool(MTriangle *)> &against,
                  localChange &best)
  {
    bool found = false;
    for(int k = 0; k < 3; k++) {
      MVertex *a = t->getVertex(k), *b = t->getVertex((k + 1) % 3);
      auto it = edges.find(meshEdge(a, b));
      if(it == edges.end() || it->second.size() != 2) continue; // boundary
      MTriangle *pair[2] = {it->second[0], it->second[1]};
      const std::size_t bad = against(pair[0]) + against(pair[1]);
      for(int kind = 0; kind < 2; kind++) {
        localChange c;
        if(!(kind ? flipChange(gf, a, b, pair, edges, c) :
                    splitChange(gf, a, b, pair, c)))
          continue;
        for(MTriangle *n : c.in) c.bad += against(n);
        if(c.bad < bad && (!found || c.bad < best.bad)) {
          if(found) best.discard();
          best = c;
          found = true;
        }
        else
          c.discard();
      }
    }
    return found;
  }

  // A node of the face's mesh moved in (u, v), its triangles watched
  struct movableNode {
    GFace *gf;
    MFaceVertex *v;
    const std::vector<MTriangle *> &around;
    std::vector<double> sign; // (u, v) orientation of each, to keep

    // Moves the node to (u, v), on the surface; false where there is none
    bool place(const SPoint2 &uv)
    {
      GPoint p = gf->point(uv.x(), uv.y());
      if(!p.succeeded()) return false;
      set(uv, SPoint3(p.x(), p.y(), p.z()));
      return true;
    }
    void set(const SPoint2 &uv, const SPoint3 &xyz)
    {
      v->setParameter(0, uv.x());
      v->setParameter(1, uv.y());
      v->x() = xyz.x();
      v->y() = xyz.y();
      v->z() = xyz.z();
    }
    // Triangles around against the input, or -1 if one turned over in (u, v)
    int bad(const std::function<bool(MTriangle *)> &against) const
    {
      int n = 0;
      for(std::size_t i = 0; i < around.size(); i++) {
        MTriangle *a = around[i];
        if(signedUvArea(gf, a->getVertex(0), a->getVertex(1),
                        a->getVertex(2)) * sign[i] <= 0.)
          return -1;
        n += against(a);
      }
      return n;
    }
  };

  // Where to try the node: the (u, v) centroid of its neighbours, and
  // halfway to each of them
  std::vector<SPoint2> candidatePlaces(GFace *gf, MVertex *v,
                                       const std::vector<MTriangle *> &around)
  {
    const SPoint2 here = meshNodeUv(gf, v);
    std::vector<SPoint2> places(1, SPoint2(0., 0.));
    for(MTriangle *a : around)
      for(int j = 0; j < 3; j++) {
        if(a->getVertex(j) == v) continue;
        SPoint2 q = meshNodeUv(gf, a->getVertex(j));
        places[0] += q * (1. / (2 * around.size()));
        places.push_back((here + q) * 0.5);
      }
    return places;
  }

  // Moves the inner corners of the triangles against the input to the
  // place among candidatePlaces that leaves the fewest of their triangles
  // against the input, if fewer than now and all valid in (u, v); returns
  // the nodes moved
  std::size_t relocateCorners(GFace *gf,
                              const std::function<bool(MTriangle *)> &against)
  {
    std::map<MVertex *, std::vector<MTriangle *> > ring;
    for(MTriangle *t : gf->triangles)
      for(int k = 0; k < 3; k++) ring[t->getVertex(k)].push_back(t);
    std::size_t moved = 0;
    for(MTriangle *t : gf->triangles) {
      if(!against(t)) continue;
      for(int k = 0; k < 3; k++) {
        MFaceVertex *v = dynamic_cast<MFaceVertex *>(t->getVertex(k));
        if(!v || v->onWhat() != gf) continue; // on a curve: stays
        movableNode node{gf, v, ring[v], {}};
        for(MTriangle *a : node.around)
          node.sign.push_back(signedUvArea(gf, a->getVertex(0),
                                           a->getVertex(1), a->getVertex(2)));
        const SPoint2 start = meshNodeUv(gf, v);
        const SPoint3 startXyz = v->point();
        int best = node.bad(against), bestPlace = -1;
        std::vector<SPoint2> places = candidatePlaces(gf, v, node.around);
        for(std::size_t i = 0; i < places.size(); i++) {
          if(!node.place(places[i])) continue;
          int bad = node.bad(against);
          if(bad >= 0 && bad < best) {
            best = bad;
            bestPlace = (int)i;
          }
        }
        if(bestPlace >= 0 && node.place(places[bestPlace])) {
          moved++;
          continue;
        }
        node.set(start, startXyz); // back where it was, exactly
      }
    }
    return moved;
  }

} // namespace

invertedRepair
splitInvertedTriangles(GFace *gf, const std::function<bool(MTriangle *)> &against,
                       int maxPasses)
{
  invertedRepair r;
  for(MTriangle *t : gf->triangles) r.before += against(t);
  r.after = r.before;
  while(r.after && (int)r.passes < maxPasses) {
    r.passes++;
    std::map<meshEdgeKey, std::vector<MTriangle *> > edges = faceEdgeTriangles(gf);
    std::set<MTriangle *> removed;
    std::vector<MTriangle *> added;
    std::size_t changes = 0;
    for(MTriangle *t : gf->triangles) {
      if(removed.count(t) || !against(t)) continue;
      localChange c;
      if(!bestChange(gf, t, edges, against, c)) continue;
      if(removed.count(c.out[0]) || removed.count(c.out[1])) {
        c.discard();
        continue;
      }
      if(c.node) gf->mesh_vertices.push_back(c.node);
      for(MTriangle *o : c.out) removed.insert(o);
      added.insert(added.end(), c.in.begin(), c.in.end());
      // the new edges, for the flips that follow in this pass (the removed
      // triangles stay listed: their edges are skipped as changed)
      for(MTriangle *n : c.in)
        for(int k = 0; k < 3; k++)
          edges[meshEdge(n->getVertex(k), n->getVertex((k + 1) % 3))]
            .push_back(n);
      changes++;
    }
    r.changes += changes;
    replaceTriangles(gf, removed, added);
    const std::size_t moved = relocateCorners(gf, against);
    r.moves += moved;
    if(!changes && !moved) break;
    r.after = 0;
    for(MTriangle *t : gf->triangles) r.after += against(t);
  }
  return r;
}
} // namespace reparam

