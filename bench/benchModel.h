// Reparam - what the benchmark programs share: an STL merged and classified
// like the STL recipe (ClassifySurfaces{40 deg, 1, 1, 180 deg}).

#ifndef BENCH_MODEL_H
#define BENCH_MODEL_H

#include <cstddef>

struct classifiedStl {
  std::size_t triangles = 0; // in the file
  double meanEdge = 0.; // of the input triangles
  double classifySeconds = 0.;
};

// gmsh::initialize() with the benchmarks' options (errors on stderr,
// REPARAM_BENCH_VERBOSITY, Mesh.CompoundSplit from REPARAM_BENCH_SPLIT,
// keep going after errors), then merges and
// classifies `file` into the current model; ClassifySurfaces checks its
// patches with Mesh.CompoundParametrization = classifyMap
classifiedStl loadClassifiedStl(const char *file, int classifyMap);

#endif
