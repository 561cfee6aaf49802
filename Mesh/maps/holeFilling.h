// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Holes (Sec. 3): with the inner loops free, convex and harmonic maps lose
// their conformality near them (paper Fig. 9). Each inner loop is therefore
// triangulated (on a plane, or in space where its rim folds over) and the
// map computed on the extended patch.
// No node is added, so the (u, v) of the patch's nodes are those of the
// extended patch's, and the filling triangles never enter the face's
// parametric domain: they only take part in the solve.

#ifndef HOLE_FILLING_H
#define HOLE_FILLING_H

#include <array>
#include <vector>
#include "discretePatch.h"

namespace reparam {

struct holeFilling {
  // Triangles filling the holes, oriented like the patch's
  std::vector<std::array<int, 3> > triangles;
  int filledHoles = 0;
  // Inner loops left free: triangulateHole cannot fill them, or they are
  // too large for the patch around
  int skippedHoles = 0;
};

// Triangulates the polygon of one inner loop: ear clipping on its mean
// plane (Newell's normal), else on the plane the patch around the loop
// faces (its triangles' mean normal), then Delaunay edge flips in that
// plane; else, where the rim crosses itself seen from both planes, the
// triangulation of least area in space (loops of up to 200 nodes). Neither
// of the last two when the triangles around face no one way (the end of a
// tube, which a filling would close into a sock). No diagonal may
// duplicate an edge of the patch. False if it cannot.
bool triangulateHole(const discretePatch &patch, int loop,
                     std::vector<std::array<int, 3> > &triangles);

// A hole whose filling has more than this times the patch's own area is not
// filled (counted as skipped, so that the layout cuts the patch): the patch
// is a thin frame around it, that a conformal map of the filled patch
// squeezes into a band along the disk's edge (bench/README.md, Maps and
// solvers)
const double maxHoleToPatchArea = 10.;

// All inner loops (every loop but patch.outerLoop) that triangulateHole
// fills, but for holes larger than maxHoleToPatchArea times the patch
holeFilling fillHoles(const discretePatch &patch);

} // namespace reparam

#endif
