// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The elements of a recombined face's mesh that point against its input,
// split again with a neighbour (Mesh/quad/polygonSplits.h). The triangle
// meshes have their own repair of such triangles before their
// optimization (edge splits and flips, Geo/planar/invertedElementRepair.h), the
// quadrangle meshes had none: a fold thinner than the mesh size kept a few
// elements against the input (bench/README.md, Elements against the input
// split again).

#ifndef REPARAM_RESPLIT_AGAINST_H
#define REPARAM_RESPLIT_AGAINST_H

#include <cstddef>

class GFace;

namespace reparam {

// Each element of gf pointing against its input (the report's test, in the
// orientation most of gf's elements have) and a neighbour across one of
// its edges, as one polygon, split again into the triangles and
// quadrangles none of which points against the input, with the best worst
// quality (eta, kappa) and at most two triangles more; kept only then.
// Returns how many pairs were split again
std::size_t reparamResplitElementsAgainstInput(GFace *gf);

} // namespace reparam

#endif
