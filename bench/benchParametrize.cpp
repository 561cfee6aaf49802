// Reparam - parametrization benchmark: Gmsh's own map against Reparam's on the
// same patches, in the same process.
//
//   reparamBenchParametrize file.stl [map...]
//
// Classifies the STL like the STL recipe (ClassifySurfaces{40 deg, 1, 1,
// 180 deg}), then times computeParametrization() on every patch with each
// map (default: 3 then 0; stock last, since it can take minutes), the best of
// 3 runs (1 when a run takes over 10 s). Prints one "triangles ..." line,
// then one "map M seconds S ok K" line per map, flushed as soon as known, so
// that a caller's timeout still gets the fast results.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include "GModel.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "MTriangle.h"
#include "OS.h"
#include "gmsh.h"

int main(int argc, char **argv)
{
  if(argc < 2) {
    std::fprintf(stderr, "usage: %s file.stl [map...]\n", argv[0]);
    return 2;
  }
  std::vector<int> maps;
  for(int i = 2; i < argc; i++) maps.push_back(std::atoi(argv[i]));
  if(maps.empty()) maps = {3, 0};

  gmsh::initialize(0, nullptr, false);
  // errors on stderr, and keep going after them like the gmsh executable
  gmsh::option::setNumber("General.Terminal", 1);
  gmsh::option::setNumber("General.Verbosity", 1);
  gmsh::option::setNumber("General.AbortOnError", 0);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 3);
  gmsh::merge(argv[1]);
  std::vector<std::size_t> tags, nodes;
  gmsh::model::mesh::getElementsByType(2, tags, nodes);
  // Mean input edge length: the bench remeshes with it, so that the output
  // has about as many triangles as the input
  double edges = 0.;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    for(MTriangle *t : (*it)->triangles)
      for(int j = 0; j < 3; j++)
        edges += t->getVertex(j)->distance(t->getVertex((j + 1) % 3));
  double meanEdge = tags.empty() ? 0. : edges / (3. * tags.size());

  double t0 = TimeOfDay();
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  double classify = TimeOfDay() - t0;

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
              tags.size(), patches.size(), largest, classify, meanEdge);
  std::fflush(stdout);

  for(int map : maps) {
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    double best = 1e300;
    int ok = 0;
    for(int run = 0; run < 3 && (run == 0 || best < 10.); run++) {
      double seconds = 0.;
      ok = 0;
      for(const auto &t : patches) {
        std::vector<MVertex *> n;
        std::vector<SPoint2> uv;
        std::vector<SPoint3> xyz;
        std::vector<int> tri;
        double start = TimeOfDay();
        ok += computeParametrization(t, n, uv, xyz, tri) ? 1 : 0;
        seconds += TimeOfDay() - start;
      }
      best = std::min(best, seconds);
    }
    std::printf("map %d seconds %.4f ok %d\n", map, best, ok);
    std::fflush(stdout);
  }
  gmsh::finalize();
  return 0;
}
