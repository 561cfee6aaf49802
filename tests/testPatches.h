// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Synthetic patches for the tests: known geometry, so that tests can assert
// exact numbers without any data file.

#ifndef TEST_PATCHES_H
#define TEST_PATCHES_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "discretePatch.h"

using namespace reparam;

struct testTriangulation {
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > triangles;
};

// Polar grid of the unit disk: `rings` rings of `sectors` nodes around a
// centre node, ring radius (i / rings)^radialExponent, ring i twisted by
// twist * i sectors. Outer boundary: a regular polygon. Counterclockwise.
testTriangulation polarDisk(int rings, int sectors, double radialExponent = 1.,
                            double twist = 0.);

// polarDisk lifted onto the unit sphere's upper half (z = sqrt(1 - r^2))
testTriangulation hemisphere(int rings, int sectors);

// polarDisk with the cells of some (ring, sector) index ranges removed
testTriangulation
polarDiskWithHoles(int rings, int sectors,
                   const std::vector<std::array<int, 4> > &holes);

// A square grid of n x n cells over [0,1]^2 whose middle column of nodes is
// pushed to within `gap` of its left neighbours: slivers with kappa ~ gap
testTriangulation sliverGrid(int n, double gap);

// rectangleGrid(n, n, 1, 1) with its interior nodes moved at random (a
// fixed linear congruential sequence of `seed`) by up to amount / (2 n)
// along x and y: amount close to 1 gives slivers and caps
testTriangulation jitteredGrid(int n, double amount, unsigned seed);

// Apply z = f(x, y) to every node
testTriangulation liftPlanar(testTriangulation t, double amplitude);

// nx x ny cells over [0, lx] x [0, ly] (z = 0), diagonals alternating
testTriangulation rectangleGrid(int nx, int ny, double lx, double ly);

// rectangleGrid(8, 8, 1, 1) whose edge ab of the cells (4, 4) and (4, 3) is
// split by a node m at its midpoint moved by `offset`: the triangle (b, a, m)
// degenerate (no offset) or a sliver
testTriangulation gridWithSplitEdge(const SPoint3 &offset);

// The unit-radius half cylinder of the given length: nAround x nAlong cells,
// each a planar rectangle cut in two, so that the polyhedron is exactly
// developable
testTriangulation halfCylinder(int nAround, int nAlong, double length);

// polarDisk on the unit sphere, up to the polar angle `angle` (radians)
testTriangulation sphericalCap(int rings, int sectors, double angle);

// rectangleGrid(nx, ny, length, 1) bent to the saddle
// z = amplitude ((x - length/2)^2 - (y - 1/2)^2): elongated, not developable
testTriangulation saddleStrip(int nx, int ny, double length, double amplitude);

// A helicoidal ramp: rectangleGrid(nAround, nAcross, 1, 1) mapped to the
// strip of radii [r1, r2] wound `turns` times around the z axis, rising by
// `pitch` per turn. Nearly flat for a small pitch: its conformal image is
// close to an annular sector of 2 pi turns, which overlaps itself beyond one
// turn (the fold fixture).
testTriangulation helicoidStrip(int nAround, int nAcross, double turns,
                                double r1, double r2, double pitch);

// Nodes closer than tol made one, nodes of no triangle dropped, triangles
// left with a repeated node dropped
testTriangulation weld(testTriangulation t, double tol);

// Closed surfaces: the torus of radii R > r (nAround x nTube cells, both
// even), the unit sphere (a latitude-longitude grid of nLongitude x
// nLatitude cells, welded at the poles)
testTriangulation torus(int nAround, int nTube, double R, double r);
testTriangulation sphere(int nLongitude, int nLatitude);

discretePatch makePatchOrDie(const testTriangulation &t);

// t as the meshes the fidelity measures and the optimizer take
namespace reparam {
  struct surfaceMesh;
}
surfaceMesh asSurfaceMesh(const testTriangulation &t);

// n x n unit-square quadrangles over [0, n]^2 (z = 0), corners
// counterclockwise; point (i, j) is i + (n + 1) j, quadrangle (i, j) is
// i + n j
surfaceMesh quadGrid(int n);

// The signed area of quadrangle q of m in the (x, y) plane (positive
// counterclockwise)
double quadAreaXY(const surfaceMesh &m, const std::array<int, 4> &q);

// Twice the signed area of triangle t in the uv plane (uv: 2 values per node)
double uvArea2(const std::vector<double> &uv, const std::array<int, 3> &t);

// Smallest kappa of the 3D triangles
double minKappa(const testTriangulation &t);

#endif
