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

#include <algorithm>
#include <array>
#include <cmath>
#include "GmshMessage.h"
#include "SBoundingBox3d.h"
#include "SVector3.h"
#include "facetOrientation.h"
#include "flatPieces.h"
#include "reparamHooks.h"
#include "reparamOptions.h"

namespace reparam {

namespace {

  bool finite(const SPoint3 &p)
  {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  }

  // A solid's facets as node indices, its nodes and its repair
  struct stlSolid {
    std::vector<std::array<double, 3> > nodes;
    std::vector<std::array<int, 3> > facets;
    facetRepair repair;
  };

  // The corners of neighbouring facets are written with the same
  // coordinates: nodes by exact coordinates (Gmsh merges them after)
  void indexCorners(const std::vector<SPoint3> &corners, stlSolid &solid)
  {
    // the corners sorted by their coordinates, equal ones together in their
    // order in the file; nodes numbered in order of first appearance, with
    // the coordinates of that appearance: a sort of a flat array, not a
    // tree of a node per corner
    solid.facets.resize(corners.size() / 3);
    const std::size_t n = 3 * solid.facets.size();
    auto key = [&corners](std::size_t i) {
      return std::array<double, 3>{
        {corners[i].x(), corners[i].y(), corners[i].z()}};
    };
    std::vector<int> order(n);
    for(std::size_t i = 0; i < n; i++) order[i] = (int)i;
    std::stable_sort(order.begin(), order.end(),
                     [&key](int a, int b) { return key(a) < key(b); });
    // first[i]: the first corner (in the file) with i's coordinates
    std::vector<int> first(n);
    for(std::size_t k = 0; k < n; k++)
      first[order[k]] = k && !(key(order[k - 1]) < key(order[k])) ?
                          first[order[k - 1]] :
                          order[k];
    std::vector<int> node(n, -1);
    for(std::size_t i = 0; i < n; i++) {
      int &id = node[first[i]];
      if(id < 0) {
        id = (int)solid.nodes.size();
        solid.nodes.push_back(key(i));
      }
      solid.facets[i / 3][i % 3] = id;
    }
  }

  // The facets as the repair turns them (the volume of a piece needs them
  // consistent)
  void turnFacets(stlSolid &solid)
  {
    for(std::size_t f = 0; f < solid.facets.size(); f++)
      if(solid.repair.reverse[f])
        std::swap(solid.facets[f][1], solid.facets[f][2]);
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
  std::vector<stlSolid> solids(points.size());
  double area = 0.;
  std::size_t count = 0;
  for(std::size_t s = 0; s < points.size(); s++) {
    indexCorners(points[s], solids[s]);
    solids[s].repair = orientFacets(solids[s].facets);
    turnFacets(solids[s]);
    std::size_t n = 0;
    area +=
      facetArea(solids[s].nodes, solids[s].facets, solids[s].repair.drop, n);
    count += n;
  }
  // the layout's noise size: pieces smaller than it are below the input's
  // own triangles
  const double size =
    getReparamOptions().noiseSize > 0. ?
      getReparamOptions().noiseSize :
      (count ? std::sqrt(4. * area / (std::sqrt(3.) * count)) : 0.);
  std::size_t reversed = 0, dropped = 0, pieces = 0;
  SPoint3 firstPiece;
  for(std::size_t s = 0; s < points.size(); s++) {
    stlSolid &solid = solids[s];
    facetRepair &r = solid.repair;
    const flatPieceDrop flat =
      findFlatPieces(solid.nodes, solid.facets, r.drop, size);
    if(!r.reversed && !r.dropped && !flat.dropped) continue;
    std::vector<int> gone = r.droppedPieces;
    gone.insert(gone.end(), flat.pieces.begin(), flat.pieces.end());
    if(!gone.empty() && !pieces) firstPiece = points[s][3 * gone[0]];
    std::vector<SPoint3> kept;
    kept.reserve(points[s].size());
    for(std::size_t f = 0; f < solid.facets.size(); f++) {
      if(r.drop[f] || flat.drop[f]) continue;
      const SPoint3 *c = &points[s][3 * f];
      if(r.reverse[f])
        kept.insert(kept.end(), {c[0], c[2], c[1]});
      else
        kept.insert(kept.end(), {c[0], c[1], c[2]});
    }
    points[s].swap(kept);
    reversed += r.reversed;
    dropped += r.dropped + flat.dropped;
    pieces += gone.size();
  }
  if(pieces)
    Msg::Warning("Reparam: STL input repaired: %lu facets turned to agree "
                 "with their neighbours, %lu facets dropped (repeating "
                 "another's nodes, or of %lu closed pieces without volume: "
                 "facets lying on each other, or thinner than a hundredth of "
                 "their extent and smaller than the input's triangles), the "
                 "first piece at (%g, %g, %g)",
                 reversed, dropped, pieces, firstPiece.x(), firstPiece.y(),
                 firstPiece.z());
  else if(reversed || dropped)
    Msg::Warning("Reparam: STL input repaired: %lu facets turned to agree "
                 "with their neighbours, %lu facets repeating another's "
                 "nodes dropped",
                 reversed, dropped);
  return reversed + dropped;
}
