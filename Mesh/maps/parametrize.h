// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The parametrization of a patch, the stage's one entry: its holes filled
// on their mean plane (Sec. 3), the chosen map or the automatic chain
// (Fig. 23) run with its checks and repairs (Sec. 5), a map chosen by hand
// that stays flipped or folded replaced by the mean value map (a flipped
// map can make the planar meshers loop), and whether the result may be
// meshed. Gmsh-free: Geo/parametrize builds the patch from Gmsh's
// triangles, calls this, logs what it returns and hands the (u, v) back.

#ifndef REPARAM_PARAMETRIZE_H
#define REPARAM_PARAMETRIZE_H

#include <string>
#include <vector>
#include "discretePatch.h"
#include "mapChain.h"

namespace reparam {

class mapCache;

struct parametrizeOptions {
  // Mesh.CompoundParametrization, 1 to 6 (0, Gmsh's own map, is not ours)
  int map = 6;
  // Mesh.CompoundFillHoles: the inner loops filled before mapping
  bool fillHoles = true;
  // Mesh.CompoundRepair: flipped triangles repaired (Sec. 5)
  bool repair = true;
  // Maps computed earlier for the same patch (the layout's), taken from
  // here; with keepInCache, the map computed is kept here instead
  mapCache *cache = nullptr;
  bool keepInCache = false;
  // A patch whose nodes lie within this share of its diagonal of their
  // mean plane is mapped by its projection on it, whatever `map` asks, its
  // holes left free (planeProjection.h; Geometry.MatchMeshTolerance, what
  // Gmsh's discrete faces take; 0: never)
  double planeTolerance = 0.;
};

enum class parametrizeOutcome {
  done, // one-to-one, or a map chosen by hand kept as it is (warned)
  notImplemented, // no map of that value
  mapFailed, // the chosen map (or every map of the chain) failed
  noBijectiveMap, // automatic chain: every map flips or folds
};

struct parametrization {
  parametrizeOutcome outcome = parametrizeOutcome::done;
  checkedMap result; // the (u, v) kept, the attempts in the order made
  // A map chosen by hand that is not one-to-one: the mean value map's
  // attempts (logged after the others), and whether its map was kept (its
  // attempts then also end result.attempts); failedChoice: the index in
  // result.attempts of the attempt it replaces (-1: no fallback)
  std::vector<mapAttempt> fallbackAttempts;
  bool usedFallback = false;
  int failedChoice = -1;
  bool fromCache = false;
  // holes: inner boundary loops; filled on the mean plane, or skipped
  // (their projection cannot be cut); fillError: the filled patch was not
  // valid, every hole left free
  std::size_t holes = 0;
  int filledHoles = 0, skippedHoles = 0;
  reparamError fillError;
  double fillTime = 0.; // wall seconds

  bool ok() const { return outcome == parametrizeOutcome::done; }
  const mapAttempt &chosen() const
  {
    return result.attempts[result.chosen];
  }
};

// Parametrizes `patch` (built by makeDiscretePatch, valid) by o.map, or by
// its projection on its plane when planar (o.planeTolerance).
// result.map.uv has 2 values per node of `patch`.
parametrization parametrize(const discretePatch &patch,
                            const parametrizeOptions &o);

// Whether every hole of `patch` can be filled (triangulateHole), as
// parametrize fills them (true without holes)
bool holesFillable(const discretePatch &patch);

} // namespace reparam

#endif
