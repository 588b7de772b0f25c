#include "motion/element_discretisation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"

namespace drycut::motion {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxDepth = 24;
constexpr double kInfSpread = std::numeric_limits<double>::infinity();

// Angles β + k·period (k integer) strictly inside the sweep, as arc lengths.
void add_periodic(double beta, double period, double phi0, double sweep, double speed, std::vector<double>& out) {
  const double lo = std::min(phi0, phi0 + sweep), hi = std::max(phi0, phi0 + sweep);
  for (double phi = beta + std::ceil((lo - beta) / period) * period; phi < hi; phi += period) {
    if (phi > lo) out.push_back(std::abs(phi - phi0) * speed);
  }
}

void arc_critical_lengths(const geometry::ArcCurve& arc, double length, std::vector<double>& out) {
  const double sweep = arc.sweep();
  if (sweep == 0.0 || arc.radius() <= 0.0) return;  // straight axial move: constant limits
  const double speed = length / std::abs(sweep);
  const double pitch = arc.axial_travel() / sweep;
  const Vec3& e1 = arc.first_axis();
  const Vec3& e2 = arc.second_axis();
  const Vec3 n = arc.normal();
  for (int i = 0; i < 3; ++i) {
    const double r_i = std::hypot(e1[i], e2[i]);
    if (r_i < 1e-12) continue;  // the axis is along the normal: t_i, κ_i constant
    const double alpha = std::atan2(e2[i], e1[i]);
    add_periodic(alpha, kPi / 2, arc.start_angle(), sweep, speed, out);
    // t_i = 0 on a helix: r·R_i·sin(φ - α) = p·n_i.
    const double q = pitch * n[i] / (arc.radius() * r_i);
    if (pitch != 0.0 && std::abs(q) < 1.0) {
      add_periodic(alpha + std::asin(q), 2 * kPi, arc.start_angle(), sweep, speed, out);
      add_periodic(alpha + kPi - std::asin(q), 2 * kPi, arc.start_angle(), sweep, speed, out);
    }
  }
}

double spread(double a, double b, double c) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) {
    // Infinite on all three: no limit. Mixed: a limit appears on part of the piece.
    return (std::isinf(a) && std::isinf(b) && std::isinf(c)) ? 0.0 : kInfSpread;
  }
  const double lo = std::min({a, b, c}), hi = std::max({a, b, c});
  return lo > 0 ? hi / lo - 1.0 : (hi > 0 ? kInfSpread : 0.0);
}

bool constant_bound(const VelocityBound& b) { return b.limit == Limit::Feed || b.limit == Limit::ShortBlock; }

struct Refiner {
  const DiscretisationRule& rule;
  const StationEvaluator& evaluate;
  double length;
  std::vector<Station>& out;

  // The ramp limits matter on [a, b] only where a ramp can run: within the distance of a ramp
  // from rest to the bound of the element's ends (junction dips, stops), and the acceleration
  // only when such a ramp can reach it (BRISK, or Δv > a²/j under SOFT).
  bool ramp_matters(const Station& a, const Station& b) const {
    const double v = std::max(a.bound.velocity, b.bound.velocity);
    if (!std::isfinite(v)) return true;
    const RampLimits lo{std::min(a.ramp.accel, b.ramp.accel), std::min(a.ramp.jerk, b.ramp.jerk)};
    const double zone = ramp_distance(0.0, v, lo);
    return a.s < zone || b.s > length - zone;
  }

  bool accel_can_bind(const Station& a, const Station& b) const {
    const double v = std::max(a.bound.velocity, b.bound.velocity);
    const double accel = std::min(a.ramp.accel, b.ramp.accel);
    const double jerk = std::max(a.ramp.jerk, b.ramp.jerk);
    return !std::isfinite(jerk) || v > accel * accel / jerk;
  }

  // Appends the stations after `a` up to and including `b`.
  void refine(const Station& a, const Station& b, int depth) {
    const int budget = rule.max_segments - static_cast<int>(out.size());
    if (depth < kMaxDepth && budget > 2 && b.s - a.s > 2 * rule.min_piece_mm) {
      // Both ends at the feed: every varying limit is above it over the whole (monotone) piece.
      const bool check_bound = !(a.bound.velocity == b.bound.velocity && constant_bound(a.bound) &&
                                 constant_bound(b.bound));
      const bool check_ramp = ramp_matters(a, b);
      if (check_bound || check_ramp) {
        const Station m = evaluate(0.5 * (a.s + b.s));
        const bool split =
            spread(a.bound.velocity, m.bound.velocity, b.bound.velocity) > rule.bound_tolerance ||
            (check_ramp && spread(a.ramp.jerk, m.ramp.jerk, b.ramp.jerk) > rule.ramp_tolerance) ||
            (check_ramp && accel_can_bind(a, b) &&
             spread(a.ramp.accel, m.ramp.accel, b.ramp.accel) > rule.ramp_tolerance);
        if (split) {
          refine(a, m, depth + 1);
          refine(m, b, depth + 1);
          return;
        }
      }
    }
    out.push_back(b);
  }
};

}  // namespace

bool discretise_element(const geometry::Curve& curve, double length, double fine_step_mm,
                        const DiscretisationRule& rule, const StationEvaluator& evaluate,
                        std::vector<Station>& out) {
  out.clear();
  out.push_back(evaluate(0.0));
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(&curve);
  if (rule.fixed_segment_mm > 0 || !arc) {
    const double step = rule.fixed_segment_mm > 0 ? rule.fixed_segment_mm : fine_step_mm;
    const double n = std::clamp(std::ceil(length / step), 1.0, double(rule.max_segments));
    const double h = length / n;
    const auto count = static_cast<size_t>(n);
    for (size_t k = 1; k <= count; ++k) out.push_back(evaluate(k == count ? length : h * static_cast<double>(k)));
    return false;
  }
  thread_local std::vector<double> cuts;
  cuts.clear();
  arc_critical_lengths(*arc, length, cuts);
  std::sort(cuts.begin(), cuts.end());
  Refiner refiner{rule, evaluate, length, out};
  double last = 0.0;
  for (double s : cuts) {
    // Critical points closer than 1 µm to each other or to the ends add nothing.
    if (s - last <= 1e-3 || length - s <= 1e-3) continue;
    const Station a = out.back();
    refiner.refine(a, evaluate(s), 0);
    last = s;
  }
  const Station a = out.back();
  refiner.refine(a, evaluate(length), 0);
  static struct C { size_t n = 0, e = 0; ~C() { if (std::getenv("DRYCUT_STATS")) std::fprintf(stderr, "arcs %zu segments %zu\n", e, n); } } c;  // TEMP
  c.n += out.size() - 1; ++c.e;
  return true;
}

}  // namespace drycut::motion
