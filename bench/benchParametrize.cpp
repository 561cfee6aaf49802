// Reparam - parametrization benchmark: Gmsh's own map against Reparam's on the
// same patches, in the same process.
//
//   reparamBenchParametrize file.stl [map...]
//
// Classifies the STL like the STL recipe (ClassifySurfaces{40 deg, 1, 1,
// 180 deg}, with the first map given), then times computeParametrization()
// on every patch with each map (default: 3 then 0; stock last, since it can
// take minutes), the best of 3 runs (1 when a run takes over 10 s). Prints
// one "triangles ..." line, then one "map M seconds S ok K flipped F folds G
// notOneToOne P" line per map, flushed as soon as known, so that a caller's
// timeout still gets the fast results. Each result is also
// checked (first run, untimed): flipped uv triangles and boundary folds, and
// the number of patches with either.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include "Context.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "OS.h"
#include "benchModel.h"
#include "bijectivityCheck.h"
#include "discretePatch.h"
#include "gmsh.h"
#include "planeProjection.h"

using namespace reparam;

struct bijectivityCount {
  std::size_t flipped = 0, folds = 0;
};

// Flips and folds of a parametrization as Gmsh gets it (any map, also
// Gmsh's own), with Reparam's exact checks; a planar patch whose projection
// is one-to-one up to the input's own rounding (Gmsh's planar tolerance) is
// one-to-one (Mesh/maps/planeProjection.h: the map Reparam gives it)
static bijectivityCount countNonBijective(const std::vector<SPoint3> &xyz,
                                          const std::vector<int> &tri,
                                          const std::vector<SPoint2> &uv)
{
  bijectivityCount c;
  std::vector<std::array<int, 3> > triangles(tri.size() / 3);
  for(std::size_t t = 0; t < triangles.size(); t++)
    triangles[t] = {{tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]}};
  discretePatch patch;
  if(!makeDiscretePatch(xyz, triangles, patch).ok()) return c;
  std::vector<double> flat(2 * uv.size());
  for(std::size_t i = 0; i < uv.size(); i++) {
    flat[2 * i] = uv[i].x();
    flat[2 * i + 1] = uv[i].y();
  }
  const double tolerance = CTX::instance()->geom.matchMeshTolerance;
  if(patchIsPlanar(patch, tolerance)) {
    if(planeProjection(patch, tolerance).bijective) return c;
  }
  bijectivityReport r = checkBijectivity(patch, flat);
  c.flipped = r.flippedTriangles.size();
  c.folds = r.numFolds;
  return c;
}

int main(int argc, char **argv)
{
  if(argc < 2) {
    std::fprintf(stderr, "usage: %s file.stl [map...]\n", argv[0]);
    return 2;
  }
  std::vector<int> maps;
  for(int i = 2; i < argc; i++) maps.push_back(std::atoi(argv[i]));
  if(maps.empty()) maps = {3, 0};

  // ClassifySurfaces lays out and verifies its patches with the first map
  // (Reparam's layout for 1 to 6, Gmsh's split loop for 0)
  classifiedStl stl = loadClassifiedStl(argv[1], maps[0]);

  std::vector<std::vector<MTriangle *> > patches;
  std::size_t largest = 0;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it) {
    if((*it)->triangles.empty()) continue;
    patches.push_back((*it)->triangles);
    largest = std::max(largest, (*it)->triangles.size());
  }
  std::printf("triangles %lu patches %lu largest %lu classify %.3f "
              "meanEdge %.6g\n",
              stl.triangles, patches.size(), largest, stl.classifySeconds,
              stl.meanEdge);
  std::fflush(stdout);

  for(int map : maps) {
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    double best = 1e300;
    int ok = 0, notOneToOne = 0;
    std::size_t flipped = 0, folds = 0;
    // REPARAM_BENCH_RUNS=1: one run (one log line per step)
    const char *runsEnv = std::getenv("REPARAM_BENCH_RUNS");
    const int runs = runsEnv ? std::max(1, std::atoi(runsEnv)) : 3;
    for(int run = 0; run < runs && (run == 0 || best < 10.); run++) {
      double seconds = 0.;
      ok = 0;
      for(const auto &t : patches) {
        std::vector<MVertex *> n;
        std::vector<SPoint2> uv;
        std::vector<SPoint3> xyz;
        std::vector<int> tri;
        double start = TimeOfDay();
        bool done = computeParametrization(t, n, uv, xyz, tri);
        seconds += TimeOfDay() - start;
        ok += done ? 1 : 0;
        // the first run also checks the result, outside the timing
        if(run == 0 && done) {
          bijectivityCount c = countNonBijective(xyz, tri, uv);
          flipped += c.flipped;
          folds += c.folds;
          notOneToOne += c.flipped || c.folds;
        }
      }
      best = std::min(best, seconds);
    }
    std::printf("map %d seconds %.4f ok %d flipped %lu folds %lu "
                "notOneToOne %d\n",
                map, best, ok, flipped, folds, notOneToOne);
    std::fflush(stdout);
  }
  gmsh::finalize();
  return 0;
}
