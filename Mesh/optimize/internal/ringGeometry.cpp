// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "ringGeometry.h"

namespace reparam::optimizeInternal {

SVector3 ringNormal(const std::vector<SPoint3> &points,
                    const std::vector<std::array<int, 3> > &triangles,
                    const std::vector<int> &ring)
{
  SVector3 normal(0., 0., 0.);
  for(int t : ring) {
    const std::array<int, 3> &c = triangles[t];
    normal += crossprod(SVector3(points[c[0]], points[c[1]]),
                        SVector3(points[c[0]], points[c[2]]));
  }
  return normal;
}

} // namespace reparam::optimizeInternal
