#pragma once
// The colour scale for path velocity: red (slow, where feed is lost) through yellow and green to
// blue (fast). Discrete bins keep the SVG small: consecutive segments of one bin share a polyline.
#include <string>

namespace drycut::report {

inline constexpr int kColourBins = 24;

// The bin of `fraction` in [0, 1] (clamped; NaN -> 0).
int colour_bin(double fraction);

// "#rrggbb" for a bin (the colour at the bin's centre).
std::string bin_colour(int bin);

// "#rrggbb" for a fraction in [0, 1] (continuous, for the legend gradient stops).
std::string scale_colour(double fraction);

}  // namespace drycut::report
