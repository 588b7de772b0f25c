#pragma once
// Corner smoothing G641 / G642 / G643 / G645 (docs/smoothing.md): an element filter between the
// NC block compressor and the planner. At a corner between two straight elements it trims both
// and inserts a rounding element (the control's "intermediate rounding block").
//
// WHAT THE CONTROL DOES (FB1 B1 "Continuous-path mode", PGA "G641/G642/G643/G644/G645")
//   G641 rounds by distance: the rounding starts ADIS (G0: ADISPOS) before the corner and ends
//   that far after it; no ADIS programmed = 0 = G64. On short blocks the distance is shortened by
//   up to 36 %; where even that does not fit, the transition runs as G64. G642 (G645 at corners)
//   and G643 round within tolerances, chosen by MD20480 SMOOTHING_MODE (tens digit G642/G645,
//   units digit G643): 0 the axis tolerances MD33100, 1 the contour tolerance SD42465, 2 the
//   orientation tolerance (geometry axes: MD33100), 3 contour and orientation, 4 ADIS/ADISPOS.
//   CTOL= / ATOL[ax]= override the tolerances (negative: the data value again). G0 blocks use
//   MD20560 G0_TOLERANCE_FACTOR × the tolerance. No rounding is inserted where G64 would pass
//   the transition without a velocity reduction (the overload-factor rule, MD32310), unless the
//   mode is G643 or MD20490 IGNORE_OVL_FACTOR_FOR_ADIS is TRUE; nor between very short blocks
//   (a block takes at least one IPO cycle: the rounding block would slow the path); nor across a
//   change BRISK/SOFT or a block without path motion. G642..G645 need MD28520 >= 3.
//
// WHAT DRYCUT DOES
//   A corner is the joint of two motion elements (lines, arcs, spline spans, compressor spans)
//   whose tangents u1 (into the corner C) and u2 (out of it) differ. The rounding starts d before C on the first line and ends d after it on the
//   second, as a Bezier curve with its inner control point(s) at the corner:
//     G641/G642/G643: the QUADRATIC P0 = C - d·u1, P1 = C, P2 = C + d·u2. Its second derivative
//       is constant: traversed at a steady parameter rate every axis accelerates constantly,
//       as the manuals describe the rounding blocks of G641/G642 ("constant acceleration").
//       Tangent-continuous (C1); its curvature steps from 0 to sin θ/(2d) at the joins.
//     G645: the CUBIC P0 = C - d·u1, P1 = P2 = C, P3 = C + d·u2 (the double control point):
//       tangent- and curvature-continuous (curvature 0 at both joins, as G645 avoids curvature
//       steps; drycut's reading of "G645 ... also tangential transitions that are not
//       curvature-continuous").
//   By symmetry the closest approach to C is at the parameter middle:
//       quadratic: B(1/2) - C = d/4·(u2 - u1),  deviation = d/4·|u2 - u1| = d/2·sin(θ/2)
//       cubic:     B(1/2) - C = d/8·(u2 - u1),  deviation = d/8·|u2 - u1| = d/4·sin(θ/2)
//   (θ the angle between u1 and u2); per axis k·d·|u2_i - u1_i| (k = 1/4, 1/8). The distance
//   from the programmed lines is smaller still (quadratic: d·t²·sin θ from the first line and
//   d·(1-t)²·sin θ from the second, at most d/4·sin θ). The trim d:
//     - distance modes (G641, digit 4): d = ADIS (ADISPOS between G0 blocks);
//     - contour tolerance (digit 1/3): d = tol/(k·|u2 - u1|);
//     - axis tolerances (digit 0/2): d = min_i tol_i/(k·|u2_i - u1_i|);
//   then at most max_block_share (0.5, drycut's assumption: not published) of each neighbouring
//   programmed block. A G641 distance shortened by more than adis_max_reduction (36 %) gives G64.
//   The rounding element (SplineSpan, inserted, labelled "G641".."G645") carries the block of
//   the corner, the lower feed of the two and its deviation (smoothing_deviation_mm); the trimmed
//   neighbours keep the length of their programmed blocks for the short-block rule, and the
//   rounding is a block for it too. No rounding where that rule, or the rounding's own
//   curvature limits (centripetal acceleration, SOFT curvature jerk, sampled at 9 points),
//   would hold the path to no more than G64 allows at the corner (it would slow the path), or
//   when either element moves extra axes or positioning axes.
//   At an arc or spline neighbour (geometry/trimmed_curve.hpp cuts it: an arc stays an ArcCurve)
//   the same Bezier shape runs between the points d along the curves before and after C, with
//   the curves' tangents there: tangent-continuous, the neighbour's curvature not matched (G645
//   too). d comes from the tangents at C as above; the deviation is then measured (the closest
//   of 65 points to C) and d shrinks by a quarter (at most 8 times) until it is within the
//   tolerance, else no rounding.
//   Not modelled (the transition stays G64): G645's rounding of tangential transitions with a
//   curvature step (line into a tangent arc; MD33120), G644, orientation tolerances (OTOL,
//   SD42466).
// Memory: one held element. Without a rounding mode at an element's end it passes at once.
#include <cstdint>
#include <optional>

#include "interp/geometry/polynomial_span.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

// Tangent: the quadratic rounding (constant axis accelerations; G641/G642/G643).
// Curvature: the cubic rounding with the double control point (G645).
enum class BlendContinuity { Tangent, Curvature };
BlendContinuity blend_continuity(int smoothing_code);

// The rounding of the corner C between unit tangents u1 and u2 with trim d (see above).
geometry::PolynomialSpan corner_blend_curve(const geometry::Vec3& corner, const geometry::Vec3& u1,
                                            const geometry::Vec3& u2, double trim_mm, BlendContinuity continuity);
// Its closest distance to the corner: d/4·|u2 - u1| (Tangent), d/8·|u2 - u1| (Curvature).
double corner_blend_deviation(const geometry::Vec3& u1, const geometry::Vec3& u2, double trim_mm,
                              BlendContinuity continuity);
double blend_deviation_factor(BlendContinuity continuity);

class CornerSmoothing final : public ElementSink {
 public:
  CornerSmoothing(ElementSink& next, const machine::MachineProfile& profile);

  void consume(PathElement&& element) override;
  void finish() override;

  // The trim the rules give the corner at the end of `a` into `b` (unit tangents u1, u2;
  // programmed block lengths la, lb), before the overload and short-block checks; 0: no rounding.
  double trim_distance(const PathElement& a, const PathElement& b, const geometry::Vec3& u1,
                       const geometry::Vec3& u2, double la, double lb) const;

  uint64_t corners_rounded() const { return corners_; }

 private:
  // Where the tolerance comes from at the corner after `a` (MD20480 digit, CTOL/ATOL, G0 factor).
  struct Tolerance {
    enum Kind { Distance, Contour, Axes } kind = Axes;
    double distance = 0, contour = 0;
    geometry::Vec3 axes = geometry::Vec3::Zero();
  };
  struct Rounding {
    std::shared_ptr<const geometry::PolynomialSpan> curve;
    double trim = 0;       // d, along each neighbour
    double deviation = 0;  // closest distance to the corner
  };
  Tolerance tolerance(const PathElement& a, const PathElement& b) const;
  // The rounding with trim d (lines: closed form; curves: shrunk until within the tolerance).
  std::optional<Rounding> fit_rounding(const PathElement& a, const PathElement& b, const geometry::Vec3& u1,
                                       const geometry::Vec3& u2, double d) const;
  // Hands on the trimmed pending element and the rounding; holds or hands on b, trimmed.
  void hand_on(PathElement& b, Rounding rounding);
  bool holds(const PathElement& e) const;
  // Rounds the corner between pending_ and b when the rules allow: hands on the trimmed
  // pending element and the rounding, then holds or hands on b with its start trimmed.
  // False: nothing changed (b is still the caller's).
  bool round_corner(PathElement& b);
  // The velocity G64 would allow at the corner (overload-factor rule) and the velocity the
  // blocks allow there without it (F, axis velocities, the short-block rule); rounding only
  // where the first is lower (unless G643 or MD20490).
  double g64_corner_velocity(const PathElement& a, const geometry::Vec3& u1, const geometry::Vec3& u2) const;
  double programmed_velocity(const PathElement& e, const geometry::Vec3& u) const;
  // The lowest velocity the rounding's curvature allows (centripetal, SOFT curvature jerk).
  double rounding_velocity(const geometry::PolynomialSpan& curve, const PathElement& a) const;
  void emit_pending();

  ElementSink& next_;
  const machine::MachineProfile& profile_;
  std::optional<PathElement> pending_;  // a Line whose end may still be rounded
  uint64_t corners_ = 0;
};

}  // namespace drycut::interp
