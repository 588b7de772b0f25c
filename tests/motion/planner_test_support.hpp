#pragma once
// Shared helpers for planner tests: a plain profile, element builders and a recorder.
#include <memory>
#include <string>
#include <vector>

#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"
#include "motion/planner.hpp"
#include "test_curves.hpp"

namespace drycut::motion::testing {

// 3 axes at 40 m/min, 5 m/s², jerk 50 m/s³, path jerk 40 m/s³, IPO 4 ms, OVL 1.2.
inline machine::MachineProfile plain_profile(int lookahead = 64) {
  machine::MachineProfile p;
  p.name = "test";
  const char* names[3] = {"X", "Y", "Z"};
  for (int i = 0; i < 3; ++i) {
    auto& a = p.axes[static_cast<size_t>(i)];
    a.name = names[i];
    a.max_velocity_mm_s = 40000.0 / 60.0;
    a.max_accel_mm_s2 = 5000;
    a.max_jerk_mm_s3 = 50000;
  }
  p.ipo_cycle_s = 0.004;
  p.max_accel_ovl_factor = 1.2;
  p.path_jerk_mm_s3 = 40000;
  p.soft_accel_factor = 1.0;
  p.curv_effect_on_path_accel = 0.75;
  p.lookahead_blocks = lookahead;
  p.short_block_factor = 0.9;
  p.g0_accel_factor = 1.0;
  p.g0_jerk_factor = 1.0;
  p.tool_change_time_s = 3.0;
  return p;
}

struct Mode {
  bool soft = false;
  bool exact_stop = false;  // G60
};

inline interp::PathElement motion(geometry::CurvePtr curve, double feed_mm_min, Mode mode = {},
                                  interp::ElementKind kind = interp::ElementKind::Line, int line = 0) {
  interp::PathElement e;
  e.kind = kind;
  e.curve = std::move(curve);
  e.feed_mm_s = feed_mm_min / 60.0;
  e.dynamics.profile = mode.soft ? interp::AccelProfile::Soft : interp::AccelProfile::Brisk;
  e.dynamics.transition = mode.exact_stop ? interp::TransitionMode::ExactStop : interp::TransitionMode::Continuous;
  e.label = kind == interp::ElementKind::Arc ? "G2" : "G1";
  e.source.line = static_cast<uint32_t>(line);
  e.source.text = "N" + std::to_string(line);
  return e;
}

inline interp::PathElement line(Vec3 a, Vec3 b, double feed_mm_min, Mode mode = {}, int n = 0) {
  return motion(std::make_shared<TestLine>(a, b), feed_mm_min, mode, interp::ElementKind::Line, n);
}

inline interp::PathElement rapid(Vec3 a, Vec3 b) {
  interp::PathElement e = line(a, b, 0.0);
  e.rapid = true;
  e.label = "G0";
  return e;
}

inline interp::PathElement passive(interp::ElementKind kind, std::string label) {
  interp::PathElement e;
  e.kind = kind;
  e.label = std::move(label);
  return e;
}

struct Recorder : PlanObserver {
  std::vector<BlockTiming> blocks;
  std::vector<TrajectorySample> samples;
  void on_block(const BlockTiming& t) override { blocks.push_back(t); }
  void on_sample(const TrajectorySample& s) override {
    samples.push_back(s);
    samples.back().source = nullptr;  // not valid after the call
  }
};

}  // namespace drycut::motion::testing
