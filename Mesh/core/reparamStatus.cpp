// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "reparamStatus.h"

namespace reparam {

const char *reparamStatusMessage(reparamStatus status)
{
  switch(status) {
  case reparamStatus::ok: return "success";
  case reparamStatus::emptyPatch: return "the triangulation is empty";
  case reparamStatus::invalidCoordinates:
    return "a node has a NaN or infinite coordinate";
  case reparamStatus::degenerateTriangle:
    return "a triangle is degenerate (zero area or repeated node)";
  case reparamStatus::nonManifoldEdge:
    return "an edge is shared by more than two triangles";
  case reparamStatus::nonManifoldVertex:
    return "a node joins several boundary fans";
  case reparamStatus::nonOrientable:
    return "the triangulation is not orientable";
  case reparamStatus::severalComponents:
    return "the triangulation has several connected components";
  case reparamStatus::noBoundary:
    return "the surface is closed (no boundary): it must be split into "
           "disk-like patches first";
  case reparamStatus::notDiskTopology:
    return "the surface is not of disk topology (genus > 0): it must be "
           "split into disk-like patches first";
  case reparamStatus::solverFailed: return "the linear solver failed";
  case reparamStatus::notImplemented:
    return "this parametrization is not implemented yet";
  }
  return "unknown status";
}

std::string reparamError::what() const
{
  std::string s = reparamStatusMessage(status);
  if(!detail.empty()) s += " (" + detail + ")";
  return s;
}
} // namespace reparam

