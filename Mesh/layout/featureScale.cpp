// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include "SVector3.h"
#include "featureScale.h"
#include "triangleAdjacency.h"

namespace reparam {

namespace {

  double angleBetween(const SVector3 &a, const SVector3 &b)
  {
    const double na = a.norm(), nb = b.norm();
    if(!(na > 0.) || !(nb > 0.)) return -1.;
    return std::acos(std::max(-1., std::min(1., dot(a, b) / (na * nb))));
  }

  // Per-triangle area-weighted normals and centroids, and the walk around
  // an edge; the stamps spare clearing a visited flag per edge
  class scaleProbe {
  public:
    scaleProbe(const layoutMesh &mesh, const triangleAdjacency &adjacency)
      : _mesh(mesh), _adjacency(adjacency), _normal(mesh.triangles.size()),
        _centroid(mesh.triangles.size()), _stamp(mesh.triangles.size(), 0)
    {
      for(std::size_t t = 0; t < mesh.triangles.size(); t++) {
        const auto &n = mesh.triangles[t];
        const SPoint3 &a = mesh.points[n[0]], &b = mesh.points[n[1]],
                      &c = mesh.points[n[2]];
        _normal[t] = 0.5 * crossprod(SVector3(a, b), SVector3(a, c));
        _centroid[t] =
          SPoint3((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.,
                  (a.z() + b.z() + c.z()) / 3.);
      }
    }

    double dihedral(int e, double radius)
    {
      if(_adjacency.numTriangles(e) != 2) return -1.;
      const int t1 = _adjacency.edgeTriangles[_adjacency.edgeStart[e]];
      const int t2 = _adjacency.edgeTriangles[_adjacency.edgeStart[e] + 1];
      const double a1 = _normal[t1].norm(), a2 = _normal[t2].norm();
      if(!(a1 > 0.) || !(a2 > 0.)) return -1.;
      SVector3 bisector = _normal[t1] * (1. / a1) + _normal[t2] * (1. / a2);
      // beyond about 150 degrees the bisector says nothing of the sides
      if(bisector.norm() < 0.5) return -1.;
      const SPoint3 &p0 = _mesh.points[_adjacency.edges[e][0]];
      const SPoint3 &p1 = _mesh.points[_adjacency.edges[e][1]];
      const SPoint3 middle((p0.x() + p1.x()) / 2., (p0.y() + p1.y()) / 2.,
                           (p0.z() + p1.z()) / 2.);
      SVector3 side = crossprod(SVector3(p0, p1), bisector);
      if(!(side.norm() > 0.)) return -1.;
      const double s1 = dot(SVector3(middle, _centroid[t1]), side);
      const double s2 = dot(SVector3(middle, _centroid[t2]), side);
      if(!(s1 * s2 < 0.)) return -1.;
      if(s1 < 0.) side *= -1.;
      SVector3 first(0., 0., 0.), second(0., 0., 0.);
      walk(t1, t2, middle, radius, [&](int t) {
        const double s = dot(SVector3(middle, _centroid[t]), side);
        if(s > 0.)
          first += _normal[t];
        else if(s < 0.)
          second += _normal[t];
      });
      return angleBetween(first, second);
    }

    // The angle between the normals of edge e's two triangles
    double ownDihedral(int e) const
    {
      const int *t = &_adjacency.edgeTriangles[_adjacency.edgeStart[e]];
      return angleBetween(_normal[t[0]], _normal[t[1]]);
    }

  private:
    // Calls f on t1, t2 and every triangle reached from them across
    // manifold edges whose centroid lies within radius of middle
    template <class F>
    void walk(int t1, int t2, const SPoint3 &middle, double radius, F f)
    {
      _round++;
      std::vector<int> &front = _front;
      front.assign({t1, t2});
      _stamp[t1] = _stamp[t2] = _round;
      const double r2 = radius * radius;
      for(std::size_t i = 0; i < front.size(); i++) {
        const int t = front[i];
        f(t);
        for(int k = 0; k < 3; k++) {
          const int o = _adjacency.across(_adjacency.triangleEdges[t][k], t);
          if(o < 0 || _stamp[o] == _round) continue;
          _stamp[o] = _round;
          if(SVector3(middle, _centroid[o]).normSq() <= r2) front.push_back(o);
        }
      }
    }

    const layoutMesh &_mesh;
    const triangleAdjacency &_adjacency;
    std::vector<SVector3> _normal; // area times the unit normal
    std::vector<SPoint3> _centroid;
    std::vector<unsigned> _stamp;
    unsigned _round = 0;
    std::vector<int> _front;
  };

} // namespace

double dihedralAtScale(const layoutMesh &mesh,
                       const triangleAdjacency &adjacency, int e, double radius)
{
  scaleProbe probe(mesh, adjacency);
  return probe.dihedral(e, radius);
}

std::size_t dropFeaturesBelowScale(const layoutMesh &mesh,
                                   const triangleAdjacency &adjacency,
                                   double radius,
                                   std::vector<char> &featureEdge)
{
  if(!(radius > 0.)) return 0;
  scaleProbe probe(mesh, adjacency);
  std::size_t dropped = 0;
  for(std::size_t e = 0; e < featureEdge.size(); e++) {
    if(!featureEdge[e] || adjacency.numTriangles((int)e) != 2) continue;
    const double atScale = probe.dihedral((int)e, radius);
    if(atScale < 0.) continue;
    if(atScale < 0.5 * probe.ownDihedral((int)e)) {
      featureEdge[e] = 0;
      dropped++;
    }
  }
  return dropped;
}

} // namespace reparam
