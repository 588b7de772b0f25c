// The reference point of a turning tool under G42 (cutting edge position 3, nose radius 0.8 in
// G18): the machine guides the tip P, which lies 0.8 behind the edge centre S on Z and on X.
// The finishing pass of docs/controller-state.md "Turning tools under G41/G42", every point by
// hand (X radius, Y 0, Z):
//   contour: approach (22,0,5) -> (20,0,2), N50 (20,0,2) -> (20,0,-20), N60 -> (25,0,-20),
//            retract G40 -> (30,0,5).
//   S (G42 right of the path: +X along -Z, +Z along +X): N50 at X 20.8, N60 at Z -19.2, the
//   inside corner S (-19.2 on Z, 20.8 on X); the approach ends perpendicular to N50 at S (2, 20.8),
//   N60 ends perpendicular at S (25 on X, -19.2 on Z).
//   P = S + (-0.8, -0.8): approach to (20, 0, 1.2), N50 to (20, 0, -20), N60 to (24.2, 0, -20),
//   retract from there to the programmed (30, 0, 5).
#include "cutter_compensation_test_support.hpp"

namespace drycut::test {
namespace {

interp::PathElement shifted(interp::PathElement e, const Vec3& shift) {
  e.compensation.reference_shift = shift;
  return e;
}

TEST(CutterCompensationEdge, TurningToolTipFollowsTheContour) {
  Comp g42;
  g42.side = interp::CompensationSide::Right;
  g42.radius = 0.8;
  g42.plane_axis = 1;  // G18
  const Vec3 tip(-0.8, 0.0, -0.8);
  StageRun run;
  run.feed({shifted(line({22, 0, 5}, {20, 0, 2}, g42, 4), tip), shifted(line({20, 0, 2}, {20, 0, -20}, g42, 5), tip),
            shifted(line({20, 0, -20}, {25, 0, -20}, g42, 6), tip), line({25, 0, -20}, {30, 0, 5}, g42.off(), 7)});
  const auto m = run.sink.motions();
  ASSERT_EQ(m.size(), 4u);
  expect_continuous(m);
  EXPECT_LT((m[0].curve->start() - Vec3(22, 0, 5)).norm(), 1e-9);
  EXPECT_LT((m[0].curve->end() - Vec3(20, 0, 1.2)).norm(), 1e-9);
  EXPECT_LT((m[1].curve->end() - Vec3(20, 0, -20)).norm(), 1e-9);  // the Ø40 pass ends at the shoulder
  EXPECT_LT((m[2].curve->end() - Vec3(24.2, 0, -20)).norm(), 1e-9);
  EXPECT_LT((m[3].curve->end() - Vec3(30, 0, 5)).norm(), 1e-9);
}

TEST(CutterCompensationEdge, NoShiftLeavesTheEdgeCentrePath) {
  // Edge position 9 (no shift): S is guided, the pass at X 20.8 and the shoulder at Z -19.2.
  Comp g42;
  g42.side = interp::CompensationSide::Right;
  g42.radius = 0.8;
  g42.plane_axis = 1;
  StageRun run;
  run.feed({line({22, 0, 5}, {20, 0, 2}, g42, 4), line({20, 0, 2}, {20, 0, -20}, g42, 5),
            line({20, 0, -20}, {25, 0, -20}, g42, 6), line({25, 0, -20}, {30, 0, 5}, g42.off(), 7)});
  const auto m = run.sink.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_LT((m[1].curve->end() - Vec3(20.8, 0, -19.2)).norm(), 1e-9);
}

}  // namespace
}  // namespace drycut::test
