// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Every stage (patch building, maps, checks) returns a status, so that the
// caller and the fallback chain decide, and the log says exactly why.

#ifndef REPARAM_STATUS_H
#define REPARAM_STATUS_H

#include <string>

namespace reparam {

enum class reparamStatus {
  ok,
  emptyPatch,
  invalidCoordinates, // NaN or infinite node coordinates
  degenerateTriangle, // zero area or repeated node
  nonManifoldEdge, // an edge shared by more than two triangles
  nonManifoldVertex, // a node where several boundary fans meet
  nonOrientable,
  severalComponents,
  noBoundary, // closed surface: must be split first
  notDiskTopology, // genus > 0: must be split first
  solverFailed,
  notImplemented,
};

// One sentence per status, for messages
const char *reparamStatusMessage(reparamStatus status);

struct reparamError {
  reparamStatus status = reparamStatus::ok;
  std::string detail; // which triangle, node or value
  int node = -1; // the patch node at fault, if any
  bool ok() const { return status == reparamStatus::ok; }
  // "<status message> (<detail>)"
  std::string what() const;
};

inline reparamError reparamFailure(reparamStatus status,
                                   const std::string &detail = "",
                                   int node = -1)
{
  reparamError e;
  e.status = status;
  e.detail = detail;
  e.node = node;
  return e;
}

} // namespace reparam

#endif
