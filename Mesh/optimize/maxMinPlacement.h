// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Where a node lifts the worst triangle around it most. The optimizer's moves
// try a few places (the neighbours' centroid, the apex that makes the worst
// triangle equilateral, halfway to each): in a tight spot each of them lowers
// another triangle of the ring (bench/README.md, Optimization on the input,
// step 3). The place that maximizes the worst kappa of the ring is searched
// instead, in the ring's plane, by compass steps that halve when none is
// better.

#ifndef MAX_MIN_PLACEMENT_H
#define MAX_MIN_PLACEMENT_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "SVector3.h"

namespace reparam {

// The point of the plane through `start` normal to `normal` where the worst
// kappa of the triangles (x, a, b), for each (a, b) of `opposite`, is
// highest, none of them turning over (from its side of `normal` at
// `start`); steps from `step` down to step / 32 in eight directions
SPoint3 maxMinKappaPoint(const SPoint3 &start,
                         const std::vector<std::array<SPoint3, 2> > &opposite,
                         const SVector3 &normal, double step);

// The worst kappa of those triangles with the node at x, -1 if one turns
// over from its side at `start`
double worstRingKappa(const SPoint3 &x, const SPoint3 &start,
                      const std::vector<std::array<SPoint3, 2> > &opposite,
                      const SVector3 &normal);

} // namespace reparam

#endif
