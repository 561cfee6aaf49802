// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Faces meshed onto each other. A part of the input thinner than the mesh
// size between two faces of the layout (a speck of a few voxels floating
// in a CT segmentation, a pin of a CAD part 0.4 mm wide at the size 1.5
// mm) has its curves' nodes on both sides and none inside: both faces are
// meshed with the same triangles, the part collapses into a double sheet
// whose edges four triangles share, and nothing told the user
// (bench/README.md, Bad input). One of the two faces is then meshed with
// its input triangles stitched to its curves
// (Geo/parametrize/reparamInputMesh.h, with its warning), which reopens the
// part as the input has it, unless that input has slivers (fans of
// triangles of kappa near 0); the pairs left are named in one warning.

#ifndef REPARAM_OVERLAPPING_FACES_H
#define REPARAM_OVERLAPPING_FACES_H

#include <cstddef>
#include <vector>

class GFace;
class GModel;

namespace reparam {

struct overlappingFaces {
  GFace *first, *second; // first->tag() < second->tag()
  // edges inside both (two triangles of each) and triangles of both
  std::size_t overlaps;
};

// The pairs of faces of m meshed over each other: an edge inside one of
// them is inside the other too (not along the input's own edges of more
// than two triangles: where three faces meet along a curve, a fin stands
// on a face, or two faces touch), or a triangle of one is the other's
std::vector<overlappingFaces> facesMeshedOntoEachOther(GModel *m);

// Meshes one face of each such pair (the one of fewer input triangles
// first, its input no sliver below kappa 0.01) with its input triangles
// where that turns none against the input and parts them, and makes its
// report again; with `warn`, names the pairs left in one warning. Returns
// the faces re-meshed.
std::size_t reparamSeparateOverlappingFaces(GModel *m, bool warn = true);

} // namespace reparam

#endif
