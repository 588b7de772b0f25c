#pragma once
// Collects the motion elements of a stream as dense samples by arc length, keeping what the
// deviation evaluation needs to tell contour from approach (end points, source block, the tool
// radius requested). An element sink: it sits behind the interpreter or behind the compensation.
#include <vector>

#include "interp/path_element.hpp"
#include "workload/curve_source.hpp"

namespace drycut::workload {

struct SampledElement {
  std::vector<Vec3> points;  // at s = 0, h, ..., L (both ends included)
  BlockRef source;
  bool rapid = false;
  bool arc = false;  // a circle or helix (G2/G3, CIP, CT): a curve the program states exactly
  interp::CompensationRequest compensation;
  const Vec3& start() const { return points.front(); }
  const Vec3& end() const { return points.back(); }
};

class PathSampler : public interp::ElementSink {
 public:
  explicit PathSampler(double step_mm);
  void consume(interp::PathElement&& element) override;
  const std::vector<SampledElement>& elements() const { return elements_; }

 private:
  double step_;
  std::vector<SampledElement> elements_;
};

}  // namespace drycut::workload
