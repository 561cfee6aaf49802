// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The facets of an STL file as Gmsh reads them (hook in GModel::readSTL,
// patches/0009): a facet with a NaN or infinite coordinate made Gmsh's
// reader crash (its node search box became NaN), and a file cut short was
// refused whole. Such facets are dropped, with one warning; the others are
// read.
//
// reparamDropInvalidStlFacets takes per solid 3 corners per facet: an
// incomplete last facet (a file cut short) is dropped too, with a warning;
// a file left without any facet, or with zero-area ones only, is an error.

#include <array>
#include <cmath>
#include <map>
#include "GmshMessage.h"
#include "SBoundingBox3d.h"
#include "SVector3.h"
#include "facetOrientation.h"
#include "reparamHooks.h"
#include "reparamOptions.h"

namespace reparam {

namespace {

  bool finite(const SPoint3 &p)
  {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  }

} // namespace

} // namespace reparam

using namespace reparam;

std::size_t
reparamDropInvalidStlFacets(std::vector<std::vector<SPoint3> > &points,
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
  std::size_t left = 0, flat = 0;
  for(const std::vector<SPoint3> &solid : points)
    for(std::size_t i = 0; i + 2 < solid.size(); i += 3) {
      left++;
      const SVector3 n = crossprod(SVector3(solid[i], solid[i + 1]),
                                   SVector3(solid[i], solid[i + 2]));
      flat += !(norm(n) > 0.);
    }
  if(!left)
    Msg::Error("Reparam: the STL file has no complete facet with finite "
               "coordinates: nothing to mesh");
  else if(flat == left)
    Msg::Error("Reparam: the %lu facets of the STL file all have zero area: "
               "nothing to mesh",
               left);
  if(!dropped) return 0;
  bbox.reset();
  for(const std::vector<SPoint3> &solid : points)
    for(const SPoint3 &p : solid) bbox += p;
  Msg::Warning("Reparam: %lu STL facets with a NaN or infinite coordinate "
               "skipped",
               dropped);
  return dropped;
}

unsigned int reparamCompleteStlFacets(unsigned int facets,
                                      std::size_t bytesRead)
{
  const std::size_t complete = bytesRead / 50;
  if(complete >= facets) return facets;
  Msg::Warning("Reparam: the binary STL file is truncated: %lu of its %u "
               "facets read",
               complete, facets);
  return (unsigned int)complete;
}

std::size_t reparamOrientStlFacets(std::vector<std::vector<SPoint3> > &points)
{
  if(getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return 0;
  std::size_t reversed = 0, dropped = 0, pillows = 0;
  SPoint3 firstPillow;
  for(std::vector<SPoint3> &solid : points) {
    // the corners of neighbouring facets are written with the same
    // coordinates: nodes by exact coordinates (Gmsh merges them after)
    std::map<std::array<double, 3>, int> index;
    std::vector<std::array<int, 3> > facets(solid.size() / 3);
    for(std::size_t i = 0; i < 3 * facets.size(); i++) {
      const std::array<double, 3> key = {
        {solid[i].x(), solid[i].y(), solid[i].z()}};
      facets[i / 3][i % 3] =
        index.insert(std::make_pair(key, (int)index.size())).first->second;
    }
    const facetRepair r = orientFacets(facets);
    if(!r.reversed && !r.dropped) continue;
    if(!r.droppedPieces.empty() && !pillows)
      firstPillow = solid[3 * r.droppedPieces[0]];
    std::vector<SPoint3> kept;
    kept.reserve(solid.size());
    for(std::size_t f = 0; f < facets.size(); f++) {
      if(r.drop[f]) continue;
      const SPoint3 *c = &solid[3 * f];
      if(r.reverse[f])
        kept.insert(kept.end(), {c[0], c[2], c[1]});
      else
        kept.insert(kept.end(), {c[0], c[1], c[2]});
    }
    solid.swap(kept);
    reversed += r.reversed;
    dropped += r.dropped;
    pillows += r.droppedPieces.size();
  }
  if(pillows)
    Msg::Warning("Reparam: STL input repaired: %lu facets turned to agree "
                 "with their neighbours, %lu facets repeating another's "
                 "nodes dropped, with %lu pieces made only of facets lying "
                 "on each other (no volume), the first at (%g, %g, %g)",
                 reversed, dropped, pillows, firstPillow.x(), firstPillow.y(),
                 firstPillow.z());
  else if(reversed || dropped)
    Msg::Warning("Reparam: STL input repaired: %lu facets turned to agree "
                 "with their neighbours, %lu facets repeating another's "
                 "nodes dropped",
                 reversed, dropped);
  return reversed + dropped;
}
