#include "interp/cutting_speed_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <typeinfo>

#include "interp/constant_cutting_speed.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {
namespace {

constexpr double kStep = 1.05;
constexpr int kMaxPieces = 32;
constexpr int kArcSamples = 16;  // intervals the arc's speed range is sampled over

double rpm(const CuttingSpeedLaw& law, double x0, double x1) {
  return constant_cutting_speed_rpm(law.speed_mm_min, x0, x1, law.min_rpm, law.max_rpm);
}

int piece_count(double n_min, double n_max) {
  return std::clamp(static_cast<int>(std::ceil(std::log(n_max / n_min) / std::log(kStep))), 2, kMaxPieces);
}

}  // namespace

// Piece k (1..pieces) of the element at the feed of its own harmonic-mean speed: every piece but
// the last continues the block (one block in the report, no block change, no exact stop).
PathElement block_piece(const PathElement& e, geometry::CurvePtr curve, double feed, int k, int pieces) {
  PathElement piece = e;
  piece.curve = std::move(curve);
  piece.feed_mm_s = feed;
  piece.block_length_mm = e.block_length_mm > 0 ? e.block_length_mm : e.curve->length();  // the block's
  if (k < pieces) {
    piece.continues_block = true;
    piece.dynamics.exact_stop_this_block = false;
    if (piece.dynamics.transition == TransitionMode::ExactStop) piece.dynamics.transition = TransitionMode::Continuous;
  }
  return piece;
}

bool CuttingSpeedPieces::cut_line(const PathElement& e, const CuttingSpeedLaw& law) {
  const geometry::Vec3 a = e.curve->start(), b = e.curve->end();
  const double xa = law.x_at(a), xb = law.x_at(b);
  const double n0 = rpm(law, xa, xa), n1 = rpm(law, xb, xb), mean = rpm(law, xa, xb);
  if (!(n0 > 0 && n1 > 0 && mean > 0) || std::max(n0, n1) / std::min(n0, n1) <= kStep) return false;
  const int pieces = piece_count(std::min(n0, n1), std::max(n0, n1));
  geometry::Vec3 from = a;
  for (int k = 1; k <= pieces; ++k) {
    const double f0 = static_cast<double>(k - 1) / pieces, f1 = static_cast<double>(k) / pieces;
    const geometry::Vec3 to = k == pieces ? b : geometry::Vec3(a + (b - a) * f1);
    const double feed = e.feed_mm_s * rpm(law, xa + (xb - xa) * f0, xa + (xb - xa) * f1) / mean;
    next_.consume(block_piece(e, std::make_shared<geometry::LineCurve>(from, to), feed, k, pieces));
    from = to;
  }
  return true;
}

bool CuttingSpeedPieces::cut_arc(const PathElement& e, const CuttingSpeedLaw& law) {
  const auto& arc = static_cast<const geometry::ArcCurve&>(*e.curve);
  if (arc.axial_travel() != 0.0 || arc.sweep() == 0.0) return false;  // a helix keeps its one feed
  // x(φ) = x_c + r·(a·cos φ + b·sin φ), a and b the law's gradient along the arc's axes.
  const double xc = law.x_at(arc.centre()), a = law.along.dot(arc.first_axis()), b = law.along.dot(arc.second_axis());
  const double r = arc.radius(), phi0 = arc.start_angle(), sweep = arc.sweep();
  const auto x_at_share = [&](double f) {
    const double phi = phi0 + sweep * f;
    return xc + r * (a * std::cos(phi) + b * std::sin(phi));
  };
  // Mean x over the angles f0..f1 (exact: ∫ x dφ / Δφ), for the speed of a sub-arc.
  const auto mean_x = [&](double f0, double f1) {
    const double p0 = phi0 + sweep * f0, p1 = phi0 + sweep * f1;
    return xc + r * (a * (std::sin(p1) - std::sin(p0)) - b * (std::cos(p1) - std::cos(p0))) / (p1 - p0);
  };
  const double xa = x_at_share(0.0), xb = x_at_share(1.0), mean = rpm(law, xa, xb);
  double n_min = 0, n_max = 0;
  for (int i = 0; i <= kArcSamples; ++i) {
    const double x = x_at_share(static_cast<double>(i) / kArcSamples), n = rpm(law, x, x);
    n_min = i == 0 ? n : std::min(n_min, n);
    n_max = i == 0 ? n : std::max(n_max, n);
  }
  if (!(n_min > 0 && mean > 0) || n_max / n_min <= kStep) return false;
  const int pieces = piece_count(n_min, n_max);
  for (int k = 1; k <= pieces; ++k) {
    const double f0 = static_cast<double>(k - 1) / pieces, f1 = static_cast<double>(k) / pieces;
    auto sub = std::make_shared<geometry::ArcCurve>(arc.centre(), arc.radius(), arc.first_axis(), arc.second_axis(),
                                                    arc.start_angle() + arc.sweep() * f0, arc.sweep() * (f1 - f0), 0.0);
    // The sub-arc's ends as a straight course moved to the arc's mean x over it: its harmonic-mean
    // speed is then exact where no limit binds (the chord's ends alone were off by Δφ²/12).
    const double x0 = x_at_share(f0), x1 = x_at_share(f1), shift = mean_x(f0, f1) - 0.5 * (x0 + x1);
    const double feed = e.feed_mm_s * rpm(law, x0 + shift, x1 + shift) / mean;
    next_.consume(block_piece(e, std::move(sub), feed, k, pieces));
  }
  return true;
}

void CuttingSpeedPieces::consume(PathElement&& e) {
  const CuttingSpeedLaw* law = e.cutting_speed.get();
  bool cut = false;
  if (law && !e.rapid && e.curve && e.feed_mm_s > 0) {
    // A line (or one the contour stages trimmed: its curvature is 0), or a circular arc.
    if (e.kind == ElementKind::Line && e.curve->max_curvature() == 0.0) cut = cut_line(e, *law);
    else if (e.kind == ElementKind::Arc && typeid(*e.curve) == typeid(geometry::ArcCurve)) cut = cut_arc(e, *law);
  }
  if (!cut) next_.consume(std::move(e));
}

}  // namespace drycut::interp
