// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Small edits of a face's new mesh through its parametrization, shared by
// the local repairs run after the planar mesher (a node added at a (u, v)
// point lies on the surface; triangles replaced in the face's list).

#ifndef FACE_MESH_EDIT_H
#define FACE_MESH_EDIT_H

#include <map>
#include <set>
#include <utility>
#include <vector>
#include "SPoint2.h"

class GFace;
class MFaceVertex;
class MTriangle;
class MVertex;

namespace reparam {

typedef std::pair<MVertex *, MVertex *> meshEdgeKey;
inline meshEdgeKey meshEdge(MVertex *a, MVertex *b)
{
  return a < b ? meshEdgeKey(a, b) : meshEdgeKey(b, a);
}

// The (u, v) of a node of gf's mesh (on gf, or on one of its curves)
SPoint2 meshNodeUv(GFace *gf, MVertex *v);

// The triangles of gf around each of its mesh edges
std::map<meshEdgeKey, std::vector<MTriangle *> > faceEdgeTriangles(GFace *gf);

// A node of gf at (u, v), on the surface; null where gf has no point
MFaceVertex *newFaceNode(GFace *gf, double u, double v);

// The two halves of t (corners a and b, edge ab split at m), in t's turn
void splitTriangleAt(MTriangle *t, MVertex *a, MVertex *b, MVertex *m,
                     std::vector<MTriangle *> &halves);

// gf's triangles without `removed` (deleted) and with `added`
void replaceTriangles(GFace *gf, const std::set<MTriangle *> &removed,
                      const std::vector<MTriangle *> &added);

} // namespace reparam

#endif
