// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Reparam's patch layout for ClassifySurfaces{..., forParametrization = 1}:
// the triangulation is cut along its sharp edges into feature patches, the
// patches that are noise at the mesh scale are merged into a neighbour, and
// every patch is cut until the parametrization it will get is verified, on
// the part exactly as it will be meshed (the paper's Sec. 6 and SPEC Sec. 3).
// The verification is the caller's (the maps and their checks); this file
// only grows, cleans and cuts, and always ends: every cut makes both sides
// smaller, and the cutting depth is bounded.

#ifndef PATCH_LAYOUT_H
#define PATCH_LAYOUT_H

#include <array>
#include <functional>
#include <string>
#include <vector>
#include "SPoint3.h"
#include "surfaceMesh.h"

namespace reparam {

// The nodes and triangles (no quadrangles) of the surface to lay out
struct layoutMesh : surfaceMesh {
  // Node pairs no patch may cross: sharp edges, boundaries. Non-manifold
  // edges are never crossed either.
  std::vector<std::array<int, 2> > featureEdges;
};

struct layoutParameters {
  // A feature patch is noise at the mesh scale, and is merged into the
  // neighbour it shares the longest boundary with, when it has at most
  // noiseTriangles triangles, an area below noiseArea, or a width (twice its
  // area over its perimeter) below noiseWidth and an area below
  // noiseWidthMaxArea
  int noiseTriangles = 0;
  double noiseArea = 0.;
  double noiseWidth = 0.;
  double noiseWidthMaxArea = 0.;
  // Sharp edges whose dihedral angle, seen over a disk of this radius,
  // falls below half their own are no features (featureScale.h; 0: every
  // sharp edge is one)
  double featureRadius = 0.;
  // Cuts of one feature patch, at most this deep (each halves it or so)
  int maxDepth = 48;
  // A part refused for its size alone is cut by the Fiedler vector of
  // about this many clusters of its triangles (bisectPart; 0: exact): the
  // exact one of a large scan's largest parts, one after the other, was
  // most of the layout's time (1.4M triangles: 66 s)
  std::size_t coarseCutNodes = 50000;
  // Parts verified at once, each on its own thread (the verifier must then
  // be safe to call from several threads); the result is the same for any
  // number
  int threads = 1;
};

// What the caller's verification says of a part (triangle indices of the
// mesh): kept as it is, or cut because of `reason`
struct partCheck {
  bool ok = true;
  std::string reason;
  // refused for its number of triangles alone (not mapped): cut by a
  // coarse Fiedler vector (layoutParameters::coarseCutNodes)
  bool bySize = false;
  // Where its maps fail (nodes of the mesh): the cut goes through one of
  // `cutThrough` (sorted; triangles flipped or crushed) or between the two
  // nodes of a pair of `cutApart` (boundary edges whose images cross)
  std::vector<int> cutThrough;
  std::vector<std::array<int, 2> > cutApart;
};
typedef std::function<partCheck(const std::vector<int> &triangles)>
  partVerifier;

struct layoutSplit {
  std::size_t triangles = 0; // of the part cut
  int depth = 0;
  std::size_t parts = 0;
  std::string reason;
  // fans of triangles moved across the cut where it pinched a side
  // (unpinchCut.h)
  std::size_t movedFans = 0;
  // cut where its maps fail (partCheck::cutThrough, cutApart)
  bool atFailure = false;
};

struct layoutResult {
  std::vector<int> patch; // per triangle: 0 .. numPatches - 1
  int numPatches = 0;
  // The sharp edges kept as features (node pairs, of mesh.featureEdges), and
  // how many were sharp below featureRadius only
  std::vector<std::array<int, 2> > features;
  std::size_t featuresBelowScale = 0;
  int featurePatches = 0; // patches between sharp edges
  int mergedNoise = 0; // noise patches merged into a neighbour
  int cleanedPatches = 0; // feature patches left after the merges
  std::vector<layoutSplit> splits;
  // Final patches the verification still refuses (a single triangle, or the
  // depth bound reached), with its reason
  std::vector<std::pair<int, std::string> > unverified;
  // The edges (node pairs) between two final patches, on the boundary or
  // non-manifold: what a classification must not cross to grow these
  // patches
  std::vector<std::array<int, 2> > cutEdges;
  double cleanTime = 0., splitTime = 0.; // wall seconds
};

// Area of triangle t, length of the edge of nodes (a, b)
double triangleArea(const layoutMesh &mesh, int t);
double edgeLength(const layoutMesh &mesh, const std::array<int, 2> &edge);

layoutResult computePatchLayout(const layoutMesh &mesh,
                                const layoutParameters &parameters,
                                const partVerifier &verify);

// The stages, for tests: patch index per triangle of the components between
// feature and non-manifold edges; the same after merging noise patches
// (returns how many were merged)
struct triangleAdjacency;
std::vector<int> featurePatches(const layoutMesh &mesh,
                                const triangleAdjacency &adjacency,
                                const std::vector<char> &featureEdge,
                                int &numPatches);
int mergeNoisePatches(const layoutMesh &mesh,
                      const triangleAdjacency &adjacency,
                      const layoutParameters &parameters,
                      std::vector<int> &patch, int &numPatches);

// Cuts a connected part (triangle indices) in two where a cut is short
// compared with the smaller side: the best level set of the Fiedler vector
// of its dual graph (edges weighted by length over centroid distance).
// Returns the side (0 or 1) of each triangle of `part`, both non-empty.
// coarseNodes > 0: a part of more than twice as many triangles gets the
// Fiedler vector of a graph of about coarseNodes clusters of its
// triangles, smoothed on its own graph (the eigensolver's cost grows
// faster than the graph: a cut where the cut's place matters less).
// `check`'s places where the part's maps fail (partCheck::cutThrough,
// cutApart), if any: the level is, of those whose cut goes through one of
// those nodes or between the nodes of one of those pairs, leaving a tenth
// of the area on each side and at most twice as long for its area as the
// shortest level, the shortest (a fold about one node stays whole in one
// half of a cut elsewhere, refused for the same reason level after level);
// `atFailure` (if given): whether such a level was taken. `across`: the
// part's partNeighbours when the caller has them.
std::vector<char>
bisectPart(const layoutMesh &mesh, const triangleAdjacency &adjacency,
           const std::vector<int> &part, std::size_t coarseNodes = 0,
           const partCheck &check = partCheck(), bool *atFailure = nullptr,
           const std::vector<std::array<int, 3> > *across = nullptr);

// The edge-connected components of a part (through manifold edges whose two
// triangles are both in the part); `across` as for bisectPart
std::vector<std::vector<int> >
partComponents(const triangleAdjacency &adjacency, const std::vector<int> &part,
               std::size_t numTriangles,
               const std::vector<std::array<int, 3> > *across = nullptr);

} // namespace reparam

#endif
