// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "holeFilling.h"
#include "mapCache.h"
#include "mapKind.h"
#include "parametrize.h"
#include "planeProjection.h"
#include "stageTimer.h"

namespace reparam {

namespace {

  // The patch and the triangles filling its holes as one patch, on the same
  // nodes (its (u, v) are the patch's)
  reparamError extendedPatch(const discretePatch &patch,
                             const holeFilling &filling,
                             discretePatch &extended)
  {
    std::vector<std::array<int, 3> > all = patch.triangles;
    all.insert(all.end(), filling.triangles.begin(), filling.triangles.end());
    return makeDiscretePatch(patch.points, std::move(all), extended);
  }

  // The patch the maps see: `patch`, or `extended` when its holes are filled
  const discretePatch &mappedPatch(const discretePatch &patch,
                                   const parametrizeOptions &o,
                                   discretePatch &extended, parametrization &p)
  {
    p.holes = patch.boundaryLoops.size() - 1;
    if(!o.fillHoles || patch.boundaryLoops.size() < 2) return patch;
    const holeFilling filling = fillHoles(patch);
    p.skippedHoles = filling.skippedHoles;
    if(filling.triangles.empty()) return patch;
    p.fillError = extendedPatch(patch, filling, extended);
    if(!p.fillError.ok()) return patch;
    p.filledHoles = filling.filledHoles;
    return extended;
  }

  // The chain's map of `mapped`, or the one kept in the cache for it
  checkedMap chainOf(const discretePatch &mapped, const parametrizeOptions &o,
                     const std::vector<mapStep> &steps, bool &fromCache)
  {
    checkedMap result;
    fromCache = o.cache && o.cache->take(mapped, o.map, o.repair, result);
    if(fromCache) return result;
    result = runMapChain(mapped, steps, o.repair);
    if(o.cache && o.keepInCache) o.cache->keep(mapped, o.map, o.repair, result);
    return result;
  }

  // A map chosen by hand (not mean value, not the chain) that is not
  // one-to-one: the mean value map instead when it is one-to-one (a convex
  // boundary)
  void fallBackToMeanValue(const discretePatch &mapped,
                           const parametrizeOptions &o, parametrization &p)
  {
    checkedMap &result = p.result;
    p.failedChoice = result.chosen;
    checkedMap fallback = runMapChain(
      mapped, mapChain((int)compoundParametrization::meanValue), o.repair);
    p.fallbackAttempts = fallback.attempts;
    if(fallback.chosen < 0 || !fallback.bijective) return;
    p.usedFallback = true;
    result.chosen = (int)result.attempts.size() + fallback.chosen;
    result.attempts.insert(result.attempts.end(), fallback.attempts.begin(),
                           fallback.attempts.end());
    result.map = std::move(fallback.map);
    result.bijective = true;
  }

  // The holes filled, then o.map or the chain
  parametrization parametrizeByMaps(const discretePatch &patch,
                                    const parametrizeOptions &o)
  {
    parametrization p;
    const double t0 = wallSeconds();
    discretePatch extended;
    const discretePatch &mapped = mappedPatch(patch, o, extended, p);
    p.fillTime = wallSeconds() - t0;

    const std::vector<mapStep> steps = mapChain(o.map);
    if(steps.empty()) {
      p.outcome = parametrizeOutcome::notImplemented;
      return p;
    }
    p.result = chainOf(mapped, o, steps, p.fromCache);
    if(p.result.chosen < 0) {
      p.outcome = parametrizeOutcome::mapFailed;
      return p;
    }
    if(!p.result.bijective &&
       o.map != (int)compoundParametrization::automatic &&
       o.map != (int)compoundParametrization::meanValue)
      fallBackToMeanValue(mapped, o, p);
    // Never a folded or flipped map to the planar mesher in automatic mode;
    // a map chosen by hand is kept as it is, the caller warns
    if(!p.result.bijective && o.map == (int)compoundParametrization::automatic)
      p.outcome = parametrizeOutcome::noBijectiveMap;
    return p;
  }

} // namespace

parametrization parametrize(const discretePatch &patch,
                            const parametrizeOptions &o)
{
  if(!patchIsPlanar(patch, o.planeTolerance))
    return parametrizeByMaps(patch, o);
  checkedMap plane = planeProjection(patch, o.planeTolerance);
  if(plane.bijective) {
    // meshed on its plane with its holes: none filled
    parametrization p;
    p.holes = patch.boundaryLoops.size() - 1;
    p.result = std::move(plane);
    return p;
  }
  // folded onto itself beyond the input's rounding (a flap of a CAD export
  // laid flat): mapped as any part, the projection's attempt first. Cut
  // until each side's projection is one-to-one instead, the flaps of a
  // non-manifold CAD export ended with more elements against the input
  // (bench/README.md, Maps and solvers)
  parametrization p = parametrizeByMaps(patch, o);
  p.result.attempts.insert(p.result.attempts.begin(), plane.attempts[0]);
  if(p.result.chosen >= 0) p.result.chosen++;
  if(p.failedChoice >= 0) p.failedChoice++;
  return p;
}

bool holesFillable(const discretePatch &patch)
{
  if(patch.boundaryLoops.size() < 2) return true;
  const holeFilling filling = fillHoles(patch);
  discretePatch extended;
  return !filling.skippedHoles && !filling.triangles.empty() &&
         extendedPatch(patch, filling, extended).ok();
}

} // namespace reparam
