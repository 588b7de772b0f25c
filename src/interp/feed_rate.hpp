#pragma once
// The path feed of one motion block from the feed state (SINUMERIK G group 15 and the thread
// and tapping codes; docs/controller-state.md "Feeds"). Written out:
// - G94: v = F · u / 60 mm/s, u = mm per unit of F when it was programmed (25.4 for inch).
// - G95: v = F · u · n / 60 (F per revolution, n spindle speed rev/min); n = 0 is alarm 10860.
// - G93: F is 1/min: the block lasts 1/F min, v = L · F / 60 for a block of path length L.
// - G33/G331/G332: the axis of the lead (I: X, J: Y, K: Z) travels one lead P per revolution:
//   revolutions N = D / P (D the block's travel on that axis, the path length if it has none),
//   time t = N / n min, v = L / (60 t). That is L / (P · n) min for a thread along the axis.
// - G34/G35: the lead grows/shrinks by c (F, mm/rev²) per revolution: D = P·N ± c·N²/2, so
//   N = (√(P² + 2cD) − P)/c (G34) or (P − √(P² − 2cD))/c (G35; P² < 2cD: the lead would reach
//   zero inside the block, alarm 14800).
#include <string>

#include <Eigen/Core>

#include "interp/modal_state.hpp"

namespace drycut::interp {

struct FeedResult {
  double mm_s = 0.0;
  int alarm = 0;  // nonzero: the block cannot run (number of the control's alarm)
  std::string detail;
};

// Revolutions of a G34 (increasing) / G35 thread over `travel` mm of its lead axis, from the lead
// P and the change c per revolution (the formulas above); negative when a G35 lead would reach
// zero within the travel.
double lead_change_revolutions(double travel, double lead, double change, bool increasing);

// `spindle_rpm` is the speed the spindle turns at (0 = stopped; G96 already resolved),
// `chord` the block's end minus start, `lead_change_mm` the F of a G34/G35 block.
FeedResult path_feed(const ModalState& state, double spindle_rpm, double length_mm,
                     const Eigen::Vector3d& chord, double lead_change_mm);

}  // namespace drycut::interp
