// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The sharp creases left inside a patch (a crease that ends inside its face
// bounds no patch; one the noise merge took in) as chains of input nodes,
// for the mesh to follow them as embedded curves instead of cutting across
// (bench/README.md#tips-and-creases).

#ifndef CREASE_CHAINS_H
#define CREASE_CHAINS_H

#include <array>
#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// The nodes where three crease edges or more meet (isCrease(a, b) says
// whether the edge of nodes a and b is one): a spike of a scan whose sharp
// edges the patch layout merged into a patch as noise
std::vector<int>
creaseCorners(const std::vector<SPoint3> &points,
              const std::vector<std::array<int, 3> > &triangles,
              const std::function<bool(int, int)> &isCrease);

// The chains of crease edges (isCrease(a, b)) of the triangulation, cut at
// their branch points (three creases or more), as node sequences; each
// trimmed of its nodes closer than `margin` to an `avoid` point (the face's
// boundary: an embedded curve must not touch it), then kept if its length
// is at least `minLength`.
std::vector<std::vector<int> >
creaseChains(const std::vector<SPoint3> &points,
             const std::vector<std::array<int, 3> > &triangles,
             const std::function<bool(int, int)> &isCrease,
             const std::vector<SPoint3> &avoid, double margin,
             double minLength);

// Whether a crease (the polyline of an embedded curve) is too small for the
// mesh size asked at its middle: shorter than three sizes (at most three
// segments) and either bent (its ends closer than 0.8 of its length) or
// with an end within half a size of one of `others` (the face's other
// curves, none ending there). Three segments cannot follow a bent crease,
// and its ends are corners inside the face (a crease doubling back on
// itself leaves a sliver between two of its segments); between an end and a
// curve passing closer than half a size the mesh must put a triangle
// narrower than that. Of any length, one that comes back beside itself
// closer than half a size (a hairpin at the mesh's scale) is too small too:
// its 1D mesh turns back on itself and the triangle between two of its
// segments is a sliver. A straight short crease away from others is meshed
// along as well as a long one (bench/README.md#tips-and-creases)
bool creaseTooSmallForMesh(const std::vector<SPoint3> &crease,
                           const std::vector<std::vector<SPoint3> > &others,
                           double size);

// Whether two triangles sharing an edge meet at a crease sharper than
// `angle` (radians, between their normals) within `distance` of the
// polyline: the surface folds right beside it (the walls of a slot
// shallower than the mesh size, in the same face as the plate around)
bool creaseWithin(const std::vector<SPoint3> &points,
                  const std::vector<std::array<int, 3> > &triangles,
                  const std::vector<SPoint3> &polyline, double distance,
                  double angle);

} // namespace reparam

#endif
