// Reparam - the clock of the stages' logged times

#include <chrono>
#include <thread>
#include <gtest/gtest.h>
#include "OS.h"
#include "stageTimer.h"

using namespace reparam;

TEST(stageTimer, sameClockAsGmshTimeOfDay)
{
  // both read the steady clock: the same seconds, to the time between calls
  const double ours = wallSeconds(), gmsh = TimeOfDay();
  EXPECT_GE(gmsh, ours);
  EXPECT_LT(gmsh - ours, 0.01);
}

TEST(stageTimer, measuresASleep)
{
  const double t0 = wallSeconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double elapsed = wallSeconds() - t0;
  EXPECT_GE(elapsed, 0.02);
  EXPECT_LT(elapsed, 2.);
}
