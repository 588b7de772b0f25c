// Closed loop: "measurements" planned with a known field value are given to the calibration,
// which starts from another value and must find the known one again.
#include "calibrate/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "interp/geometry/line_curve.hpp"

namespace drycut::calibrate {
namespace {

machine::MachineProfile test_profile() {
  machine::MachineProfile p;
  p.name = "calibration test";
  const char* names[3] = {"X", "Y", "Z"};
  for (size_t i = 0; i < 3; ++i) {
    p.axes[i].name = names[i];
    p.axes[i].max_velocity_mm_s = 40000.0 / 60.0;
    p.axes[i].max_accel_mm_s2 = 5000;
    p.axes[i].max_jerk_mm_s3 = 100000;
    p.axes[i].transition_jerk_mm_s3 = 400000;
  }
  p.path_jerk_mm_s3 = 40000;
  return p;
}

// A closed polygon of `sides` G1 blocks round a circle of radius r, SOFT, G64, at F.
RecordedProgram polygon(int sides, double r, double feed_mm_min) {
  RecordedProgram p;
  for (int k = 0; k < sides; ++k) {
    const double a0 = 2 * std::numbers::pi * k / sides, a1 = 2 * std::numbers::pi * (k + 1) / sides;
    interp::PathElement e;
    e.kind = interp::ElementKind::Line;
    e.curve = std::make_shared<geometry::LineCurve>(geometry::Vec3(r * std::cos(a0), r * std::sin(a0), 0),
                                                    geometry::Vec3(r * std::cos(a1), r * std::sin(a1), 0));
    e.feed_mm_s = feed_mm_min / 60.0;
    e.dynamics.profile = interp::AccelProfile::Soft;
    e.dynamics.transition = interp::TransitionMode::Continuous;
    e.label = "G1";
    e.source.line = static_cast<uint32_t>(k + 1);
    p.elements.push_back(std::move(e));
  }
  return p;
}

std::vector<RecordedProgram> programs() { return {polygon(12, 10, 3000), polygon(40, 25, 2000), polygon(7, 5, 4000)}; }

// Measurements made by planning the programs on `truth`.
Measurements synthetic(const machine::MachineProfile& truth, bool with_feeds) {
  Measurements m;
  int n = 0;
  for (const auto& program : programs()) {
    const Prediction p = predict(program, truth, report::RunSpan{}, std::nullopt);
    MeasuredRun run;
    run.name = "polygon " + std::to_string(++n);
    run.time_s = *p.time_s;
    if (with_feeds) run.min_feed_mm_min = p.min_feed_mm_min;
    m.runs.push_back(run);
  }
  return m;
}

TEST(Calibration, RecoversThePathJerkTheMeasurementsWereMadeWith) {
  machine::MachineProfile truth = test_profile();
  truth.path_jerk_mm_s3 = 13000;  // 13 m/s³; the calibration starts from 40
  const Measurements m = synthetic(truth, false);
  CalibrationOptions o;
  o.jobs = 2;
  Calibration c(m, programs(), test_profile(), {find_profile_field("path_jerk")}, o);
  const CalibrationReport r = c.run();
  ASSERT_EQ(r.fields.size(), 1u);
  EXPECT_DOUBLE_EQ(r.fields[0].start, 40.0);
  EXPECT_NEAR(r.fields[0].fitted, 13.0, 0.13);
  EXPECT_LT(r.mape_fitted, 0.1);
  EXPECT_GT(r.mape_start, 1.0);  // the start was measurably wrong
  ASSERT_TRUE(r.mape_loo.has_value());
  EXPECT_LT(*r.mape_loo, 0.5);
  // d t / d ln(path jerk) < 0: a higher jerk is faster on every polygon.
  for (const auto& run : r.runs) EXPECT_LT(run.sensitivity[0], 0.0);
}

TEST(Calibration, RecoversTheAxisJerk) {
  machine::MachineProfile base = test_profile();
  base.path_jerk_mm_s3 = 1e7;  // the axis jerk MD32431 decides the ramps
  machine::MachineProfile truth = base;
  for (auto& a : truth.axes) a.max_jerk_mm_s3 = 30000;  // 30 m/s³; the calibration starts from 100
  const Measurements m = synthetic(truth, false);
  CalibrationOptions o;
  o.jobs = 2;
  o.leave_one_out = false;
  Calibration c(m, programs(), base, {find_profile_field("jerk")}, o);
  const CalibrationReport r = c.run();
  EXPECT_DOUBLE_EQ(r.fields[0].start, 100.0);
  EXPECT_NEAR(r.fields[0].fitted, 30.0, 0.3);
}

TEST(Calibration, RecoversTwoFieldsWithFeeds) {
  machine::MachineProfile truth = test_profile();
  truth.path_jerk_mm_s3 = 25000;
  truth.max_accel_ovl_factor = 1.08;
  const Measurements m = synthetic(truth, true);
  CalibrationOptions o;
  o.jobs = 2;
  o.leave_one_out = false;
  Calibration c(m, programs(), test_profile(), {find_profile_field("path_jerk"), find_profile_field("ovl_factor")}, o);
  const CalibrationReport r = c.run();
  EXPECT_NEAR(r.fields[0].fitted, 25.0, 0.25);
  EXPECT_NEAR(r.fields[1].fitted, 1.08, 0.0108);
}

TEST(Calibration, RefusesAFieldNoRunDependsOn) {
  // No M6 in the polygons: the tool change time cannot change any time.
  const Measurements m = synthetic(test_profile(), false);
  Calibration c(m, programs(), test_profile(), {find_profile_field("tool_change_time")}, {});
  try {
    c.run();
    FAIL() << "tool_change_time was fitted";
  } catch (const CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot identify tool_change_time"), std::string::npos) << e.what();
  }
}

// Straight moves from rest to rest under SOFT: the time depends on the acceleration only through
// MAX_AX_ACCEL x SOFT_ACCEL_FACTOR (no corner, no curve), so the two cannot be told apart.
TEST(Calibration, RefusesTwoFieldsThatActOnlyTogether) {
  std::vector<RecordedProgram> moves;
  for (double length : {20.0, 150.0, 600.0}) {
    RecordedProgram p = polygon(1, 1, 30000);
    p.elements[0].curve = std::make_shared<geometry::LineCurve>(geometry::Vec3(0, 0, 0), geometry::Vec3(length, 0, 0));
    moves.push_back(std::move(p));
  }
  machine::MachineProfile truth = test_profile();
  truth.soft_accel_factor = 0.7;
  truth.path_jerk_mm_s3 = 1e6;  // jerk high enough that the acceleration decides the ramps
  for (auto& a : truth.axes) a.max_jerk_mm_s3 = 1e6;
  Measurements m;
  for (const auto& p : moves) {
    MeasuredRun run;
    run.name = "move";
    run.time_s = *predict(p, truth, report::RunSpan{}, std::nullopt).time_s;
    m.runs.push_back(run);
  }
  CalibrationOptions o;
  o.leave_one_out = false;
  // Started at the truth: the optimum is where both act, and they act alike there.
  Calibration c(m, moves, truth, {find_profile_field("accel"), find_profile_field("soft_accel_factor")}, o);

  try {
    c.run();
    FAIL() << "accel and soft_accel_factor were fitted together";
  } catch (const CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot identify accel, soft_accel_factor together"), std::string::npos)
        << e.what();
  }
}

TEST(Calibration, SameInputSameResult) {
  machine::MachineProfile truth = test_profile();
  truth.path_jerk_mm_s3 = 9000;
  const Measurements m = synthetic(truth, false);
  CalibrationOptions o;
  o.leave_one_out = false;
  o.jobs = 2;
  Calibration a(m, programs(), test_profile(), {find_profile_field("path_jerk")}, o);
  o.jobs = 1;  // the thread count does not change the result
  Calibration b(m, programs(), test_profile(), {find_profile_field("path_jerk")}, o);
  EXPECT_EQ(a.run().fields[0].fitted, b.run().fields[0].fitted);
}

}  // namespace
}  // namespace drycut::calibrate
