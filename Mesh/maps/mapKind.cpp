// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "mapKind.h"

namespace reparam {

const char *compoundParametrizationName(int value)
{
  switch(value) {
  case 0: return "Gmsh built-in mean value";
  case 1: return "finite element harmonic";
  case 2: return "barycentric (Tutte)";
  case 3: return "mean value";
  case 4: return "finite element conformal (LSCM)";
  case 5: return "spectral conformal";
  case 6: return "automatic";
  case 7: return "plane projection";
  }
  return "unknown";
}

} // namespace reparam
