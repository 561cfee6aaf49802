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
    if(solid.size() % 3) {
      // a file cut in the middle of a facet: its complete facets are read
      Msg::Warning("Reparam: the STL file ends in the middle of a facet: "
                   "%lu facets read",
                   kept.size() / 3);
    }
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

unsigned int reparamCompleteStlFacets(unsigned int facets, std::size_t bytesRead)
{
  const std::size_t complete = bytesRead / 50;
  if(complete >= facets) return facets;
  Msg::Warning("Reparam: the binary STL file is truncated: %lu of its %u "
               "facets read",
               complete, facets);
  return (unsigned int)complete;
}
