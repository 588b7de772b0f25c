#include "interp/geometry/curve_sampler.hpp"

#include <cmath>

namespace drycut::geometry {

std::vector<Vec3> sample_curve(const Curve& curve, double ds) {
  const double length = curve.length();
  std::vector<Vec3> out;
  if (!(ds > 0.0) || !std::isfinite(ds) || length <= 0.0) {
    out.push_back(curve.start());
    if (length > 0.0) out.push_back(curve.end());
    return out;
  }
  const auto steps = static_cast<size_t>(std::floor(length / ds));
  out.reserve(steps + 2);
  for (size_t i = 0; i <= steps; ++i) out.push_back(curve.at(static_cast<double>(i) * ds).position);
  if (length - static_cast<double>(steps) * ds > 1e-12) out.push_back(curve.end());
  return out;
}

}  // namespace drycut::geometry
