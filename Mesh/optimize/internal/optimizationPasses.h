// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The passes optimizeOnInput runs over the whole mesh: the targeted flips
// and moves around the triangles below the target or pointing against the
// input (poorTrianglePasses.cpp; bench/README.md, Optimization on the
// input, step 3), and the smoothing sweeps over every movable node
// (smoothingSweeps.cpp): the targeted moves do not reach the rows along the
// curves, which the frontal mesher left a little uneven (bench/README.md,
// Smoothing and Valence flips).

#ifndef OPTIMIZE_OPTIMIZATION_PASSES_H
#define OPTIMIZE_OPTIMIZATION_PASSES_H

#include <cstddef>
#include <vector>
#include "optimizableMesh.h"
#include "optimizeOnInput.h"

namespace reparam {
class closestTriangleSearch;
}

namespace reparam::optimizeInternal {

// First a move of the nodes around `smooth` (the points edge collapses
// left: their triangles valid but uneven), then up to o.maxPasses passes:
// flips of the edges of the triangles below the target or against the
// input (worst first), moves of their corners; counted into r's passes,
// flips, moves and searches (which stop the passes at
// o.searchesPerTriangle per triangle, and 1000 more)
void improvePoorTriangles(optimizableMesh &m, const surfaceMesh &input,
                          const closestTriangleSearch &onInput,
                          const meshOptimizationOptions &o,
                          meshOptimizationResult &r,
                          const std::vector<int> &smooth);

// How many triangles of m are below o.target (`below`) and marked against
// the input (`against`, optimizableMesh::against)
void countPoorTriangles(const optimizableMesh &m,
                        const meshOptimizationOptions &o, std::size_t &below,
                        std::size_t &against);

// Up to o.smoothPasses sweeps, until one changes nothing: valence flips of
// every triangle's edges (o.valenceFlips), then a smoothing move of every
// movable node (localOptimizer::trySmooth); counted into r's flips, moves
// and searches
void smoothMesh(optimizableMesh &m, const surfaceMesh &input,
                const closestTriangleSearch &onInput,
                const meshOptimizationOptions &o, meshOptimizationResult &r);

} // namespace reparam::optimizeInternal

#endif
