#include "interp/geometry/translated_curve.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/trimmed_curve.hpp"

namespace drycut::geometry {
namespace {

const Vec3 kShift(-0.8, 0.0, -0.8);

TEST(TranslatedCurve, LineStaysALine) {
  const CurvePtr moved = translate_curve(std::make_shared<LineCurve>(Vec3(20, 0, 2), Vec3(20, 0, -20)), kShift);
  ASSERT_NE(dynamic_cast<const LineCurve*>(moved.get()), nullptr);
  EXPECT_LT((moved->start() - Vec3(19.2, 0, 1.2)).norm(), 1e-12);
  EXPECT_LT((moved->end() - Vec3(19.2, 0, -20.8)).norm(), 1e-12);
}

TEST(TranslatedCurve, ArcStaysAnArcAboutTheMovedCentre) {
  // Quarter circle r 5 about (0,0,0) in G17 from (5,0,0) to (0,5,0): moved, (4.2,0,-0.8) -> (-0.8,5,-0.8).
  const auto arc = std::make_shared<ArcCurve>(Vec3::Zero(), 5.0, Plane::G17, 0.0, std::numbers::pi / 2, 0.0);
  const CurvePtr moved = translate_curve(arc, kShift);
  const auto* moved_arc = dynamic_cast<const ArcCurve*>(moved.get());
  ASSERT_NE(moved_arc, nullptr);
  EXPECT_LT((moved_arc->centre() - kShift).norm(), 1e-12);
  EXPECT_LT((moved->start() - Vec3(4.2, 0, -0.8)).norm(), 1e-12);
  EXPECT_LT((moved->end() - Vec3(-0.8, 5, -0.8)).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(moved->length(), arc->length());
}

TEST(TranslatedCurve, AnyOtherCurveIsWrapped) {
  // A trimmed piece of the arc (not an ArcCurve of its own class): same length, points moved.
  const auto arc = std::make_shared<ArcCurve>(Vec3::Zero(), 5.0, Plane::G17, 0.0, std::numbers::pi / 2, 0.0);
  const CurvePtr piece = std::make_shared<TrimmedCurve>(arc, 1.0, 3.0);
  const CurvePtr moved = translate_curve(piece, kShift);
  EXPECT_NE(dynamic_cast<const TranslatedCurve*>(moved.get()), nullptr);
  EXPECT_DOUBLE_EQ(moved->length(), 2.0);
  EXPECT_LT((moved->at(1.0).position - (piece->at(1.0).position + kShift)).norm(), 1e-12);
  EXPECT_LT((moved->at(1.0).tangent - piece->at(1.0).tangent).norm(), 1e-12);
  EXPECT_EQ(translate_curve(piece, Vec3::Zero()), piece);  // no shift: the same curve
}

}  // namespace
}  // namespace drycut::geometry
