// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Shape quality of quadrangles (Sec. 1 of the paper).

#ifndef QUAD_QUALITY_H
#define QUAD_QUALITY_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "SVector3.h"

namespace reparam {

// Eq. (4): eta = max(1 - (2 / pi) max_k |pi / 2 - alpha_k|, 0) over the four
// corner angles; 1 for a square, 0 when a corner is flat or reflex (measured
// against the quad's normal, the cross product of its diagonals)
double quadEta(const SPoint3 &p0, const SPoint3 &p1, const SPoint3 &p2,
               const SPoint3 &p3);

// The unit normal of quadrangle q of points p: its diagonals' cross
// product, normalized (zero for a quadrangle of parallel diagonals)
SVector3 quadNormal(const std::array<int, 4> &q, const std::vector<SPoint3> &p);

// The worst and the mean eta of m's quadrangles (1 and 1 without any)
struct surfaceMesh;
void etaOfQuadrangles(const surfaceMesh &m, double &worst, double &mean);

} // namespace reparam

#endif
