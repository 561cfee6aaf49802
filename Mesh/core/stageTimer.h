// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The clock of the stages' logged times (assembly, solve, checks, layout):
// wall seconds on the same monotonic clock as Gmsh's TimeOfDay() (OS.cpp),
// without Gmsh's OS.h. The times are only reported, never compared to decide.

#ifndef STAGE_TIMER_H
#define STAGE_TIMER_H

#include <chrono>

namespace reparam {

// Seconds since the steady clock's epoch: only differences mean anything
inline double wallSeconds()
{
  const auto t = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t.time_since_epoch()).count();
}

} // namespace reparam

#endif
