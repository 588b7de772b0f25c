// FGROUP lengths (projected_length.hpp) against closed forms.
#include "interp/geometry/projected_length.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ProjectedLength, LineCountsTheGroupedAxesOnly) {
  const LineCurve line({0, 0, 0}, {100, 50, 10});
  EXPECT_NEAR(projected_length(line, 0b001), 100.0, 1e-12);                 // FGROUP(X)
  EXPECT_NEAR(projected_length(line, 0b011), std::hypot(100.0, 50.0), 1e-12);  // FGROUP(X,Y)
  EXPECT_NEAR(projected_length(line, 0b111), line.length(), 1e-12);
}

TEST(ProjectedLength, HelixInItsPlaneIsTheCircle) {
  // Radius 5, one full turn (G17), Z -10: in the plane 2·pi·5 = 31.4159; in 3-D sqrt(31.4159² + 10²).
  const ArcCurve helix({0, 5, 0}, 5.0, Plane::G17, -kPi / 2, 2 * kPi, -10.0);
  EXPECT_NEAR(helix.length(), std::hypot(10 * kPi, 10.0), 1e-9);
  EXPECT_NEAR(projected_length(helix, 0b011), 10 * kPi, 1e-9);
  EXPECT_NEAR(projected_length(helix, 0b100), 10.0, 1e-9);  // FGROUP(Z): the depth
  // Counted on X alone: |x'| integrated over a full circle is 4 radii = 20 (a kink where x' = 0).
  EXPECT_NEAR(projected_length(helix, 0b001), 20.0, 20.0 * 1e-4);
}

}  // namespace
}  // namespace drycut::geometry
