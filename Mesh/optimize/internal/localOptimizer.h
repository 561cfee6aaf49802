// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The state optimizeOnInput's passes share: the triangles around each
// point, which points changed since a move of them was refused, the input
// points under the triangles' centroids, the searches of the input spent.
// Its work is split by job: ring measures (ringMeasures.cpp), edge flips
// (edgeFlips.cpp), node moves (nodeMoves.cpp) and smoothing moves
// (smoothingSweeps.cpp).

#ifndef OPTIMIZE_LOCAL_OPTIMIZER_H
#define OPTIMIZE_LOCAL_OPTIMIZER_H

#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>
#include "SPoint3.h"
#include "SVector3.h"
#include "closestTriangle.h"
#include "optimizableMesh.h"
#include "optimizeOnInput.h"

namespace reparam::optimizeInternal {

// A kept change must raise the worst kappa by this much: no cycles, no
// work for rounding
const double minimalGain = 1e-2;

class localOptimizer {
public:
  // works on m, against `input` (searched by onInput); `searches` counts
  // the searches of the input, which stop the flips and moves at `budget`
  localOptimizer(optimizableMesh &m, const surfaceMesh &input,
                 const closestTriangleSearch &onInput,
                 const meshOptimizationOptions &o, std::size_t &searches,
                 std::size_t budget);

  double kappa(int t) const; // of triangle t
  // the triangles below the target or against the input: against the input
  // first, then worst first
  std::vector<int> trianglesBelowTarget() const;
  bool spent() const { return _searches >= _budget; }
  // v and the corners of its triangles, into `to`
  void addNeighbours(int v, std::set<int> &to) const;

  // the first of t's edges tryFlip flips
  bool tryFlips(int t, bool forValence = false);
  // no valence flip makes a triangle worse than this (unless its pair
  // was): the target, or the mesh's worst when that is higher, so that the
  // flips never lower the worst kappa of a mesh
  double valenceFloor = 0.6;
  bool tryMove(int v);
  bool trySmooth(int v, double gain);

  // The ring of v, the triangles around it (ringMeasures.cpp; the apexes
  // and the max-min place in nodeMoves.cpp and smoothingSweeps.cpp)
  int neighbourAcross(int t, int a, int b) const;
  int valenceOf(int v) const;
  int idealValenceOf(int v) const;
  std::pair<double, double> ringKappa(int v, const SPoint3 &at) const;
  struct ringQuality {
    double worst = 1., sum = 0.;
    int below = 0;
  };
  ringQuality ringAt(int v, const SPoint3 &at) const;
  SPoint3 ringCentroid(int v) const;
  SPoint3 ringApexMean(int v) const;
  SPoint3 worstTriangleApex(int v) const;
  SPoint3 maxMinPoint(int v) const;
  double ringLongestEdge(int v) const;
  double distanceToRing(int v, const SPoint3 &at, const SPoint3 &p) const;

private:
  optimizableMesh &_m;
  const surfaceMesh &_input;
  const closestTriangleSearch &_onInput;
  const meshOptimizationOptions _o;
  std::vector<std::vector<int> > _around; // triangles around each point
  // points whose surroundings changed since a move of them was refused
  std::vector<bool> _dirty;
  // searches of the input made and allowed: on CAD inputs with huge
  // triangles among tiny ones a search costs much more, and a face with
  // many triangles it cannot better must not hold the mesher
  std::size_t &_searches;
  const std::size_t _budget;
  void changedAround(int v);
  // the input's point closest to triangle t's centroid, kept until a
  // corner of t moves (a smoothing sweep asks for most of them twice)
  mutable std::vector<closestTriangleHit> _atCentroid;
  mutable std::vector<bool> _known;
  const closestTriangleHit &centroidHit(int t) const;
  bool against(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c) const;
  double distanceToInput(const SPoint3 &p) const;

  bool tryFlip(int t, int k, bool forValence = false);
  void replaceCorner(int t, int from, int to);
  // the valences and their ideals, kept from the first valence flip on
  // (the node moves between do not change them)
  mutable std::vector<int> _valence, _idealValence;
  double valenceCost(int v, int change) const;

  SVector3 ringNormal(int v) const;
  bool starKernelPoint(int v, SPoint3 &at) const;
  double ringFarthest(int v, const SPoint3 &at, double tolerance,
                      bool checkAgainst, bool &valid,
                      std::vector<closestTriangleHit> *hits = nullptr) const;

  static bool smoothedBetter(const ringQuality &before,
                             const ringQuality &after, double sumGain);
  std::vector<SPoint3> smoothingTargets(int v, const ringQuality &before,
                                        double sumGain) const;
  bool holdsInput(int v, const SPoint3 &to,
                  const std::vector<closestTriangleHit> &held) const;
};

} // namespace reparam::optimizeInternal

#endif
