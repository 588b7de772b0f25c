// POLY: polynomial interpolation (PGA Fundamentals, "Polynomial interpolation (POLY, POLYPATH,
// PO, PL)"; docs/controller-state.md "Polynomial interpolation"). Each axis written as
// PO[ax]=(end, a2, a3, a4, a5) follows f(p) = a0 + a1 p + a2 p^2 + ... + a5 p^5 for p in [0, PL]
// (PL default 1); a0 is the start, a1 follows from the end point; an axis written plainly moves
// linearly in p.
#include <cmath>

#include "interp/geometry/polynomial_curve.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using namespace detail;

PathElement Interpreter::build_polynomial(BlockContext& ctx, const Vector3d& target) {
  Eigen::Matrix<double, 3, 4> higher = Eigen::Matrix<double, 3, 4>::Zero();  // a2..a5 per axis
  bool curved = false;
  for (const parser::PolyWord& w : ctx.block.poly) {
    if (w.axis.empty()) {
      // A rational polynomial: not modelled, the block goes straight to its end point.
      warn_once(ctx, "PO[]= (POLY denominator: the block is planned as a straight line)", w.column);
      return build_line(ctx, target);
    }
    const int i = axis_index(w.axis);
    if (i < 0) continue;  // an extra axis moves with the path, linearly
    // The coefficients are in the axis's unit, a diameter under DIAMON/DIAM90 like the end point.
    const double scale = geometry_unit() * state_.diameter.position_factor(i, false);
    for (size_t k = 1; k < w.values.size(); ++k) {
      higher(i, static_cast<Eigen::Index>(k - 1)) = w.values[k] * scale;
      curved = curved || w.values[k] != 0.0;
    }
  }
  if (!curved) return build_line(ctx, target);
  double p_end = 1.0;
  if (const parser::AddressWord* pl = ctx.block.find_address("PL")) {
    if (!(pl->value > 0 && pl->value <= kMaxAddressValue))
      raise(ctx, 12160, "PL must be > 0 and within the control's value range", pl->column);
    p_end = pl->value;
  }
  // The frame maps the polynomial as a whole: its higher coefficients turn with the frame's
  // linear part (a translation leaves them as they are).
  const Frame& frame = block_frame(ctx);
  if (!frame.is_pure_translation()) higher = frame.linear() * higher;
  PathElement e = element_template(ctx, ElementKind::SplineSpan);
  e.label = "POLY";
  e.curve = std::make_shared<geometry::PolynomialCurve>(geometry::PolynomialCurve::through(position_, target, higher, p_end));
  if (!(std::isfinite(e.curve->length()) && e.curve->end().allFinite()))
    raise(ctx, 12160, "the polynomial cannot be computed (coefficients out of range)");
  e.feed_mm_s = feed_mm_s(ctx, e.curve->length(), target - position_);
  return e;
}

}  // namespace drycut::interp
