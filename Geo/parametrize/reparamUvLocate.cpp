// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Where a point of the (u, v) plane lies on a discrete face whose (u, v)
// image is not convex. Gmsh's planar meshers mesh the polygon of the face's
// boundary nodes; on the free boundary of a conformal map that polygon's
// chords cut across concave stretches of the image, so the mesher asks for
// points, normals and derivatives just outside the parametrized triangles.
// Gmsh's discreteFace answered "not found" (with an arbitrary normal), which
// made Frontal-Delaunay's mesh invalid and Gmsh throw it away for MeshAdapt
// (bench/README.md, Points just outside the (u, v) triangles). The hook
// (patches/0007) takes such points on the closest triangle instead.
//
// The points inside are located by a tree of the (u, v) triangles' boxes
// (Mesh/core/uvTriangleTree.h) in place of Gmsh's octree (patches/0021), built
// with the face's parametrization when Reparam's maps are on; Gmsh's own
// map (Mesh.CompoundParametrization = 0) keeps the octree.

#include <algorithm>
#include <cstring>
#include <map>
#include <mutex>
#include <unordered_map>
#include "MElementOctree.h"
#include "MTriangle.h"
#include "SPoint2.h"
#include "SPoint3.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "uvTriangleTree.h"

namespace reparam {

namespace {

  // A point's coordinates, bit for bit
  struct pointKey {
    double x[3];
    bool operator==(const pointKey &o) const
    {
      return std::memcmp(x, o.x, sizeof(x)) == 0;
    }
  };
  struct pointKeyHash {
    std::size_t operator()(const pointKey &k) const
    {
      std::size_t h = 0;
      for(double c : k.x) h = h * 1000003u ^ std::hash<double>()(c);
      return h;
    }
  };

  // the (u, v) of points asked again and again: the curves' nodes
  const std::size_t maxCachedPoints = 1000000;

} // namespace

} // namespace reparam

using namespace reparam;

class reparamUvLocator {
public:
  explicit reparamUvLocator(const std::vector<std::array<double, 6> > &c)
    : tree(c)
  {
  }
  uvTriangleTree tree;
  // parFromPoint's answers; a face may be asked from several threads
  // (the optimization, the report) once it is meshed
  mutable std::mutex guard;
  mutable std::unordered_map<pointKey, SPoint2, pointKeyHash> uvOf;
};

reparamUvLocator *reparamNewUvLocator(const std::vector<MTriangle> &t2d)
{
  if(getReparamOptions().parametrization <= 0 || t2d.empty()) return nullptr;
  std::vector<std::array<double, 6> > corners(t2d.size());
  for(std::size_t i = 0; i < t2d.size(); i++)
    for(int k = 0; k < 3; k++) {
      // the (u, v) of a parametrized node are its x and y
      corners[i][2 * k] = t2d[i].getVertex(k)->x();
      corners[i][2 * k + 1] = t2d[i].getVertex(k)->y();
    }
  return new reparamUvLocator(corners);
}

void reparamDeleteUvLocator(reparamUvLocator *locator) { delete locator; }

MElement *reparamFindUvTriangle(const reparamUvLocator *locator,
                                const MElementOctree *octree,
                                const std::vector<MTriangle> &t2d, double u,
                                double v)
{
  if(!locator) return octree ? octree->find(u, v, 0.0, -1, true) : nullptr;
  // the triangle found last, per thread (faces are meshed in parallel),
  // tried first: a mesher's next query is often in it (a search hint of
  // this thread's mesher, not a face's record: stays here, not in
  // Geo/core/reparamState.h)
  thread_local const reparamUvLocator *lastLocator = nullptr;
  thread_local int last = -1;
  const int t = locator->tree.find(u, v, lastLocator == locator ? last : -1);
  lastLocator = locator;
  last = t;
  return t < 0 ? nullptr : const_cast<MTriangle *>(&t2d[t]);
}

namespace reparam {

namespace {

  // The boundary triangles of the last triangulation asked about (a face is
  // meshed at once, so the cache hits); one per thread, as faces may be
  // meshed in parallel (a cache of this thread's searches: stays here, not
  // in Geo/core/reparamState.h)
  struct boundaryCache {
    const MTriangle *data = nullptr;
    std::size_t size = 0;
    std::vector<int> boundary;
  };

  std::vector<int> boundaryTriangles(const std::vector<MTriangle> &t2d)
  {
    std::map<std::pair<const MVertex *, const MVertex *>, int> count;
    auto key = [](const MVertex *a, const MVertex *b) {
      return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    };
    for(const MTriangle &t : t2d)
      for(int k = 0; k < 3; k++)
        count[key(t.getVertex(k), t.getVertex((k + 1) % 3))]++;
    std::vector<int> boundary;
    for(std::size_t i = 0; i < t2d.size(); i++)
      for(int k = 0; k < 3; k++)
        if(count[key(t2d[i].getVertex(k), t2d[i].getVertex((k + 1) % 3))] ==
           1) {
          boundary.push_back((int)i);
          break;
        }
    return boundary;
  }

  // Closest point to (u, v) on segment (a, b); squared distance
  double closestOnSegment(double u, double v, double ax, double ay, double bx,
                          double by, double &cu, double &cv)
  {
    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    double s = len2 > 0. ? ((u - ax) * dx + (v - ay) * dy) / len2 : 0.;
    s = std::min(1., std::max(0., s));
    cu = ax + s * dx;
    cv = ay + s * dy;
    return (u - cu) * (u - cu) + (v - cv) * (v - cv);
  }

} // namespace

} // namespace reparam

MTriangle *reparamClosestUvTriangle(const std::vector<MTriangle> &t2d,
                                    double &u, double &v)
{
  if(t2d.empty()) return nullptr;
  thread_local boundaryCache cache;
  if(cache.data != t2d.data() || cache.size != t2d.size()) {
    cache.data = t2d.data();
    cache.size = t2d.size();
    cache.boundary = boundaryTriangles(t2d);
  }
  // a point outside the image is closest to a boundary edge, hence to a
  // boundary triangle (a point on its other edges is inside or on another
  // boundary triangle's edge)
  double best = 1e300, bu = u, bv = v;
  int bestTriangle = -1;
  for(int i : cache.boundary) {
    const MTriangle &t = t2d[i];
    for(int k = 0; k < 3; k++) {
      const MVertex *a = t.getVertex(k), *b = t.getVertex((k + 1) % 3);
      double cu, cv;
      double d = closestOnSegment(u, v, a->x(), a->y(), b->x(), b->y(), cu, cv);
      if(d < best) {
        best = d;
        bu = cu;
        bv = cv;
        bestTriangle = i;
      }
    }
  }
  if(bestTriangle < 0) return nullptr;
  u = bu;
  v = bv;
  return const_cast<MTriangle *>(&t2d[bestTriangle]);
}

SPoint2
reparamParFromPoint(const reparamUvLocator *locator, const SPoint3 &p,
                    const std::function<SPoint2(const SPoint3 &)> &search)
{
  if(!locator) return search(p);
  const reparamUvLocator *l = locator;
  const pointKey key{{p.x(), p.y(), p.z()}};
  {
    std::lock_guard<std::mutex> lock(l->guard);
    auto it = l->uvOf.find(key);
    if(it != l->uvOf.end()) return it->second;
  }
  const SPoint2 uv = search(p);
  std::lock_guard<std::mutex> lock(l->guard);
  if(l->uvOf.size() < maxCachedPoints) l->uvOf.emplace(key, uv);
  return uv;
}

