#include "interp/cutting_speed_pieces.hpp"

#include <algorithm>
#include <cmath>

#include "interp/constant_cutting_speed.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

void CuttingSpeedPieces::consume(PathElement&& e) {
  constexpr double kStep = 1.05;
  constexpr int kMaxPieces = 32;
  const CuttingSpeedLaw* law = e.cutting_speed.get();
  // Straight elements only (a line, or one the contour stages trimmed: its curvature is 0).
  if (!law || e.rapid || !e.curve || !(e.feed_mm_s > 0) || e.kind != ElementKind::Line ||
      e.curve->max_curvature() != 0.0) {
    next_.consume(std::move(e));
    return;
  }
  const geometry::Vec3 a = e.curve->start(), b = e.curve->end();
  const double xa = law->x_at(a), xb = law->x_at(b);
  const auto rpm = [&](double x0, double x1) {
    return constant_cutting_speed_rpm(law->speed_mm_min, x0, x1, law->min_rpm, law->max_rpm);
  };
  const double n0 = rpm(xa, xa), n1 = rpm(xb, xb), mean = rpm(xa, xb);
  if (!(n0 > 0 && n1 > 0 && mean > 0) || std::max(n0, n1) / std::min(n0, n1) <= kStep) {
    next_.consume(std::move(e));
    return;
  }
  const int pieces = std::clamp(
      static_cast<int>(std::ceil(std::log(std::max(n0, n1) / std::min(n0, n1)) / std::log(kStep))), 2, kMaxPieces);
  const double block_length = e.block_length_mm > 0 ? e.block_length_mm : e.curve->length();
  geometry::Vec3 from = a;
  for (int k = 1; k <= pieces; ++k) {
    const double f0 = static_cast<double>(k - 1) / pieces, f1 = static_cast<double>(k) / pieces;
    const geometry::Vec3 to = k == pieces ? b : geometry::Vec3(a + (b - a) * f1);
    PathElement piece = e;
    piece.curve = std::make_shared<geometry::LineCurve>(from, to);
    piece.feed_mm_s = e.feed_mm_s * rpm(xa + (xb - xa) * f0, xa + (xb - xa) * f1) / mean;
    piece.block_length_mm = block_length;  // the block change is the block's (short-block rule)
    if (k < pieces) {
      piece.continues_block = true;
      piece.dynamics.exact_stop_this_block = false;
      if (piece.dynamics.transition == TransitionMode::ExactStop) piece.dynamics.transition = TransitionMode::Continuous;
    }
    from = to;
    next_.consume(std::move(piece));
  }
}

}  // namespace drycut::interp
