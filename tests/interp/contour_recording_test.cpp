// The contour recorder (contour_recording.hpp) on hand-made elements: lines and arcs in the G18
// plane (abscissa Z, ordinate X), whose columns are worked out by hand:
//   line (X10 Z0) -> (X10 Z-20): kind 1, start (0, 10), end (-20, 10), centre (0, 0).
//   arc about (Z-20, X20), radius 10, from (Z-20, X10) to (Z-30, X20) over a quarter turn through
//   (Z-27.07, X12.93): in (Z, X) the start is at -90°, the end at 180°: the turn is clockwise
//   (G2); the same arc run backwards is G3.
//   Its sweep is -90 degrees (clockwise), the reverse +90; the radius 10 for both.
//   a whole circle about (Z0, X0) counter-clockwise in (Z, X): G3 (start = end), sweep +360.
//   a machine -> workpiece map (here: minus a shift of 5 on X) is applied to every point.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "interp/contour_recording.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
constexpr double kPi = std::numbers::pi;
constexpr PlaneIndices kG18{2, 0, 1};

PathElement line(Vec3 a, Vec3 b, bool rapid = false) {
  PathElement e;
  e.kind = ElementKind::Line;
  e.rapid = rapid;
  e.curve = std::make_shared<geometry::LineCurve>(a, b);
  return e;
}

// An arc in the Z-X plane (x = Z, y = X in the ArcCurve's e1/e2 frame: e1 = Z, e2 = X, so a
// positive sweep is counter-clockwise in (Z, X)).
PathElement arc_zx(double cz, double cx, double r, double start_deg, double sweep_deg) {
  PathElement e;
  e.kind = ElementKind::Arc;
  e.curve = std::make_shared<geometry::ArcCurve>(Vec3(cx, 0, cz), r, Vec3::UnitZ(), Vec3::UnitX(), start_deg * kPi / 180,
                                                 sweep_deg * kPi / 180, 0.0);
  return e;
}

TEST(ContourRecorder, LinesAndArcsInTheZxPlane) {
  ContourRecorder rec;
  rec.start([](const Vec3& p) { return Vec3(p.x() - 5, p.y(), p.z()); });
  rec.consume(line(Vec3(15, 0, 0), Vec3(15, 0, -20)));
  rec.consume(arc_zx(-20, 25, 10, -90, -90));  // clockwise from (Z-20, X15) to (Z-30, X25)
  rec.consume(arc_zx(-20, 25, 10, 180, 90));   // back again, counter-clockwise
  rec.consume(line(Vec3(25, 0, -30), Vec3(50, 0, 10), true));
  ASSERT_EQ(rec.size(), 4u);

  const auto v = [&](size_t i, int k) { return *rec.value(i, k, kG18); };
  EXPECT_EQ(v(0, 0), 1.0);
  EXPECT_NEAR(v(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(v(0, 2), 10.0, 1e-12);
  EXPECT_NEAR(v(0, 3), -20.0, 1e-12);
  EXPECT_NEAR(v(0, 4), 10.0, 1e-12);
  EXPECT_EQ(v(0, 5), 0.0);

  EXPECT_EQ(v(1, 0), 2.0);
  EXPECT_NEAR(v(1, 1), -20.0, 1e-9);
  EXPECT_NEAR(v(1, 2), 10.0, 1e-9);
  EXPECT_NEAR(v(1, 3), -30.0, 1e-9);
  EXPECT_NEAR(v(1, 4), 20.0, 1e-9);
  EXPECT_NEAR(v(1, 5), -20.0, 1e-9);
  EXPECT_NEAR(v(1, 6), 20.0, 1e-9);
  EXPECT_NEAR(v(1, 7), -90.0, 1e-9);
  EXPECT_NEAR(v(1, 8), 10.0, 1e-9);
  EXPECT_EQ(v(2, 0), 3.0);
  EXPECT_NEAR(v(2, 7), 90.0, 1e-9);
  EXPECT_EQ(v(0, 7), 0.0);  // a line has no sweep and no radius
  EXPECT_EQ(v(0, 8), 0.0);
  EXPECT_EQ(v(3, 0), 0.0);  // rapid
  EXPECT_FALSE(rec.value(4, 0, kG18));
  EXPECT_FALSE(rec.value(0, 9, kG18));
}

TEST(ContourRecorder, WholeCircleKeepsItsSense) {
  ContourRecorder rec;
  rec.start([](const Vec3& p) { return p; });
  rec.consume(arc_zx(0, 0, 10, 0, 360));
  rec.consume(arc_zx(0, 0, 10, 0, -360));
  EXPECT_EQ(*rec.value(0, 0, kG18), 3.0);
  EXPECT_EQ(*rec.value(1, 0, kG18), 2.0);
  EXPECT_NEAR(*rec.value(0, 7, kG18), 360.0, 1e-9);
  EXPECT_NEAR(*rec.value(1, 7, kG18), -360.0, 1e-9);
  // Start and end coincide: the sense comes from a point inside the arc, not from the ends.
  EXPECT_NEAR(*rec.value(0, 1, kG18), *rec.value(0, 3, kG18), 1e-9);
}

TEST(ContourRecorder, DwellsAndStopsAreNoContour) {
  ContourRecorder rec;
  rec.start([](const Vec3& p) { return p; });
  PathElement dwell;
  dwell.kind = ElementKind::Dwell;
  dwell.dwell_s = 1;
  rec.consume(std::move(dwell));
  EXPECT_EQ(rec.size(), 0u);
  rec.consume(line(Vec3::Zero(), Vec3::UnitX()));
  EXPECT_EQ(rec.size(), 1u);
  // A new recording forgets the last one.
  rec.start([](const Vec3& p) { return p; });
  EXPECT_EQ(rec.size(), 0u);
}

}  // namespace
}  // namespace drycut::interp
