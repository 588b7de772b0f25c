#include "motion/limit.hpp"

namespace drycut::motion {

std::string_view to_string(Limit limit) {
  switch (limit) {
    case Limit::Feed: return "feed";
    case Limit::Curvature: return "curvature";
    case Limit::Jerk: return "jerk";
    case Limit::Corner: return "corner";
    case Limit::ShortBlock: return "short_block";
    case Limit::Lookahead: return "lookahead";
    case Limit::ExactStop: return "exact_stop";
    case Limit::Axis: return "axis";
  }
  return "unknown";
}

}  // namespace drycut::motion
