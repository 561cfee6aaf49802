// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Anisotropic mesh sizes from the curvature of an input triangulation
// (Sec. 6.3 of the paper: BAMG in the parametric plane with a metric from
// the surface's curvature). The principal curvatures and directions at the
// input's nodes come from Gmsh's estimator (Rusinkiewicz's per-face
// tensors averaged at the nodes, Numeric/curvature.h); along each principal
// direction the size is 2 pi R / N (R the radius of curvature: N segments
// around a circle of that radius, as Mesh.MeshSizeFromCurvature = N does
// with the smaller radius only), bounded by [hMin, hMax]; across the
// surface hMax. BAMG pulls the metric back to the (u, v) plane itself.

#ifndef CURVATURE_METRIC_H
#define CURVATURE_METRIC_H

#include <array>
#include <memory>
#include <vector>
#include "STensor3.h"
#include "SVector3.h"

namespace reparam {

class closestTriangleSearch;
struct surfaceMesh;

// The curvatures at a node, |k| along each principal direction (unit
// tangents, orthogonal; which is the larger is not known)
struct principalCurvatures {
  SVector3 direction[2];
  double curvature[2] = {0., 0.};
};

// Per node of m (its triangles consistently oriented)
std::vector<principalCurvatures> curvaturesOf(const surfaceMesh &m);

// The sizes along the two directions: 2 pi / (n |k|), within [hMin, hMax]
struct curvatureSizes {
  double elementsPerCircle = 20., hMin = 0., hMax = 1e22;
  // sizes grow by at most this ratio per element along the surface (0:
  // not graded)
  double gradation = 0.;
  double along(double curvature) const;
};

// The metric with those sizes along the directions, hMax across them
SMetric3 curvatureMetric(const principalCurvatures &c,
                         const curvatureSizes &sizes);

// m intersected with c along c's principal directions: along each, the
// larger of the two metrics (the smaller size); c's eigenvectors from a
// symmetric eigensolver, orthonormal even where two sizes are equal
SMetric3 intersectAlong(const SMetric3 &c, const SMetric3 &m);

// Limits how fast the nodes' metrics of m decrease in size from node to
// node: a node's metric propagated along an edge e grows its sizes by the
// factor 1 + |e|_M ln(growth) (|e|_M: e's length in the metric), and the
// neighbour's metric is intersected with it, until no metric changes by
// more than 1 % (at most 20 updates per node). The curvature of a scan is
// noisy at the input's scale: without it, BAMG's own gradation, in the
// (u, v) plane, mistakes the map's conformal factor for a change of size
void gradeMetrics(const surfaceMesh &m, std::vector<SMetric3> &metrics,
                  double growth);

// The metric of an input triangulation at any point: the nodes' metrics
// (graded, sizes.gradation) interpolated at the closest point of the input
// (barycentric weights)
class curvatureMetricField {
public:
  curvatureMetricField(const surfaceMesh &input, const curvatureSizes &sizes);
  ~curvatureMetricField();
  SMetric3 at(const SPoint3 &x) const;
  // the smallest size of the metric at x (an isotropic mesher's)
  double smallestSizeAt(const SPoint3 &x) const;

private:
  std::vector<SPoint3> _points;
  std::vector<std::array<int, 3> > _triangles;
  std::vector<SMetric3> _metrics;
  std::unique_ptr<closestTriangleSearch> _search;
};

} // namespace reparam

#endif
