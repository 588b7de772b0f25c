#include "interp/corner_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <spdlog/spdlog.h>

#include "interp/geometry/trimmed_curve.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMinLength = 1e-9;      // mm: shorter elements take no part in a rounding
constexpr double kMinTurnCos = 0.99999999;  // tangents closer than ~0.0001 rad: no corner
constexpr double kMaxTurnCos = -0.9999;  // a reversal (more than ~179.2 deg): no rounding

const char* smoothing_label(int code) {
  switch (code) {
    case 641: return "G641";
    case 642: return "G642";
    case 643: return "G643";
    default: return "G645";
  }
}

// The rounding modes this stage models (G644 is planned as G64).
bool rounding_code(int code) { return code == 641 || code == 642 || code == 643 || code == 645; }

double programmed_length(const PathElement& e) {
  return e.block_length_mm > 0 ? e.block_length_mm : e.curve->length();
}

bool roundable_kind(const PathElement& e) {
  return (e.kind == ElementKind::Line || e.kind == ElementKind::Arc || e.kind == ElementKind::SplineSpan) && e.curve &&
         e.smoothing_deviation_mm < 0;
}

bool is_line(const PathElement& e) { return e.kind == ElementKind::Line; }

}  // namespace

geometry::PolynomialSpan corner_blend_curve(const Vec3& corner, const Vec3& u1, const Vec3& u2, double trim_mm,
                                            BlendContinuity continuity) {
  // As a Hermite span on u in [0, 1]. Cubic Bezier P0, C, C, P3: B'(0) = 3·(C - P0) = 3·d·u1,
  // B'(1) = 3·d·u2. Quadratic Bezier P0, C, P3: B'(0) = 2·d·u1, B'(1) = 2·d·u2.
  const double k = continuity == BlendContinuity::Curvature ? 3.0 : 2.0;
  return geometry::PolynomialSpan::hermite(corner - trim_mm * u1, corner + trim_mm * u2, k * trim_mm * u1,
                                           k * trim_mm * u2, 1.0);
}

double blend_deviation_factor(BlendContinuity continuity) {
  return continuity == BlendContinuity::Curvature ? 1.0 / 8.0 : 1.0 / 4.0;
}

double corner_blend_deviation(const Vec3& u1, const Vec3& u2, double trim_mm, BlendContinuity continuity) {
  return blend_deviation_factor(continuity) * trim_mm * (u2 - u1).norm();
}

BlendContinuity blend_continuity(int code) {
  return code == 645 ? BlendContinuity::Curvature : BlendContinuity::Tangent;
}

CornerSmoothing::CornerSmoothing(ElementSink& next, const machine::MachineProfile& profile)
    : next_(next), profile_(profile) {}

bool CornerSmoothing::holds(const PathElement& e) const {
  if (!roundable_kind(e) || e.dynamics.exact_stop_this_block) return false;
  if (e.dynamics.transition != TransitionMode::SmoothDistance && e.dynamics.transition != TransitionMode::SmoothTolerance)
    return false;
  if (!rounding_code(e.smoothing.code) || !e.extra_axes.empty() || !e.positioning.empty()) return false;
  if (e.smoothing.code != 641 && profile_.smoothing.max_axispoly_per_block < 3) return false;  // MD28520
  return e.curve->length() > kMinLength;
}

void CornerSmoothing::consume(PathElement&& element) {
  if (pending_) {
    if (round_corner(element)) return;  // it handed on or holds the trimmed element
    emit_pending();
  }
  if (holds(element)) {
    pending_ = std::move(element);
  } else {
    next_.consume(std::move(element));
  }
}

void CornerSmoothing::finish() {
  if (pending_) emit_pending();
  if (corners_ > 0) spdlog::debug("corner smoothing: {} corners rounded", corners_);
  next_.finish();
}

void CornerSmoothing::emit_pending() {
  PathElement e = std::move(*pending_);
  pending_.reset();
  next_.consume(std::move(e));
}

CornerSmoothing::Tolerance CornerSmoothing::tolerance(const PathElement& a, const PathElement& b) const {
  const SmoothingRequest& r = a.smoothing;  // the settings of the block that ends at the corner
  const machine::SmoothingData& data = profile_.smoothing;
  const bool rapid = a.rapid && b.rapid;
  Tolerance t;
  const int source = r.code == 641 ? 4 : r.code == 643 ? data.mode % 10 : data.mode / 10 % 10;
  if (source == 4) {
    t.kind = Tolerance::Distance;
    t.distance = rapid ? r.adispos_mm : r.adis_mm;
    return t;
  }
  const double g0 = rapid ? data.g0_tolerance_factor : 1.0;
  // A programmed CTOL holds for every smoothing but G641/G644 and has priority over ATOL (Job
  // Planning, "CTOL, OTOL, ATOL"), whatever tolerance MD20480 selects for the machine data.
  t.kind = source == 1 || source == 3 || r.ctol_mm >= 0 ? Tolerance::Contour : Tolerance::Axes;
  t.contour = (r.ctol_mm >= 0 ? r.ctol_mm : data.contur_tol_mm) * g0;
  for (int i = 0; i < 3; ++i)
    t.axes[i] = (r.atol_mm[i] >= 0 ? r.atol_mm[i] : profile_.axes[static_cast<size_t>(i)].compress_pos_tol_mm) * g0;
  return t;
}

double CornerSmoothing::trim_distance(const PathElement& a, const PathElement& b, const Vec3& u1, const Vec3& u2,
                                      double la, double lb) const {
  const Tolerance t = tolerance(a, b);
  const double room = profile_.smoothing.max_block_share * std::min(la, lb);
  if (t.kind == Tolerance::Distance) {
    if (t.distance <= 0) return 0.0;
    const double d = std::min(t.distance, room);
    return d < (1.0 - profile_.smoothing.adis_max_reduction) * t.distance ? 0.0 : d;
  }
  // deviation = k·d·|u2 - u1| (per axis k·d·|u2_i - u1_i|): d = tol / (k·|u2 - u1|).
  const double k = blend_deviation_factor(blend_continuity(a.smoothing.code));
  const Vec3 turn = u2 - u1;
  double d = kInf;
  if (t.kind == Tolerance::Contour) {
    d = t.contour / (k * turn.norm());
  } else {
    for (int i = 0; i < 3; ++i)
      if (std::abs(turn[i]) > 1e-12) d = std::min(d, t.axes[i] / (k * std::abs(turn[i])));
  }
  return std::min(d, room);
}

double CornerSmoothing::programmed_velocity(const PathElement& e, const Vec3& u) const {
  double v = e.rapid ? kInf : e.feed_mm_s;
  // The short-block rule (a block lasts at least one IPO cycle): between very short blocks G64
  // does not slow down at the corner below what the blocks allow anyway.
  if (!e.inserted) v = std::min(v, profile_.short_block_factor * programmed_length(e) / profile_.ipo_cycle_s);
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > 1e-12) v = std::min(v, profile_.axes[static_cast<size_t>(i)].max_velocity_mm_s / std::abs(u[i]));
  return v;
}

double CornerSmoothing::g64_corner_velocity(const PathElement& a, const Vec3& u1, const Vec3& u2) const {
  // The planner's CornerConstraint: each axis velocity may jump by a_i·(OVL - 1)·T_IPO.
  const double group = profile_.dynamic_groups[static_cast<size_t>(a.dynamics.group)].max_ax_accel;
  const double allowed = (profile_.max_accel_ovl_factor - 1.0) * profile_.ipo_cycle_s * group;
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double jump = std::abs(u2[i] - u1[i]);
    if (jump > 1e-12) v = std::min(v, profile_.axes[static_cast<size_t>(i)].max_accel_mm_s2 * allowed / jump);
  }
  return v;
}

double CornerSmoothing::rounding_velocity(const geometry::PolynomialSpan& curve, const PathElement& a) const {
  // The planner's point limits (motion/path_constraints.hpp) at 9 points of the rounding:
  // centripetal v^2 |kappa_i| <= share a_i and, under SOFT, v^3 |d3P/ds3_i| <= j_i.
  const auto& group = profile_.dynamic_groups[static_cast<size_t>(a.dynamics.group)];
  const bool soft = a.dynamics.profile == AccelProfile::Soft;
  const double accel_factor = a.rapid ? profile_.g0_accel_factor : (soft ? profile_.soft_accel_factor : 1.0);
  const double jerk_factor = a.rapid ? profile_.g0_jerk_factor : 1.0;
  double v = kInf;
  for (int k = 0; k <= 8; ++k) {
    // By parameter (the arc-length inversion of at() would cost more than the rest of the stage).
    const geometry::CurvePoint p =
        geometry::PolynomialSpan::by_arc_length(curve.derivatives(curve.parameter_end() * k / 8.0));
    for (int i = 0; i < 3; ++i) {
      const auto& axis = profile_.axes[static_cast<size_t>(i)];
      const double kappa = std::abs(p.curvature_vector[i]), rate = std::abs(p.curvature_rate[i]);
      if (kappa > 1e-15)
        v = std::min(v, std::sqrt(profile_.curv_effect_on_path_accel * axis.max_accel_mm_s2 * group.max_ax_accel *
                                  accel_factor / kappa));
      if (soft && rate > 1e-15) v = std::min(v, std::cbrt(axis.max_jerk_mm_s3 * group.max_ax_jerk * jerk_factor / rate));
    }
  }
  return v;
}

std::optional<CornerSmoothing::Rounding> CornerSmoothing::fit_rounding(const PathElement& a, const PathElement& b,
                                                                       const Vec3& u1, const Vec3& u2,
                                                                       double d) const {
  const Vec3 corner = a.curve->end();
  const BlendContinuity continuity = blend_continuity(a.smoothing.code);
  if (is_line(a) && is_line(b)) {  // closed form (corner_smoothing.hpp)
    return Rounding{std::make_shared<geometry::PolynomialSpan>(corner_blend_curve(corner, u1, u2, d, continuity)), d,
                    corner_blend_deviation(u1, u2, d, continuity)};
  }
  // An arc or spline neighbour: the same Bezier shape between the points d before and after the
  // corner along the curves, with their tangents there (tangent-continuous; the curvature of a
  // curved neighbour is not matched). Its deviation is measured (the closest of 65 points to the
  // corner); outside the tolerance d shrinks by a quarter, at most 8 times.
  const Tolerance t = tolerance(a, b);
  const double k = continuity == BlendContinuity::Curvature ? 3.0 : 2.0;
  const double la = a.curve->length();
  for (int attempt = 0; attempt < 8; ++attempt, d *= 0.75) {
    const geometry::CurvePoint p0 = a.curve->at(la - d), p3 = b.curve->at(d);
    auto span = std::make_shared<geometry::PolynomialSpan>(
        geometry::PolynomialSpan::hermite(p0.position, p3.position, k * d * p0.tangent, k * d * p3.tangent, 1.0));
    Vec3 offset = p0.position - corner;
    for (int i = 1; i <= 64; ++i) {
      const Vec3 q = span->derivatives(i / 64.0).p - corner;
      if (q.squaredNorm() < offset.squaredNorm()) offset = q;
    }
    bool within = true;
    if (t.kind == Tolerance::Contour) within = offset.norm() <= t.contour;
    if (t.kind == Tolerance::Axes)
      for (int i = 0; i < 3; ++i) within = within && std::abs(offset[i]) <= t.axes[i];
    if (within) return Rounding{std::move(span), d, offset.norm()};
  }
  return std::nullopt;
}

bool CornerSmoothing::round_corner(PathElement& b) {
  PathElement& a = *pending_;
  if (!roundable_kind(b) || b.rapid != a.rapid || b.dynamics.profile != a.dynamics.profile || !b.extra_axes.empty() ||
      !b.positioning.empty())
    return false;
  const double lb = b.curve->length();
  const Vec3 corner = a.curve->end();
  if (lb <= kMinLength || (b.curve->start() - corner).norm() > 1e-9 * (1.0 + corner.norm())) return false;
  const Vec3 u1 = a.curve->at(a.curve->length()).tangent, u2 = b.curve->at(0.0).tangent;
  const double cos_turn = u1.dot(u2);
  if (cos_turn > kMinTurnCos || cos_turn < kMaxTurnCos) return false;
  const double v = std::min(programmed_velocity(a, u1), programmed_velocity(b, u2));
  const double g64_velocity = std::min(v, g64_corner_velocity(a, u1, u2));
  const bool check_ovl = a.smoothing.code != 643 && !profile_.smoothing.ignore_ovl_factor;
  if (check_ovl && g64_velocity >= v) return false;  // G64 passes without slowing
  const double d = trim_distance(a, b, u1, u2, programmed_length(a), lb);
  if (d <= kMinLength) return false;
  std::optional<Rounding> rounding = fit_rounding(a, b, u1, u2, d);
  if (!rounding) return false;
  // The rounding is a block: at least one IPO cycle (short-block rule). Where that holds it to
  // no more than G64 allows at the corner, it would slow the path: none (FB1 "very short blocks").
  // Nor where its curvature holds the path below the G64 corner velocity (tiny roundings under
  // SOFT): drycut's reading of "the rounding block would slow down the program" (FB1).
  if (profile_.short_block_factor * rounding->curve->length() / profile_.ipo_cycle_s <= g64_velocity) return false;
  if (rounding_velocity(*rounding->curve, a) <= g64_velocity) return false;
  hand_on(b, std::move(*rounding));
  return true;
}

void CornerSmoothing::hand_on(PathElement& b, Rounding rounding) {
  PathElement& a = *pending_;
  PathElement blend;
  blend.kind = ElementKind::SplineSpan;
  blend.curve = std::move(rounding.curve);
  blend.rapid = a.rapid;
  blend.feed_mm_s = std::min(a.feed_mm_s, b.feed_mm_s);
  blend.feed_scale = a.feed_scale;
  blend.inserted = true;
  blend.dynamics = a.dynamics;
  blend.compensation = a.compensation;
  blend.label = smoothing_label(a.smoothing.code);
  blend.source = a.source;
  blend.smoothing = a.smoothing;
  blend.smoothing_deviation_mm = rounding.deviation;
  blend.compressor = a.compressor;

  const double d = rounding.trim;
  a.block_length_mm = programmed_length(a);
  const double la = a.curve->length();
  if (la - d > kMinLength) {  // else the rounding took all that was left of it
    a.curve = geometry::trim_curve(a.curve, 0.0, la - d);
    next_.consume(std::move(a));
  }
  pending_.reset();
  next_.consume(std::move(blend));
  ++corners_;

  const double lb = b.curve->length();
  b.block_length_mm = programmed_length(b);
  b.curve = geometry::trim_curve(b.curve, d, lb);
  if (holds(b)) {
    pending_ = std::move(b);
  } else {
    next_.consume(std::move(b));
  }
}

}  // namespace drycut::interp
