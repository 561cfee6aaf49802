// Reparam - what the benchmark programs share

#include <cmath>
#include <cstdlib>
#include "GModel.h"
#include "MTriangle.h"
#include "OS.h"
#include "benchModel.h"
#include "gmsh.h"


classifiedStl loadClassifiedStl(const char *file, int classifyMap)
{
  gmsh::initialize(0, nullptr, false);
  // errors on stderr, and keep going after them like the gmsh executable
  gmsh::option::setNumber("General.Terminal", 1);
  // REPARAM_BENCH_VERBOSITY=5 shows Reparam's per-step log lines
  const char *verbosity = std::getenv("REPARAM_BENCH_VERBOSITY");
  gmsh::option::setNumber("General.Verbosity",
                          verbosity ? std::atoi(verbosity) : 1);
  gmsh::option::setNumber("General.AbortOnError", 0);
  gmsh::option::setNumber("Mesh.CompoundParametrization", classifyMap);
  // REPARAM_BENCH_SPLIT=1: ClassifySurfaces also splits what Reparam's maps
  // flatten badly (Mesh.CompoundSplit)
  const char *split = std::getenv("REPARAM_BENCH_SPLIT");
  gmsh::option::setNumber("Mesh.CompoundSplit", split ? std::atoi(split) : 0);
  gmsh::merge(file);

  classifiedStl c;
  double edges = 0.;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    for(MTriangle *t : (*it)->triangles) {
      c.triangles++;
      for(int j = 0; j < 3; j++)
        edges += t->getVertex(j)->distance(t->getVertex((j + 1) % 3));
    }
  c.meanEdge = c.triangles ? edges / (3. * c.triangles) : 0.;

  double t0 = TimeOfDay();
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  c.classifySeconds = TimeOfDay() - t0;
  return c;
}
