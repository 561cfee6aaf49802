// Reparam - a libFuzzer target (scripts/fuzz.sh): any bytes as a binary STL
// file through Reparam's reading path (complete facets of a file cut short,
// non-finite facets dropped, facets oriented and repeated ones dropped),
// then the patch layout of the facets (feature patches, noise merged,
// parts cut until each one's automatic map chain is one-to-one, the
// bijectivity checks included). Nothing may crash, hang or read out of
// bounds, whatever the file says.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>
#include "GmshGlobal.h"
#include "GmshMessage.h"
#include "SBoundingBox3d.h"
#include "discretePatch.h"
#include "edgeUses.h"
#include "mapChain.h"
#include "patchLayout.h"
#include "reparamHooks.h"

using namespace reparam;

namespace {

  // Facets read from the bytes as Gmsh's binary reader does: an 80-byte
  // header, a facet count, 50 bytes per facet (a normal, three corners, an
  // attribute), as many as are complete
  std::vector<SPoint3> readFacets(const uint8_t *data, std::size_t size)
  {
    std::vector<SPoint3> corners;
    if(size < 84) return corners;
    uint32_t count;
    std::memcpy(&count, data + 80, 4);
    const unsigned facets = reparamCompleteStlFacets(count, size - 84);
    for(unsigned f = 0; f < facets && 84 + 50 * (f + 1) <= size; f++) {
      float x[12];
      std::memcpy(x, data + 84 + 50 * f, sizeof(x));
      for(int k = 0; k < 3; k++)
        corners.push_back(SPoint3(x[3 + 3 * k], x[4 + 3 * k], x[5 + 3 * k]));
    }
    return corners;
  }

  // The facets as a layout mesh: corners welded by their coordinates, the
  // edges used once or more than twice as feature edges
  layoutMesh weld(const std::vector<SPoint3> &corners)
  {
    layoutMesh m;
    std::map<std::array<double, 3>, int> index;
    for(std::size_t i = 0; i + 2 < corners.size(); i += 3) {
      std::array<int, 3> t;
      for(int k = 0; k < 3; k++) {
        const SPoint3 &p = corners[i + k];
        const std::array<double, 3> key = {{p.x(), p.y(), p.z()}};
        auto it = index.find(key);
        if(it == index.end()) {
          it = index.insert({key, (int)m.points.size()}).first;
          m.points.push_back(p);
        }
        t[k] = it->second;
      }
      if(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) m.triangles.push_back(t);
    }
    for(const auto &e : edgeUsesOf(m.triangles))
      if(e.second != 2)
        m.featureEdges.push_back({{e.first.first, e.first.second}});
    return m;
  }

  // The layout's verification: the part's automatic map chain one-to-one
  partCheck verify(const layoutMesh &m, const std::vector<int> &part)
  {
    partCheck check;
    std::vector<std::array<int, 3> > triangles;
    for(int t : part) triangles.push_back(m.triangles[t]);
    discretePatch patch;
    const reparamError error = makeDiscretePatch(m.points, triangles, patch);
    if(!error.ok()) {
      check.ok = false;
      check.reason = "patch";
      return check;
    }
    const checkedMap map = runMapChain(patch, mapChain(6), true);
    check.ok = map.bijective;
    if(!check.ok) check.reason = "map";
    return check;
  }

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  GmshInitialize();
  Msg::SetVerbosity(0); // the warnings of every input would slow it down
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, std::size_t size)
{
  std::vector<std::vector<SPoint3> > solids = {readFacets(data, size)};
  SBoundingBox3d box;
  for(const SPoint3 &p : solids[0]) box += p;
  reparamDropInvalidStlFacets(solids, box);
  reparamOrientStlFacets(solids);
  const layoutMesh m = weld(solids[0]);
  if(m.triangles.empty()) return 0;
  layoutParameters parameters;
  parameters.maxDepth = 6; // bounded work per input
  computePatchLayout(m, parameters, [&](const std::vector<int> &part) {
    return verify(m, part);
  });
  return 0;
}
