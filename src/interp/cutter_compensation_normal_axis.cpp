#include "interp/cutter_compensation_normal_axis.hpp"

#include <cmath>
#include <cstddef>

namespace drycut::interp {
namespace {

// Below this in-plane length a span or stretch has no direction to spread motion over.
constexpr double kNoLength = 1e-9;  // mm
// A span whose own motion along the normal is below this is flat.
constexpr double kFlat = 1e-9;  // mm

// Natural rise of span i: its own, or for an inserted element the slope of its block's
// programmed piece (the first non-inserted span of the same block with in-plane length).
double natural_rise(const std::vector<NormalAxisSpan>& ahead, size_t i) {
  const NormalAxisSpan& span = ahead[i];
  if (!span.inserted) return span.natural_end - span.natural_start;
  for (size_t k = i + 1; k < ahead.size(); ++k) {
    const NormalAxisSpan& piece = ahead[k];
    if (piece.block != span.block) break;
    if (piece.inserted || piece.in_plane_mm < kNoLength) continue;
    return (piece.natural_end - piece.natural_start) / piece.in_plane_mm * span.in_plane_mm;
  }
  return 0.0;
}

}  // namespace

double normal_value_at_end(double tool_normal, const std::vector<NormalAxisSpan>& ahead) {
  if (ahead.empty() || ahead.front().in_plane_mm < kNoLength) return tool_normal;
  size_t anchor = ahead.size() - 1;
  for (size_t i = 0; i < ahead.size(); ++i)
    if (ahead[i].in_step_at_end && !ahead[i].inserted) {
      anchor = i;
      break;
    }
  std::vector<double> rises(anchor + 1);
  double rise = 0.0, moving_length = 0.0, length = 0.0;
  for (size_t i = 0; i <= anchor; ++i) {
    rises[i] = natural_rise(ahead, i);
    rise += rises[i];
    length += ahead[i].in_plane_mm;
    if (std::abs(rises[i]) > kFlat) moving_length += ahead[i].in_plane_mm;
  }
  const double missing = ahead[anchor].natural_end - tool_normal - rise;
  // The share of span 0: by in-plane length among the moving spans (flat spans stay flat), or
  // among all when none moves.
  const bool spread_over_moving = moving_length >= kNoLength;
  if (spread_over_moving && std::abs(rises[0]) <= kFlat) return tool_normal + rises[0];
  const double share = ahead.front().in_plane_mm / (spread_over_moving ? moving_length : length);
  return tool_normal + rises[0] + missing * share;
}

}  // namespace drycut::interp
