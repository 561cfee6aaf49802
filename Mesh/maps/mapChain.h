// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A map, then its checks and repairs; for Mesh.CompoundParametrization = 6
// the paper's automatic chain (Fig. 23): spectral conformal -> FE conformal
// re-pinned on the principal axis -> mean value convex, each one checked
// and repaired, the first one-to-one result kept.

#ifndef MAP_CHAIN_H
#define MAP_CHAIN_H

#include <functional>
#include <vector>
#include "bijectivityCheck.h"
#include "discretePatch.h"
#include "flipRepair.h"
#include "patchMap.h"

namespace reparam {

struct mapStep {
  int map; // its Mesh.CompoundParametrization value
  std::function<patchMap(const discretePatch &)> compute;
  bool freeBoundary; // may the repair move boundary nodes?
};

// The steps of Mesh.CompoundParametrization = choice (1 to 6)
std::vector<mapStep> mapChain(int choice);

// What one step found and did, for the log
struct mapAttempt {
  int map = 0;
  reparamError error; // of the map itself
  std::size_t flipped = 0, folds = 0, degenerate = 0; // before repair
  bool repairTried = false;
  flipRepairResult repair;
  std::size_t flippedAfter = 0, foldsAfter = 0, degenerateAfter = 0;
  // Where the map fails after the repair, for the layout to cut there
  // (patch nodes): the nodes of the triangles still flipped, else of the
  // degenerate ones; the pairs of boundary nodes whose edges cross
  std::vector<int> failedNodes;
  std::vector<std::array<int, 2> > foldPairs;
  double mapTime = 0., checkTime = 0.; // wall seconds; check includes repair
  bool bijective() const { return error.ok() && !flippedAfter && !foldsAfter; }
};

struct checkedMap {
  patchMap map; // the chosen step's (u, v), repaired
  int chosen = -1; // index of the chosen step, -1 if every map failed
  bool bijective = false;
  std::vector<mapAttempt> attempts;
};

// Runs the steps in order until one gives a one-to-one map without
// degenerate triangles; if none does, keeps the one-to-one result with the
// fewest degenerate triangles, else the last map that did not fail.
checkedMap runMapChain(const discretePatch &patch,
                       const std::vector<mapStep> &steps, bool repair);

} // namespace reparam

#endif
