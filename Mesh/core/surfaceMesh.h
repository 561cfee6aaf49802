// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A surface mesh as plain arrays: nodes, triangles and quadrangles by node
// index. The one mesh type the stages pass each other (an input
// triangulation, a face's new mesh, a layout's triangles); what a stage adds
// to it (topology, per-node data) lives beside it, not in a copy of it.

#ifndef SURFACE_MESH_H
#define SURFACE_MESH_H

#include <array>
#include <vector>
#include "SPoint3.h"

namespace reparam {

struct surfaceMesh {
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > triangles;
  std::vector<std::array<int, 4> > quadrangles;
  std::size_t numElements() const
  {
    return triangles.size() + quadrangles.size();
  }
};

} // namespace reparam

#endif
