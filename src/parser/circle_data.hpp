#pragma once
// CALCDAT (Job Planning, "Calculate circle data (CALCDAT)"): the centre and radius of the circle
// through 3 or 4 points of the plane, the status FALSE when the points give no circle.
//
// Three points: the circumcircle. The perpendicular bisectors of P1P2 and P1P3 meet at the
// centre; with a = P2 - P1, b = P3 - P1 and d = 2 (a.x b.y - a.y b.x) it is
//   C = P1 + ( b.y |a|^2 - a.y |b|^2 , a.x |b|^2 - b.x |a|^2 ) / d,
// and d = 0 (collinear or coincident points) means no circle.
// Four points: the manual says that when they do not lie exactly on one circle an average is
// taken, not which average. drycut averages the centres of the circumcircles of the four
// triples that form one and takes the mean distance of the four points from that centre as the
// radius; on four points of one circle this is that circle exactly. No triple with a circle:
// status FALSE. (The averaging rule is drycut's choice, written in docs/language.md.)
#include <array>
#include <optional>
#include <span>

namespace drycut::parser {

struct CircleData {
  double centre_x = 0.0;  // abscissa of the working plane
  double centre_y = 0.0;  // ordinate
  double radius = 0.0;
};

// points: 3 or 4 (x, y) pairs. nullopt when they give no circle.
std::optional<CircleData> circle_through_points(std::span<const std::array<double, 2>> points);

}  // namespace drycut::parser
