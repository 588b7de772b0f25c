#include "interp/geometry/projected_length.hpp"

#include <array>

#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {

double projected_length(const Curve& curve, unsigned axes) {
  if ((axes & 7u) == 7u) return curve.length();
  const Vec3 mask((axes & 1u) ? 1.0 : 0.0, (axes & 2u) ? 1.0 : 0.0, (axes & 4u) ? 1.0 : 0.0);
  if (dynamic_cast<const LineCurve*>(&curve)) return (curve.end() - curve.start()).cwiseProduct(mask).norm();
  // 5-node Gauss-Legendre on [-1, 1].
  static constexpr std::array<double, 5> kNode{0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                               0.9061798459386640};
  static constexpr std::array<double, 5> kWeight{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                 0.2369268850561891, 0.2369268850561891};
  constexpr int kPieces = 16;
  const double length = curve.length();
  const double half = length / kPieces / 2.0;
  double sum = 0.0;
  for (int p = 0; p < kPieces; ++p) {
    const double mid = (2 * p + 1) * half;
    for (size_t k = 0; k < kNode.size(); ++k)
      sum += kWeight[k] * curve.at(mid + kNode[k] * half).tangent.cwiseProduct(mask).norm();
  }
  return sum * half;
}

}  // namespace drycut::geometry
