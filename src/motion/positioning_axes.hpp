#pragma once
// Positioning axes beside the path (PGA Fundamentals "Traversing positioning axes (POS, POSA,
// WAITP)", Function Manual P2 "Positioning axes", S1 "SPOS"). Each axis has its own
// interpolator: a move goes from rest to rest at the axis's velocity (FA, else MD32060; the
// spindle MD35300) and acceleration (MAX_AX_ACCEL; the spindle MD35210), without jerk limit
// (BRISKA, MD32420 off), after a lead time (SPOS of a turning spindle: braking first).
//
// How the planner uses it (planner.cpp):
// - POS/SPOS: the block ends when the path and the axis are in position. The control keeps
//   continuous-path mode only if the axis arrives first; drycut does not predict that and brings
//   the path to rest at the end of such a block, then waits max(0, move time - the time the
//   block's path took).
// - POSA/SPOSA: the axis starts when its block starts and runs on; the program waits for it at
//   WAITP/WAITS, in a block that programs the axis again (the interpreter emits the wait) and
//   at the program end (M2/M30).
#include <map>
#include <string>
#include <vector>

#include "interp/path_element.hpp"

namespace drycut::motion {

class PositioningAxes {
 public:
  // Seconds from the start of the move until the axis is in position.
  static double move_time(const interp::PositioningMove& move);
  // A POSA/SPOSA move starting at `start_s` (run clock).
  void start(const interp::PositioningMove& move, double start_s);
  // When the named axes (every running axis when `axes` is empty) are in position; the run
  // clock value, or 0 when none runs. The axes waited for are forgotten.
  double wait(const std::vector<std::string>& axes);

 private:
  std::map<std::string, double> ready_at_;
};

}  // namespace drycut::motion
