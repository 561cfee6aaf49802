// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include "GmshMessage.h"
#include "reparamStlInput.h"

namespace {

  bool finite(const SPoint3 &p)
  {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  }

} // namespace

std::size_t reparamDropInvalidStlFacets(std::vector<std::vector<SPoint3> > &points,
                                        SBoundingBox3d &bbox)
{
  std::size_t dropped = 0;
  for(std::vector<SPoint3> &solid : points) {
    std::vector<SPoint3> kept;
    kept.reserve(solid.size());
    for(std::size_t i = 0; i + 2 < solid.size(); i += 3) {
      if(finite(solid[i]) && finite(solid[i + 1]) && finite(solid[i + 2]))
        kept.insert(kept.end(), solid.begin() + i, solid.begin() + i + 3);
      else
        dropped++;
    }
    // a trailing incomplete facet is Gmsh's own error to report
    kept.insert(kept.end(), solid.begin() + (solid.size() / 3) * 3, solid.end());
    solid.swap(kept);
  }
  if(!dropped) return 0;
  bbox.reset();
  for(const std::vector<SPoint3> &solid : points)
    for(const SPoint3 &p : solid) bbox += p;
  Msg::Warning("Reparam: %lu STL facets with a NaN or infinite coordinate "
               "skipped",
               dropped);
  return dropped;
}
