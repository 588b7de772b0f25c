#include "interp/geometry/compressor_fit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "interp/geometry/cubic_spline_tangents.hpp"
#include "interp/geometry/parabola_tangent.hpp"
#include "interp/geometry/polynomial_span.hpp"

namespace drycut::geometry {
namespace {

constexpr double kSampleShares[3] = {0.25, 0.5, 0.75};

// Cubic Hermite curve on u in [0, h].
Vec3 hermite_at(const Vec3& p0, const Vec3& p1, const Vec3& m0, const Vec3& m1, double h, double u) {
  const double s = u / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * m1;
}

// One piece of a run: programmed points [a, b] without a corner inside, b - a >= 2.
class PieceFit {
 public:
  PieceFit(std::span<const Vec3> points, size_t a, size_t b, const CompressorFitOptions& options,
           std::optional<Vec3> start_tangent)
      : p_(points.subspan(a, b - a + 1)), a_(a), options_(options), start_tangent_(start_tangent) {
    t_.resize(p_.size());
    t_[0] = 0.0;
    for (size_t i = 1; i < p_.size(); ++i) t_[i] = t_[i - 1] + (p_[i] - p_[i - 1]).norm();
  }

  void run(std::vector<FittedSpan>& out);

 private:
  size_t segments() const { return p_.size() - 1; }
  std::vector<size_t> initial_knots() const;
  std::vector<Vec3> knot_tangents(const std::vector<size_t>& knots) const;
  // Largest deviation on the span between knots k0 < k1; `ok` whether it is inside the band.
  double check_span(size_t k0, size_t k1, const Vec3& m0, const Vec3& m1, bool& ok) const;
  bool inside(const Vec3& deviation) const {
    if (options_.contour_tolerance) return deviation.norm() <= options_.margin * options_.contour_tol_mm;
    return (deviation.cwiseAbs().array() <= options_.margin * options_.axis_tol_mm.array()).all();
  }
  void split_around(const std::vector<size_t>& given_up, std::vector<FittedSpan>& out) const;

  std::span<const Vec3> p_;
  size_t a_;
  const CompressorFitOptions& options_;
  std::optional<Vec3> start_tangent_;
  std::vector<double> t_;
};

void fit_range(std::span<const Vec3> points, size_t a, size_t b, const CompressorFitOptions& options,
               std::optional<Vec3> start_tangent, std::vector<FittedSpan>& out) {
  if (b - a == 1) {
    FittedSpan line;
    line.first = a;
    line.last = b;
    line.end_tangent = (points[b] - points[a]).normalized();
    out.push_back(std::move(line));
    return;
  }
  PieceFit(points, a, b, options, start_tangent).run(out);
}

std::vector<size_t> PieceFit::initial_knots() const {
  // COMPCAD: the whole piece is one span to begin with; refinement halves where needed.
  const size_t spacing = options_.max_segments_per_span > 0 ? options_.max_segments_per_span : segments();
  std::vector<size_t> knots;
  for (size_t k = 0; k < segments(); k += spacing) knots.push_back(k);
  knots.push_back(segments());
  return knots;
}

std::vector<Vec3> PieceFit::knot_tangents(const std::vector<size_t>& knots) const {
  const size_t m = segments();
  const Vec3 begin = start_tangent_ ? *start_tangent_
                                    : parabola_start_tangent(p_[0], p_[1], p_[2], t_[1] - t_[0], t_[2] - t_[1]);
  const Vec3 end = parabola_end_tangent(p_[m - 2], p_[m - 1], p_[m], t_[m - 1] - t_[m - 2], t_[m] - t_[m - 1]);
  if (options_.continuity == FitContinuity::C1) {
    std::vector<Vec3> tangents(knots.size());
    for (size_t j = 0; j < knots.size(); ++j) {
      const size_t k = knots[j];
      if (k == 0) { tangents[j] = begin; continue; }
      if (k == m) { tangents[j] = end; continue; }
      // Bessel: the parabola through the knot and its programmed neighbours, at the knot.
      const double h0 = t_[k] - t_[k - 1], h1 = t_[k + 1] - t_[k];
      tangents[j] = (h1 * (p_[k] - p_[k - 1]) / h0 + h0 * (p_[k + 1] - p_[k]) / h1) / (h0 + h1);
    }
    return tangents;
  }
  std::vector<Vec3> knot_points(knots.size());
  std::vector<double> steps(knots.size() - 1);
  for (size_t j = 0; j < knots.size(); ++j) knot_points[j] = p_[knots[j]];
  for (size_t j = 0; j + 1 < knots.size(); ++j) steps[j] = t_[knots[j + 1]] - t_[knots[j]];
  using Kind = TangentCondition::Kind;
  return cubic_spline_tangents(knot_points, steps, TangentCondition{Kind::Clamped, begin},
                               TangentCondition{Kind::Clamped, end});
}

double PieceFit::check_span(size_t k0, size_t k1, const Vec3& m0, const Vec3& m1, bool& ok) const {
  const double h = t_[k1] - t_[k0];
  double worst = 0.0;
  ok = true;
  auto test = [&](const Vec3& deviation) {
    worst = std::max(worst, deviation.norm());
    if (!inside(deviation)) ok = false;
  };
  for (size_t i = k0; i < k1; ++i) {
    if (i > k0) test(hermite_at(p_[k0], p_[k1], m0, m1, h, t_[i] - t_[k0]) - p_[i]);
    for (double f : kSampleShares) {
      const double u = t_[i] + f * (t_[i + 1] - t_[i]) - t_[k0];
      test(hermite_at(p_[k0], p_[k1], m0, m1, h, u) - (p_[i] + f * (p_[i + 1] - p_[i])));
    }
  }
  return worst;
}

void PieceFit::run(std::vector<FittedSpan>& out) {
  std::vector<size_t> knots = initial_knots();
  std::vector<double> deviation;
  for (;;) {
    const std::vector<Vec3> tangents = knot_tangents(knots);
    std::vector<size_t> refined, given_up;
    deviation.assign(knots.size() - 1, 0.0);
    for (size_t j = 0; j + 1 < knots.size(); ++j) {
      refined.push_back(knots[j]);
      bool ok = true;
      deviation[j] = check_span(knots[j], knots[j + 1], tangents[j], tangents[j + 1], ok);
      if (ok) continue;
      if (knots[j + 1] - knots[j] == 1)
        given_up.push_back(knots[j]);
      else
        refined.push_back((knots[j] + knots[j + 1]) / 2);
    }
    refined.push_back(knots.back());
    if (!given_up.empty()) {
      split_around(given_up, out);
      return;
    }
    if (refined.size() == knots.size()) {
      for (size_t j = 0; j + 1 < knots.size(); ++j) {
        const size_t k0 = knots[j], k1 = knots[j + 1];
        FittedSpan span;
        span.first = a_ + k0;
        span.last = a_ + k1;
        span.curve = std::make_shared<PolynomialSpan>(
            PolynomialSpan::hermite(p_[k0], p_[k1], tangents[j], tangents[j + 1], t_[k1] - t_[k0]));
        span.deviation_mm = deviation[j];
        span.end_tangent = tangents[j + 1].normalized();
        out.push_back(std::move(span));
      }
      return;
    }
    knots = std::move(refined);
  }
}

void PieceFit::split_around(const std::vector<size_t>& given_up, std::vector<FittedSpan>& out) const {
  std::span<const Vec3> all(p_.data() - a_, a_ + p_.size());
  size_t from = 0;
  for (size_t g : given_up) {
    if (g > from) fit_range(all, a_ + from, a_ + g, options_, from == 0 ? start_tangent_ : std::nullopt, out);
    fit_range(all, a_ + g, a_ + g + 1, options_, std::nullopt, out);
    from = g + 1;
  }
  if (from < segments()) fit_range(all, a_ + from, a_ + segments(), options_, std::nullopt, out);
}

// Whether the polyline turns at `at` (between directions d0 and d1) by more than the corner angle.
bool is_corner(const Vec3& d0, const Vec3& d1, double corner_angle_deg) {
  const double c = std::clamp(d0.dot(d1) / (d0.norm() * d1.norm()), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi > corner_angle_deg + 1e-9;
}

}  // namespace

std::vector<FittedSpan> fit_compressed_run(std::span<const Vec3> points, const CompressorFitOptions& options,
                                           std::optional<Vec3> start_tangent) {
  std::vector<FittedSpan> out;
  const size_t n = points.size() - 1;
  if (start_tangent && is_corner(*start_tangent, points[1] - points[0], options.corner_angle_deg))
    start_tangent.reset();
  size_t from = 0;
  for (size_t i = 1; i <= n; ++i) {
    if (i < n && !is_corner(points[i] - points[i - 1], points[i + 1] - points[i], options.corner_angle_deg)) continue;
    fit_range(points, from, i, options, from == 0 ? start_tangent : std::nullopt, out);
    from = i;
  }
  return out;
}

}  // namespace drycut::geometry
