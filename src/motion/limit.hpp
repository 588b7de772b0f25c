#pragma once
// Which constraint bounds the path velocity at a point.
#include <string_view>

namespace drycut::motion {

enum class Limit { Feed, Curvature, Jerk, Corner, ShortBlock, Lookahead, ExactStop, Axis };
inline constexpr int kLimitCount = static_cast<int>(Limit::Axis) + 1;  // Axis is the last

// "feed", "curvature", "jerk", "corner", "short_block", "lookahead", "exact_stop", "axis"
std::string_view to_string(Limit limit);

}  // namespace drycut::motion
