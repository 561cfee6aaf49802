// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The maps by the value of Mesh.CompoundParametrization that chooses them,
// and their names for the log: the maps' own vocabulary, so that the chain
// and the entry function need no option header of Geo/.

#ifndef MAP_KIND_H
#define MAP_KIND_H

namespace reparam {

// Values of Mesh.CompoundParametrization; `plane` is no value of it: the
// projection a planar patch gets whatever the option (planeProjection.h)
enum class compoundParametrization {
  gmsh = 0, // Gmsh's own code (the reference)
  harmonic = 1,
  barycentric = 2,
  meanValue = 3,
  conformal = 4,
  spectral = 5,
  automatic = 6,
  plane = 7
};

// "mean value", "spectral conformal"...; "plane projection" for 7,
// "unknown" outside 0..7
const char *compoundParametrizationName(int value);

} // namespace reparam

#endif
