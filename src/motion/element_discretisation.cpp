#include "motion/element_discretisation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>
#include <typeinfo>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/polynomial_span.hpp"
#include "motion/velocity_ramp.hpp"

namespace drycut::motion {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxDepth = 24;

// The station at arc length s of the curve, with the limits of its point.
// (The curve's point is built in the station: no copy of it.)
Station station_at(const geometry::Curve& curve, double s, const PointLimits& limits_at) {
  Station st{s, curve.at(s), {}, {}, {}, {}};
  const LocalLimits limits = limits_at(st.point);
  st.bound = limits.bound;
  st.ramp = limits.ramp;
  return st;
}

void arc_critical_lengths(const geometry::ArcCurve& arc, double length, std::vector<double>& out) {
  const double sweep = arc.sweep();
  if (sweep == 0.0 || arc.radius() <= 0.0) return;  // straight axial move: constant limits
  const double speed = length / std::abs(sweep);
  const double pitch = arc.axial_travel() / sweep;
  const Vec3 n = arc.normal();
  // Angles strictly inside the sweep, as arc lengths from the start.
  auto add = [&](double beta, double period) {
    arc.for_each_angle_inside(beta, period, [&](double phi) { out.push_back(std::abs(phi - arc.start_angle()) * speed); });
  };
  for (int i = 0; i < 3; ++i) {
    const double r_i = arc.axis_radius(i);
    if (r_i < 1e-12) continue;  // the axis is along the normal: t_i, κ_i constant
    const double alpha = arc.axis_phase(i);
    add(alpha, kPi / 2);
    // t_i = 0 on a helix: r·R_i·sin(φ - α) = p·n_i.
    const double q = pitch * n[i] / (arc.radius() * r_i);
    if (pitch != 0.0 && std::abs(q) < 1.0) {
      add(alpha + std::asin(q), 2 * kPi);
      add(alpha + kPi - std::asin(q), 2 * kPi);
    }
  }
}


// True when some β + k·period lies strictly inside (lo, hi): the first one above lo is below hi.
// (The first one at or above lo was tested before: one lying exactly at lo hid the next, so a
// full circle from a quadrant point had no quadrant point inside.)
bool angle_inside(double beta, double period, double lo, double hi) {
  const double phi = beta + (std::floor((lo - beta) / period) + 1.0) * period;
  return phi > lo && phi < hi;
}

// True when `worst` is within `tolerance` of the better end (the piece's limit hardly varies).
bool close_to(double worst, double a, double b, double tolerance) {
  const double best = std::max(a, b);
  if (!std::isfinite(best)) return !std::isfinite(worst);
  return worst >= best * (1.0 - tolerance);
}

// The ramp limits matter on [a, b] only where a ramp can run: within the distance of a ramp
// from rest to the bound of the element's ends (junction dips, stops), and the acceleration
// only when such a ramp can reach it (BRISK, or Δv > a²/j under SOFT).
bool ramp_matters(double length, const Station& a, const Station& b) {
  const double v = std::max(a.bound.velocity, b.bound.velocity);
  if (!std::isfinite(v)) return true;
  const RampLimits lo{std::min(a.ramp.accel, b.ramp.accel), std::min(a.ramp.jerk, b.ramp.jerk)};
  const double zone = ramp_distance(0.0, v, lo);
  return a.s < zone || b.s > length - zone;
}

// Tolerance on the ramp acceleration: a ramp up to v spends only the part of its velocity
// change above a²/j at the acceleration limit (SOFT), so the tolerance on the ramp time is
// met with a proportionally larger one on the acceleration; infinite when it cannot bind.
double accel_tolerance(const DiscretisationRule& rule, const Station& a, const Station& b) {
  const double v = std::max(a.bound.velocity, b.bound.velocity);
  const double jerk = std::max(a.ramp.jerk, b.ramp.jerk);
  const double accel = std::min(a.ramp.accel, b.ramp.accel);
  if (!std::isfinite(jerk)) return rule.ramp_tolerance;
  const double at_limit = v - accel * accel / jerk;
  return at_limit > 0 ? rule.ramp_tolerance * v / at_limit : std::numeric_limits<double>::infinity();
}

// Step 2 of the rule: the piece [a, b] with worst case w keeps its limits within tolerance
// (the velocity bound: unless `bound_checked`, which step 6 of sampled pieces has shown).
bool piece_acceptable(const DiscretisationRule& rule, double length, const Station& a, const Station& b,
                      const LocalLimits& w, bool bound_checked = false) {
  if (!bound_checked && !close_to(w.bound.velocity, a.bound.velocity, b.bound.velocity, rule.bound_tolerance))
    return false;
  if (!ramp_matters(length, a, b)) return true;
  if (!close_to(w.ramp.jerk, a.ramp.jerk, b.ramp.jerk, rule.ramp_tolerance)) return false;
  const double tolerance = accel_tolerance(rule, a, b);
  return tolerance >= 1 || close_to(w.ramp.accel, a.ramp.accel, b.ramp.accel, tolerance);
}

struct ArcRefiner {
  const geometry::ArcCurve& arc;
  double length;
  const DiscretisationRule& rule;
  const PointLimits& limits_at;
  std::vector<double>& critical;  // ascending arc lengths, filled on the first split
  std::vector<Station>& out;
  bool critical_known = false;
  std::array<double, 3> axis_radius{}, axis_phase{};  // R_i and α_i

  void prepare() {
    for (int i = 0; i < 3; ++i) {
      axis_radius[static_cast<size_t>(i)] = arc.axis_radius(i);
      axis_phase[static_cast<size_t>(i)] = arc.axis_phase(i);
    }
  }

  Station station(double s) const { return station_at(arc, s, limits_at); }

  double angle(double s) const { return arc.start_angle() + (arc.sweep() > 0 ? s : -s) * std::abs(arc.sweep()) / length; }

  // Per axis the largest |t_i|, |κ_i| and |d³P/ds³_i| over [a, b]: at an end or at an interior
  // extreme of radial_i / along_i (see the header). Every point constraint is a minimum over
  // axes of a function falling in these, so the limits of this point are the worst case.
  CurvePoint worst_point(const Station& a, const Station& b) const {
    CurvePoint w = a.point;
    const double lo = std::min(angle(a.s), angle(b.s)), hi = std::max(angle(a.s), angle(b.s));
    const double r = arc.radius(), speed = length / std::abs(arc.sweep());
    const double pitch = arc.axial_travel() / arc.sweep();
    const Vec3 n = arc.normal();
    for (int i = 0; i < 3; ++i) {
      double t = std::max(std::abs(a.point.tangent[i]), std::abs(b.point.tangent[i]));
      double k = std::max(std::abs(a.point.curvature_vector[i]), std::abs(b.point.curvature_vector[i]));
      double rate = std::max(std::abs(a.point.curvature_rate[i]), std::abs(b.point.curvature_rate[i]));
      const double r_i = axis_radius[static_cast<size_t>(i)];
      if (r_i > 1e-12) {
        const double alpha = axis_phase[static_cast<size_t>(i)];
        if (angle_inside(alpha, kPi, lo, hi)) k = r * r_i / (speed * speed);
        if (angle_inside(alpha + kPi / 2, kPi, lo, hi)) rate = r * r_i / (speed * speed * speed);
        // along_i = -R_i at α + π/2, +R_i at α + 3π/2: t_i = (r·along_i + p·n_i)/speed there.
        if (angle_inside(alpha + kPi / 2, 2 * kPi, lo, hi)) t = std::max(t, std::abs(-r * r_i + pitch * n[i]) / speed);
        if (angle_inside(alpha + 3 * kPi / 2, 2 * kPi, lo, hi)) t = std::max(t, std::abs(r * r_i + pitch * n[i]) / speed);
      }
      w.tangent[i] = t;
      w.curvature_vector[i] = k;
      w.curvature_rate[i] = rate;
    }
    return w;
  }

  // Per axis the smallest |t_i|, |κ_i| and |d³P/ds³_i| over [a, b] (a zero of along_i or radial_i
  // inside, else the smaller end): the limits of this point bound the best the piece offers
  // anywhere, which may lie inside it (a circle from quadrant point to quadrant point has its
  // best axis velocity and acceleration limits at 45 degrees, both ends are equally bad).
  CurvePoint best_point(const Station& a, const Station& b) const {
    CurvePoint p = a.point;
    const double lo = std::min(angle(a.s), angle(b.s)), hi = std::max(angle(a.s), angle(b.s));
    const double speed = length / std::abs(arc.sweep());
    const double pitch = arc.axial_travel() / arc.sweep();
    const Vec3 n = arc.normal();
    for (int i = 0; i < 3; ++i) {
      double t = std::min(std::abs(a.point.tangent[i]), std::abs(b.point.tangent[i]));
      double k = std::min(std::abs(a.point.curvature_vector[i]), std::abs(b.point.curvature_vector[i]));
      double rate = std::min(std::abs(a.point.curvature_rate[i]), std::abs(b.point.curvature_rate[i]));
      const double alpha = axis_phase[static_cast<size_t>(i)];
      if (axis_radius[static_cast<size_t>(i)] > 1e-12) {
        // along_i = 0 at α + kπ (t_i is the helix part alone there, rate_i zero), radial_i = 0 at α + π/2 + kπ.
        if (angle_inside(alpha, kPi, lo, hi)) {
          t = std::min(t, std::abs(pitch * n[i]) / speed);
          rate = 0.0;
        }
        if (angle_inside(alpha + kPi / 2, kPi, lo, hi)) k = 0.0;
      }
      p.tangent[i] = t;
      p.curvature_vector[i] = k;
      p.curvature_rate[i] = rate;
    }
    return p;
  }

  // Step 2 against the best the piece offers (its ends, or better inside: best_point). The
  // inside is looked at only where the velocity bound is set by the geometry: one set by F or
  // the short-block rule is the same everywhere (the ramps inside are then judged by the ends,
  // as before; looking inside those pieces too cost the G2/G3 bench program 4 % more).
  bool acceptable(const Station& a, const Station& b, const LocalLimits& w) const {
    if (!piece_acceptable(rule, length, a, b, w)) return false;
    if (w.bound.limit == Limit::Feed || w.bound.limit == Limit::ShortBlock) return true;
    const LocalLimits best = limits_at(best_point(a, b));
    Station ha = a, hb = b;
    for (Station* h : {&ha, &hb}) {
      h->bound.velocity = std::max({a.bound.velocity, b.bound.velocity, best.bound.velocity});
      h->ramp.jerk = std::max({a.ramp.jerk, b.ramp.jerk, best.ramp.jerk});
      h->ramp.accel = std::max({a.ramp.accel, b.ramp.accel, best.ramp.accel});
    }
    return piece_acceptable(rule, length, ha, hb, w);
  }

  // Appends the stations after `a` up to and including `b`.
  void refine(const Station& a, Station b, int depth) {
    const LocalLimits w = limits_at(worst_point(a, b));
    const int budget = rule.max_segments - static_cast<int>(out.size());
    const bool can_split = depth < kMaxDepth && budget > 8 && b.s - a.s > 2 * rule.min_piece_mm;
    if (!can_split || acceptable(a, b, w)) {
      b.piece_bound = w.bound;
      b.piece_ramp = w.ramp;
      out.push_back(b);
      return;
    }
    // Split at the critical points inside (the pieces become monotone), else in the middle.
    if (!critical_known) {
      arc_critical_lengths(arc, length, critical);
      std::sort(critical.begin(), critical.end());
      critical_known = true;
    }
    const auto first = std::upper_bound(critical.begin(), critical.end(), a.s + rule.min_piece_mm);
    const auto last = std::lower_bound(critical.begin(), critical.end(), b.s - rule.min_piece_mm);
    Station from = a;
    if (first < last) {
      for (auto it = first; it != last; ++it) {
        Station at = station(*it);
        refine(from, at, depth + 1);
        from = std::move(at);
      }
    } else {
      Station m = station(0.5 * (a.s + b.s));
      refine(a, m, depth + 1);
      from = std::move(m);
    }
    refine(from, std::move(b), depth + 1);
  }
};


// Curves without a closed form (spline spans, offset curves): the worst case of a piece is that
// of the per-axis largest |t_i|, |κ_i|, |P'''_i| (and curvature) of its ends and its midpoint;
// a piece whose limits vary beyond the tolerances is halved (the midpoint becomes a node).
struct SampledRefiner {
  const geometry::Curve& curve;
  double length;
  const DiscretisationRule& rule;
  const PointLimits& limits_at;
  std::vector<Station>& out;
  const geometry::PolynomialSpan* span = nullptr;  // set: halve in its parameter (header, step 4)

  Station station(double s) const { return station_at(curve, s, limits_at); }

  // The midpoint of [a, b], whose span parameters are ua and ub: a spline span's is at the mean
  // parameter um, its arc length from the span's table (no inversion); any other curve's at the
  // mean arc length (um unused).
  Station midpoint(const Station& a, double ua, const Station& b, double ub, double& um) const {
    if (!span) return station(0.5 * (a.s + b.s));
    um = 0.5 * (ua + ub);
    Station m{span->arc_length_at(um), geometry::PolynomialSpan::by_arc_length(span->derivatives(um)), {}, {}, {}, {}};
    const LocalLimits limits = limits_at(m.point);
    m.bound = limits.bound;
    m.ramp = limits.ramp;
    return m;
  }

  // The tangent turns by at most max_sampled_turn from a to m and from m to b: the per-axis
  // components then behave like cos/sin over a small angle, and an extreme between the samples
  // exceeds the nearest sample by at most 1 - cos(turn/2) (0.03 % at 0.05 rad).
  bool turns_little(const Station& a, const Station& m, const Station& b) const {
    const double c = std::cos(rule.max_sampled_turn);
    return a.point.tangent.dot(m.point.tangent) >= c && m.point.tangent.dot(b.point.tangent) >= c;
  }

  static CurvePoint worst_point(const Station& a, const Station& m, const Station& b) {
    CurvePoint w = m.point;
    const CurvePoint* p[3] = {&a.point, &m.point, &b.point};
    for (int i = 0; i < 3; ++i) {
      for (const CurvePoint* q : p) {
        w.tangent[i] = std::max(w.tangent[i], std::abs(q->tangent[i]));
        w.curvature_vector[i] = std::max(w.curvature_vector[i], std::abs(q->curvature_vector[i]));
        w.curvature_rate[i] = std::max(w.curvature_rate[i], std::abs(q->curvature_rate[i]));
      }
    }
    w.curvature = std::max({a.point.curvature, m.point.curvature, b.point.curvature});
    return w;
  }

  // Step 6: the bound varies monotonely over the samples, their lowest is no sampled local
  // minimum (the sample beyond the piece's lower end, beyond_a or beyond_b, is lower still: a
  // minimum between samples would hide next to a sampled one), and a ramp from the worst of
  // them (the ends' better ramp limits; an upper bound of its reach) gains at most
  // sampled_reach_tolerance over the piece: the planner could not follow the variation.
  bool ramp_bound(const Station& a, const Station& m, const Station& b, const LocalLimits& w, double beyond_a,
                  double beyond_b) const {
    const double va = a.bound.velocity, vm = m.bound.velocity, vb = b.bound.velocity, v = w.bound.velocity;
    if (!((va <= vm && vm <= vb) || (va >= vm && vm >= vb)) || !std::isfinite(v) || !(v > 0.0)) return false;
    if (!(va <= vb ? beyond_a < va : beyond_b < vb)) return false;
    const RampLimits best{std::max(a.ramp.accel, b.ramp.accel), std::max(a.ramp.jerk, b.ramp.jerk)};
    return reach_upper_bound(v, b.s - a.s, best) <= v * (1.0 + rule.sampled_reach_tolerance);
  }

  bool acceptable(const Station& a, const Station& m, const Station& b, const LocalLimits& w, double beyond_a,
                  double beyond_b) const {
    if (!turns_little(a, m, b)) return false;
    return piece_acceptable(rule, length, a, b, w) ||
           (ramp_bound(a, m, b, w, beyond_a, beyond_b) && piece_acceptable(rule, length, a, b, w, true));
  }

  // beyond_a, beyond_b: the bound of the sample next to a (before it) and to b (after it);
  // -infinity at the element's ends, which are nodes of their own. ua, ub: the span parameters
  // of a and b (spline spans).
  void refine(const Station& a, double ua, Station b, double ub, int depth, double beyond_a, double beyond_b) {
    double um = 0.0;
    Station m = midpoint(a, ua, b, ub, um);
    const LocalLimits w = limits_at(worst_point(a, m, b));
    const int budget = rule.max_segments - static_cast<int>(out.size());
    const bool can_split = depth < kMaxDepth && budget > 8 && b.s - a.s > 2 * rule.min_piece_mm;
    if (!can_split || acceptable(a, m, b, w, beyond_a, beyond_b)) {
      b.piece_bound = w.bound;
      b.piece_ramp = w.ramp;
      out.push_back(std::move(b));
      return;
    }
    const double va = a.bound.velocity, vb = b.bound.velocity;
    refine(a, ua, m, um, depth + 1, beyond_a, vb);
    const Station from = out.back();
    refine(from, um, std::move(b), ub, depth + 1, va, beyond_b);
  }
};

}  // namespace

bool discretise_element(const geometry::Curve& curve, double length, double fine_step_mm,
                        const DiscretisationRule& rule, const PointLimits& limits_at,
                        std::vector<Station>& out) {
  out.clear();
  auto station = [&](double s) { return station_at(curve, s, limits_at); };
  out.push_back(station(0.0));
  // ArcCurve is final, so comparing the dynamic type is the dynamic_cast's answer; a failing
  // __dynamic_cast walked the class hierarchy (~180 instructions per spline span).
  static_assert(std::is_final_v<geometry::ArcCurve>);
  const auto* arc =
      typeid(curve) == typeid(geometry::ArcCurve) ? static_cast<const geometry::ArcCurve*>(&curve) : nullptr;
  if (!rule.equal_segments && !arc && length > fine_step_mm) {
    DiscretisationRule sampled = rule;
    sampled.bound_tolerance = rule.sampled_bound_tolerance;
    sampled.ramp_tolerance = rule.sampled_ramp_tolerance;
    // A span's parameter runs over [0, parameter_end()] (PolynomialSpan is final: the typeid test).
    static_assert(std::is_final_v<geometry::PolynomialSpan>);
    const auto* span = typeid(curve) == typeid(geometry::PolynomialSpan)
                           ? static_cast<const geometry::PolynomialSpan*>(&curve) : nullptr;
    SampledRefiner refiner{curve, length, sampled, limits_at, out, span};
    const Station start = out.back();
    constexpr double kOpen = -std::numeric_limits<double>::infinity();
    refiner.refine(start, 0.0, station(length), span ? span->parameter_end() : 0.0, 0, kOpen, kOpen);
    return true;
  }
  if (rule.equal_segments || !arc || arc->sweep() == 0.0) {
    // Equal segments; an axial move without sweep has constant limits and gets one.
    const double step = rule.equal_segments && rule.fixed_segment_mm > 0 ? rule.fixed_segment_mm
                        : (arc && !rule.equal_segments)                  ? length
                                                                         : fine_step_mm;
    const double n = std::clamp(std::ceil(length / step), 1.0, double(rule.max_segments));
    const double h = length / n;
    const auto count = static_cast<size_t>(n);
    for (size_t k = 1; k <= count; ++k) {
      Station st = station(k == count ? length : h * static_cast<double>(k));
      const Station& prev = out.back();
      st.piece_bound = prev.bound.velocity <= st.bound.velocity ? prev.bound : st.bound;
      st.piece_ramp = {std::min(prev.ramp.accel, st.ramp.accel), std::min(prev.ramp.jerk, st.ramp.jerk)};
      out.push_back(std::move(st));
    }
    return false;
  }
  thread_local std::vector<double> critical;
  critical.clear();
  ArcRefiner refiner{*arc, length, rule, limits_at, critical, out};
  refiner.prepare();
  const Station start = out.back();
  refiner.refine(start, station(length), 0);
  return true;
}

}  // namespace drycut::motion
