// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Nodes added to a surface mesh being optimized
// (Mesh/optimize/optimizeOnInput.h): a point inserted into a triangle (split in
// three) or onto an inner edge (split with both its triangles), refused where a
// new triangle would point against the input. Within one round of insertions a
// triangle changes at most once, and its neighbours wait for the next round, so
// that the edges found at the start of the round stay true.

#ifndef TRIANGLE_SPLIT_H
#define TRIANGLE_SPLIT_H

#include <array>
#include <map>
#include <utility>
#include <vector>
#include "SPoint3.h"

namespace reparam {

class closestTriangleSearch;
struct optimizableMesh;
struct surfaceMesh;

class triangleSplitter {
public:
  // reversed: m's triangles turn against the input's
  triangleSplitter(optimizableMesh &m, const surfaceMesh &input,
                   const closestTriangleSearch &onInput, bool reversed);
  // x, a point of the input (input node `inputNode`, or -1), inserted into
  // triangle t; false if refused
  bool splitTriangle(int t, const SPoint3 &x, bool movable, int inputNode);
  // x inserted onto edge k of triangle t (corners k, k + 1), which must be
  // an inner edge, not locked; with a floor, refused if the worst new
  // triangle is below both the floor and the worst old one, unless a
  // movable node at the centroid of the four corners (on the input) is not
  bool splitEdge(int t, int k, const SPoint3 &x, bool movable, int inputNode,
                 double floor = -1.);
  // movable node v moved to x, a point of the input (input node
  // `inputNode`), and then kept there: refused if a triangle around v
  // changed this round, would point against the input or fall below kappa
  // `floor`
  bool moveNode(int v, const SPoint3 &x, int inputNode, double floor);
  // whether t may still change this round
  bool untouched(int t) const { return !_touched[t]; }
  // the triangles on edge (a, b) at the start of the round
  const std::vector<int> &edgeTriangles(int a, int b);

private:
  optimizableMesh &_m;
  const surfaceMesh &_input;
  const closestTriangleSearch &_onInput;
  const bool _reversed;
  std::map<std::pair<int, int>, std::vector<int> > _edges;
  std::vector<bool> _touched;
  std::vector<std::vector<int> > _around; // per node, at the round's start
  void touchAround(const std::vector<int> &triangles);
  bool against(const std::array<int, 3> &t, const SPoint3 &x) const;
  double worstWith(const std::vector<std::array<int, 3> > &in,
                   const SPoint3 &x) const;
  bool placeAboveFloor(const std::vector<int> &out,
                       const std::vector<std::array<int, 3> > &in, bool movable,
                       double floor, SPoint3 &x) const;
  bool apply(const std::vector<int> &out,
             const std::vector<std::array<int, 3> > &in, const SPoint3 &onEdge,
             bool movable, int inputNode, double floor = -1.);
};

// Barycentric coordinates of the point of triangle (a, b, c) closest to p
// (zero for a degenerate triangle)
void triangleBarycentric(const SPoint3 &p, const SPoint3 &a, const SPoint3 &b,
                         const SPoint3 &c, double l[3]);

} // namespace reparam

#endif
