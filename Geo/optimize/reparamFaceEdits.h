// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What the steps that edit the faces' meshes after Mesh2D share (the
// optimization across the cuts, the quadrangle steps, the pinched nodes,
// the elements split again): the faces named in their log lines, the
// faces' elements as one indexed mesh, elements taken out of a face.

#ifndef REPARAM_FACE_EDITS_H
#define REPARAM_FACE_EDITS_H

#include <string>
#include <vector>

class GFace;
class MVertex;

namespace reparam {
struct surfaceMesh;

// "2, 3, 5": the faces' tags, for a log line
std::string reparamTagList(const std::vector<GFace *> &faces);

// The faces' elements as one mesh: every face's triangles, then every
// face's quadrangles, each face's in its own order; nodes[i] is point i's
// node
surfaceMesh reparamMeshOfFaces(const std::vector<GFace *> &faces,
                               std::vector<MVertex *> &nodes);

// The elements marked in `gone` deleted and taken out of `elements` (a
// face's triangles or quadrangles), the others kept in their order
template <class T>
void reparamDropMarked(std::vector<T *> &elements,
                       const std::vector<bool> &gone)
{
  std::vector<T *> kept;
  for(std::size_t i = 0; i < elements.size(); i++)
    if(gone[i])
      delete elements[i];
    else
      kept.push_back(elements[i]);
  elements.swap(kept);
}

} // namespace reparam

#endif
