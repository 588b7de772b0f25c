#pragma once
// Axis ticks a reader can use: steps of 1, 2 or 5 × 10^k, labels without noise digits.
#include <string>
#include <vector>

namespace drycut::report {

// The tick step for about `target` ticks over [lo, hi] (1, 2 or 5 × a power of ten; 1 for an
// empty or invalid range).
double nice_tick_step(double lo, double hi, int target = 6);

// Tick positions k·step inside [lo, hi] (both ends inclusive, rounding tolerated).
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

// A tick label with as many decimals as the step needs ("0.25", "100", "-1.5").
std::string format_tick(double value, double step);

}  // namespace drycut::report
