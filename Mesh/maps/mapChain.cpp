// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "barycentricMap.h"
#include "conformalMap.h"
#include "harmonicMap.h"
#include "mapChain.h"
#include "mapKind.h"
#include "meanValueMap.h"
#include "spectralConformalMap.h"
#include "stageTimer.h"

namespace reparam {

std::vector<mapStep> mapChain(int choice)
{
  const mapStep harmonic{(int)compoundParametrization::harmonic,
                         [](const discretePatch &p) { return harmonicMap(p); },
                         false};
  const mapStep barycentric{
    (int)compoundParametrization::barycentric,
    [](const discretePatch &p) { return barycentricMap(p); }, false};
  const mapStep meanValue{
    (int)compoundParametrization::meanValue,
    [](const discretePatch &p) { return meanValueMap(p); }, false};
  const mapStep conformal{
    (int)compoundParametrization::conformal,
    [](const discretePatch &p) { return conformalMap(p); }, true};
  const mapStep spectral{
    (int)compoundParametrization::spectral,
    [](const discretePatch &p) { return spectralConformalMap(p); }, true};
  // The paper's advice when a conformal map folds: pins from the inertia
  const mapStep conformalRepinned{(int)compoundParametrization::conformal,
                                  [](const discretePatch &p) {
                                    return conformalMap(p,
                                                        principalAxisPins(p));
                                  },
                                  true};
  switch((compoundParametrization)choice) {
  case compoundParametrization::harmonic: return {harmonic};
  case compoundParametrization::barycentric: return {barycentric};
  case compoundParametrization::meanValue: return {meanValue};
  case compoundParametrization::conformal: return {conformal};
  case compoundParametrization::spectral: return {spectral};
  case compoundParametrization::automatic:
    return {spectral, conformalRepinned, meanValue};
  default: return {};
  }
}

namespace {

  // Where the attempt's map fails (mapAttempt::failedNodes, foldPairs)
  void recordFailure(const discretePatch &patch,
                     const bijectivityReport &report, mapAttempt &attempt)
  {
    const std::vector<int> &bad = report.flippedTriangles.empty() ?
                                    report.degenerateTriangles :
                                    report.flippedTriangles;
    for(int t : bad)
      for(int k = 0; k < 3; k++)
        attempt.failedNodes.push_back(patch.triangles[t][k]);
    std::sort(attempt.failedNodes.begin(), attempt.failedNodes.end());
    attempt.failedNodes.erase(
      std::unique(attempt.failedNodes.begin(), attempt.failedNodes.end()),
      attempt.failedNodes.end());
    attempt.foldPairs = report.foldPairs;
  }

} // namespace

checkedMap runMapChain(const discretePatch &patch,
                       const std::vector<mapStep> &steps, bool repair)
{
  checkedMap result;
  std::size_t fewestDegenerate = (std::size_t)-1;
  for(std::size_t s = 0; s < steps.size(); s++) {
    mapAttempt attempt;
    attempt.map = steps[s].map;
    double t0 = wallSeconds();
    patchMap map = steps[s].compute(patch);
    double t1 = wallSeconds();
    attempt.mapTime = t1 - t0;
    attempt.error = map.error;
    if(map.error.ok()) {
      bijectivityReport report = checkBijectivity(patch, map.uv);
      attempt.flipped = report.flippedTriangles.size();
      attempt.folds = report.numFolds;
      attempt.degenerate = report.degenerateTriangles.size();
      if(repair && attempt.flipped) {
        attempt.repairTried = true;
        attempt.repair =
          repairFlips(patch, map.uv, report.orientation, steps[s].freeBoundary);
        // boundary moves may cross the boundary: check everything again
        report = checkBijectivity(patch, map.uv);
      }
      attempt.flippedAfter = report.flippedTriangles.size();
      attempt.foldsAfter = report.numFolds;
      attempt.degenerateAfter = report.degenerateTriangles.size();
      recordFailure(patch, report, attempt);
    }
    attempt.checkTime = wallSeconds() - t1;
    result.attempts.push_back(std::move(attempt));
    const mapAttempt &made = result.attempts.back();
    if(!map.error.ok()) continue;
    // a one-to-one result beats any other; among them, fewer degenerate
    // triangles; without any, the last map that worked
    const bool better =
      made.bijective() ?
        (!result.bijective || made.degenerateAfter < fewestDegenerate) :
        !result.bijective;
    if(better) {
      result.map = std::move(map);
      result.chosen = (int)s;
      result.bijective = made.bijective();
      if(result.bijective) fewestDegenerate = made.degenerateAfter;
    }
    if(result.bijective && fewestDegenerate == 0) break;
  }
  if(result.chosen < 0 && !result.attempts.empty())
    result.map.error = result.attempts.back().error;
  return result;
}
} // namespace reparam

