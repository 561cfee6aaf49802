// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The 1D mesh of a discrete curve moved onto the corners of the input
// polyline it follows. Gmsh places a discrete curve's nodes at even arc
// lengths, so a segment cuts across a corner of the input (a crease turning,
// a tip) and the surface meshes on both sides cut it too: the largest
// distance to the input on CAD parts (bench/README.md#curve-corners).

#ifndef CURVE_CORNER_SNAP_H
#define CURVE_CORNER_SNAP_H

#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// polyline: the input nodes of the curve, node i at parameter i (Gmsh's
// discreteEdge). params: the 1D mesh nodes' parameters in increasing order,
// both ends included (they do not move). Returns the new parameters, both
// ends included: the curve's corners (input nodes where it turns by 40
// degrees or more seen at half a segment's length, not edge by edge; the
// sharpest of each segment, none within half a segment of the ends or of a
// sharper one) become nodes, and each piece between them is meshed evenly
// with its share of the segments rounded (at least one); with keepParity,
// apportioned so that the curve keeps its count of segments (or at least
// its parity: Gmsh gives each curve of a face Blossom recombines an even
// count, and an odd one leaves the face an odd number of triangles, which
// Blossom cannot pair). Rounding each piece instead places the nodes better
// for triangles (keeping the count cost kappa min and Hausdorff distance:
// bench/README.md#curve-corners). Without a corner, params
// as they are. `allowed`, when given, says which input nodes may be taken
// (not one another curve took: two nodes there would make a degenerate
// triangle); `corners` gets the ones taken. everyCorner: not only the
// sharpest of each segment, for a curve along a strip narrower than the
// size, whose sharp turns are the strip's (the two corners of a slot's end
// closer than a segment: the segment across the end cut one off, and the
// slot wall's triangle there turned over); elsewhere the sharpest only (a
// scan's noisy classification curves lose kappa min with every corner:
// bench/README.md#curve-corners)
std::vector<double>
snapCurveNodesToCorners(const std::vector<SPoint3> &polyline,
                        const std::vector<double> &params,
                        const std::function<bool(int)> &allowed = nullptr,
                        std::vector<int> *corners = nullptr,
                        bool keepParity = false, bool everyCorner = false);

} // namespace reparam

#endif
