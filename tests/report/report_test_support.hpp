#pragma once
// Small builders for report tests: elements, timings, samples.
#include <memory>
#include <string>

#include "interp/geometry/line_curve.hpp"
#include "interp/path_element.hpp"
#include "motion/plan_result.hpp"

namespace drycut::report::test {

inline FileName test_file() {
  static const FileName f = intern_file_name("/tmp/TEST.MPF");
  return f;
}

inline BlockRef block(uint32_t line, std::string text = "") { return BlockRef{test_file(), line, std::move(text)}; }

inline interp::PathElement line(geometry::Vec3 a, geometry::Vec3 b, double feed_mm_min, uint32_t at_line,
                                bool rapid = false) {
  interp::PathElement e;
  e.kind = interp::ElementKind::Line;
  e.curve = std::make_shared<geometry::LineCurve>(a, b);
  e.feed_mm_s = feed_mm_min / 60.0;
  e.rapid = rapid;
  e.label = rapid ? "G0" : "G1";
  e.source = block(at_line);
  return e;
}

inline motion::BlockTiming timing(const interp::PathElement& e, double time_s, double v_min_mm_s,
                                  motion::Limit limit = motion::Limit::Feed) {
  motion::BlockTiming t;
  t.source = e.source;
  t.label = e.label;
  t.time_s = time_s;
  t.length_mm = e.curve ? e.curve->length() : 0.0;
  t.v_min_mm_s = v_min_mm_s;
  t.v_max_mm_s = e.feed_mm_s;
  t.limit = limit;
  t.rapid = e.rapid;
  return t;
}

inline motion::TrajectorySample sample(double t, double x, double y, double v, const BlockRef* source) {
  motion::TrajectorySample s;
  s.t_s = t;
  s.position = geometry::Vec3(x, y, 0);
  s.v_mm_s = v;
  s.source = source;
  return s;
}

}  // namespace drycut::report::test
