// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Node moves on the input triangulation that square up a mesh of
// quadrangles (Blossom's recombination of a Frontal-Delaunay for quads
// mesh). Gmsh smooths the quadrangles in each face's (u, v) plane, which
// keeps the nodes of the face's curves where the 1D mesh put them: on the
// cut curves of a patch layout, which follow the input's edges, a node
// where the cut zig-zags gives the quadrangles on either side corners of
// 150-170 degrees (eta 0.1-0.3: most of the worst quadrangles of the smooth
// scans have three nodes on a curve). Here the nodes of the cuts move like
// the inner ones, across the cut, staying on the input surface
// (bench/README.md#squared-up-on-the-input-across-the-cuts). Each node
// tries places around it in a compass search, worst ring first, and keeps
// one where no quadrangle around falls below the worst one there (nor a
// triangle Blossom left below the worst triangle) and:
// in the first half of the sweeps, the corners' squared deviation from the
// right angle summed over the ring falls (a smooth measure, which
// straightens a zig-zag row of nodes; raising eta summed, which only sees
// each element's worst corner, flips it to the mirror zig-zag), with the
// edges' squared log-ratio to the lengths given (their mean at each node),
// in the second half eta summed rises.

#ifndef QUAD_NODE_SMOOTHING_H
#define QUAD_NODE_SMOOTHING_H

#include <cmath>
#include <cstddef>
#include <vector>
#include "SPoint3.h"

namespace reparam {

class closestTriangleSearch;
struct surfaceMesh;

struct quadSmoothingOptions {
  int sweeps = 6;
  // a move must raise the ring's measure (above) by this much
  double gain = 1e-3;
  // compass search: a node tries steps along its tangent plane's two axes,
  // from firstStep times its mean edge, halved down to lastStep times it
  double firstStep = 0.25, lastStep = 1. / 32.;
  // a move leaves the node's old place no farther from the elements around
  // it than this share of their longest edge (a node on a crease of the
  // input under the feature angle, which the elements must keep following)
  double tolerance = 0.02;
  // no element turns by more than this (radians)
  double maxTurn = M_PI / 4.;
  // per point, the length its edges should have (empty: none): in the
  // first half of the sweeps each edge of the ring adds lengthWeight times
  // its squared log-ratio to the mean of its ends' lengths to the corners'
  // deviation. The angles alone let the edges spread, which tau measures;
  // their mean at each node before the moves (meanQuadEdgeAtPoints) with a
  // weight of 0.25 raised tau and left eta mean as it was (the weights
  // tried: bench/README.md#edges-kept-even)
  std::vector<double> size;
  double lengthWeight = 0.25;
};

// A point that moves only along a polyline: a node of a feature curve or a
// border (its polyline: the input's, node i at parameter i), kept strictly
// between its neighbours on the curve (parameters before and after), its
// chords to them following the polyline (Mesh/optimize/curveNodeSlide.h)
struct polylineSlide {
  const std::vector<SPoint3> *polyline = nullptr; // null: not sliding
  double t = 0., before = 0., after = 0.;
  // the neighbours' points when they slide along the same polyline (-1:
  // fixed at before or after): their t bounds this one's
  int previous = -1, next = -1;
};

struct quadSmoothingResult {
  double etaMinBefore = 1., etaMeanBefore = 1.;
  double etaMinAfter = 1., etaMeanAfter = 1.;
  std::size_t moves = 0, searches = 0, slides = 0;
  int sweeps = 0;
};

// Per point of m, the mean length of the quadrangles' edges at it (0 at a
// point of none)
std::vector<double> meanQuadEdgeAtPoints(const surfaceMesh &m);

// Moves the points of m marked movable on the input triangulation
// searched by onInput, sweep after sweep over the nodes whose ring changed,
// until no move is kept or o.sweeps are done (the first half by corner
// deviation, the second by eta). m's elements must be consistently
// oriented around each movable point. landing[i] is set to the input
// triangle point i was moved onto (-1: not moved). eta over m's
// quadrangles, before and after. The points with a polyline in `slides`
// (when not empty, one per point) slide along it instead (its t updated,
// landing left at -1)
quadSmoothingResult
smoothQuadsOnInput(surfaceMesh &m, const std::vector<bool> &movable,
                   const closestTriangleSearch &onInput,
                   std::vector<int> &landing,
                   const quadSmoothingOptions &o = {},
                   std::vector<polylineSlide> *slides = nullptr);

} // namespace reparam

#endif
