#include "workload/deviation_path_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drycut::workload {

PathSampler::PathSampler(double step_mm) : step_(step_mm) {
  if (!(step_mm > 0)) throw std::invalid_argument("sample step must be > 0");
}

void PathSampler::consume(interp::PathElement&& element) {
  if (!element.is_motion() || !element.curve) return;
  const double length = element.curve->length();
  if (!(length > 0) || !std::isfinite(length)) return;
  // Bounded so that a huge rapid move cannot exhaust memory; contour elements are short.
  const size_t n = static_cast<size_t>(std::clamp(std::ceil(length / step_), 1.0, 1e6));
  SampledElement sampled;
  sampled.points.reserve(n + 1);
  for (size_t i = 0; i <= n; ++i)
    sampled.points.push_back(element.curve->at(length * static_cast<double>(i) / static_cast<double>(n)).position);
  sampled.source = std::move(element.source);
  sampled.rapid = element.rapid;
  sampled.arc = element.kind == interp::ElementKind::Arc;
  sampled.compensation = element.compensation;
  elements_.push_back(std::move(sampled));
}

}  // namespace drycut::workload
