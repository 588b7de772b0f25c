#pragma once
// Building element streams by hand for the radius compensation tests, and a sink collecting them.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "interp/cutter_compensation.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::test {

using geometry::Vec3;

struct CollectingSink : interp::ElementSink {
  std::vector<interp::PathElement> elements;
  bool finished = false;
  void consume(interp::PathElement&& e) override { elements.push_back(std::move(e)); }
  void finish() override { finished = true; }
  std::vector<interp::PathElement> motions() const {
    std::vector<interp::PathElement> out;
    for (const auto& e : elements)
      if (e.is_motion()) out.push_back(e);
    return out;
  }
};

inline FileName test_file() {
  static const FileName file = intern_file_name("TEST.MPF");
  return file;
}

// Compensation settings shared by the elements of one stream.
struct Comp {
  interp::CompensationSide side = interp::CompensationSide::Left;
  double radius = 2.0;
  bool g451 = false;
  bool kont = false;
  bool cdon = true;
  int plane_axis = 2;
  std::optional<std::pair<Vec3, Vec3>> tilted = std::nullopt;  // first axis, normal of a plane a frame tilted
  interp::CompensationRequest request() const {
    interp::CompensationRequest r;
    r.side = side;
    r.radius_mm = radius;
    r.intersection_corners = g451;
    r.contour_approach = kont;
    r.collision_detection = cdon;
    r.plane_normal_axis = plane_axis;
    if (tilted) {
      r.tilted = true;
      r.tilted_first = tilted->first;
      r.tilted_normal = tilted->second;
    }
    return r;
  }
  Comp off() const {
    Comp c = *this;
    c.side = interp::CompensationSide::None;
    return c;
  }
};

inline interp::PathElement motion(geometry::CurvePtr curve, interp::ElementKind kind, const Comp& comp, uint32_t line,
                                  double feed = 20.0) {
  interp::PathElement e;
  e.kind = kind;
  e.curve = std::move(curve);
  e.feed_mm_s = feed;
  e.compensation = comp.request();
  e.label = kind == interp::ElementKind::Arc ? "G3" : "G1";
  e.source.file = test_file();
  e.source.line = line;
  e.source.text = "N" + std::to_string(line * 10);
  return e;
}

inline interp::PathElement line(Vec3 a, Vec3 b, const Comp& comp, uint32_t block_line, double feed = 20.0) {
  return motion(std::make_shared<geometry::LineCurve>(a, b), interp::ElementKind::Line, comp, block_line, feed);
}

inline interp::PathElement non_motion(interp::ElementKind kind, const Comp& comp, uint32_t block_line) {
  interp::PathElement e;
  e.kind = kind;
  e.compensation = comp.request();
  e.dwell_s = kind == interp::ElementKind::Dwell ? 1.0 : 0.0;
  e.source.file = test_file();
  e.source.line = block_line;
  e.source.text = "N" + std::to_string(block_line * 10);
  return e;
}

// The tool path is one connected path.
inline void expect_continuous(const std::vector<interp::PathElement>& motions, double tol = 1e-6) {
  for (size_t i = 1; i < motions.size(); ++i)
    EXPECT_LT((motions[i].curve->start() - motions[i - 1].curve->end()).norm(), tol) << "between " << i - 1 << " and " << i;
}

inline machine::MachineProfile test_profile() {
  machine::MachineProfile p;
  p.cutcom_maxnum_check_blocks = 3;
  p.cutcom_maxnum_dummy_blocks = 3;
  return p;
}

// The compensation stage alone on a hand-built stream, collecting what it emits.
struct StageRun {
  machine::MachineProfile profile = test_profile();
  Diagnostics diagnostics;
  CollectingSink sink;
  interp::CutterCompensation stage{sink, profile, diagnostics};
  void feed(std::vector<interp::PathElement> elements) {
    for (auto& e : elements) stage.consume(std::move(e));
    stage.finish();
  }
};

}  // namespace drycut::test
