#include "interp/geometry/offset_curve.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::geometry {
namespace {

// Below this in-plane speed the tangent is treated as parallel to the plane normal.
constexpr double kParallelTolerance = 1e-12;
// Samples for the largest curvature (the offset of a line or arc has constant curvature, so
// sampling is exact there; for splines it matches Curve's "sampled" contract).
constexpr int kCurvatureSamples = 64;

Vec3 in_plane(const Vec3& v, const Vec3& n) { return v - n * n.dot(v); }

}  // namespace

Vec3 left_normal(const Vec3& tangent, const Vec3& plane_normal) {
  const Vec3 v = in_plane(tangent, plane_normal);
  const double w = v.norm();
  if (w < kParallelTolerance) return Vec3::Zero();
  return plane_normal.cross(v / w);
}

OffsetDerivatives offset_derivatives(const CurvePoint& base, double offset_mm, const Vec3& n) {
  OffsetDerivatives d;
  const Vec3 v = in_plane(base.tangent, n);
  const Vec3 v1 = in_plane(base.curvature_vector, n);
  const Vec3 v2 = in_plane(base.curvature_rate, n);
  const double w = v.norm();
  if (w < kParallelTolerance) {
    d.position = base.position;
    d.first = base.tangent;
    d.second = base.curvature_vector;
    return d;
  }
  // Unit in-plane tangent e = v/|v| and its derivatives; the offset direction is n x e.
  const Vec3 e = v / w;
  const double a = e.dot(v1);  // d|v|/du
  const Vec3 e1 = (v1 - e * a) / w;
  const double a1 = e1.dot(v1) + e.dot(v2);
  const Vec3 e2 = (v2 - e1 * a - e * a1) / w - e1 * (a / w);
  d.position = base.position + offset_mm * n.cross(e);
  d.first = base.tangent + offset_mm * n.cross(e1);
  d.second = base.curvature_vector + offset_mm * n.cross(e2);
  return d;
}

OffsetCurve::OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal)
    : OffsetCurve(base, offset_mm, plane_normal, 0.0, base->length()) {}

OffsetCurve::OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal, double u_begin, double u_end)
    : OffsetCurve(std::move(base), offset_mm, plane_normal, u_begin, u_end, NormalRamp{}) {}

OffsetCurve::OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal, double u_begin, double u_end,
                         NormalRamp ramp)
    : base_(std::move(base)), offset_(offset_mm), normal_(plane_normal.normalized()), ramp_(ramp) {
  const double length = base_->length();
  u_begin_ = std::clamp(u_begin, 0.0, length);
  u_end_ = std::clamp(u_end, u_begin_, length);
  table_ = ArcLengthTable([this](double u) { return speed(u); }, u_begin_, u_end_);
  for (int i = 0; i <= kCurvatureSamples; ++i) {
    const double u = u_begin_ + (u_end_ - u_begin_) * i / kCurvatureSamples;
    max_curvature_ = std::max(max_curvature_, curvature_vector_at(u).norm());
  }
}

OffsetDerivatives OffsetCurve::derivatives(const CurvePoint& base_point, double u) const {
  OffsetDerivatives d = offset_derivatives(base_point, offset_, normal_);
  if (ramp_.at_begin == 0.0 && ramp_.at_end == 0.0) return d;
  const double range = u_end_ - u_begin_;
  const double slope = range > 0.0 ? (ramp_.at_end - ramp_.at_begin) / range : 0.0;
  d.position += normal_ * (ramp_.at_begin + slope * (u - u_begin_));
  d.first += normal_ * slope;
  return d;
}

double OffsetCurve::speed(double u) const { return derivatives(base_->at(u), u).first.norm(); }

Vec3 OffsetCurve::curvature_vector_at(double u) const {
  const OffsetDerivatives d = derivatives(base_->at(u), u);
  const double sigma = d.first.norm();
  if (sigma < kParallelTolerance) return Vec3::Zero();  // cusp of a loop: no finite curvature
  const Vec3 t = d.first / sigma;
  return (d.second - t * t.dot(d.second)) / (sigma * sigma);
}

double OffsetCurve::base_parameter(double s) const {
  return table_.parameter_at([this](double u) { return speed(u); }, s);
}

CurvePoint OffsetCurve::at(double s) const {
  const double u = base_parameter(s);
  const CurvePoint b = base_->at(u);
  const OffsetDerivatives d = derivatives(b, u);
  CurvePoint p;
  p.position = d.position;
  const double sigma = d.first.norm();
  if (sigma < kParallelTolerance) {
    // Exactly on a cusp (offset radius zero): direction of the base, no finite curvature.
    p.tangent = b.tangent;
    return p;
  }
  p.tangent = d.first / sigma;
  p.curvature_vector = (d.second - p.tangent * p.tangent.dot(d.second)) / (sigma * sigma);
  p.curvature = p.curvature_vector.norm();
  // The third derivative would need the base's fourth: differentiate the exact curvature vector
  // numerically instead (central where possible, one-sided at the ends of the stretch).
  const double range = u_end_ - u_begin_;
  const double h = std::min(1e-5, 0.25 * range);
  if (h > 0.0) {
    const double lo = std::max(u_begin_, u - h), hi = std::min(u_end_, u + h);
    if (hi > lo) {
      const Vec3 k_lo = curvature_vector_at(lo), k_hi = curvature_vector_at(hi);
      const double ds = (hi - lo) * sigma;
      p.curvature_rate = (k_hi - k_lo) / ds;
      p.curvature_derivative = (k_hi.norm() - k_lo.norm()) / ds;
    }
  }
  return p;
}

}  // namespace drycut::geometry
