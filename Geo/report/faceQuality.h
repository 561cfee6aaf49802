// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The shape and size measures of the mesh of a face, together (SPEC.md
// sec. 5): what the report line, the benchmarks and the plugin print.

#ifndef FACE_QUALITY_H
#define FACE_QUALITY_H

#include <cstddef>
#include <vector>

class GFace;

namespace reparam {

struct faceQuality {
  std::size_t triangles = 0, quadrangles = 0;
  double kappaMin = 0., kappaMean = 0., kappaShareBelow03 = 0.;
  double etaMin = 0., etaMean = 0.; // quadrangles only
  // Eq. (5) over the unique edges, in the size field Gmsh meshes with
  // (BGM_MeshSize: mesh size options and background field; sizes from
  // curvature, which need (u, v), are left out)
  double tau = 0.;
  std::size_t edges = 0; // unique edges tau is taken over
};

faceQuality computeFaceQuality(const std::vector<GFace *> &faces);

} // namespace reparam

#endif
