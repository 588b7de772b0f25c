#pragma once
// The exact offset of a curve in a working plane (tool radius compensation):
//   Q(u) = P(u) + d * N(u),   N(u) = normalize(n x T_plane(u))
// where P is the base curve at its arc length u, T_plane the tangent's component in the plane
// with unit normal n, and d the signed offset. Looking from +n onto the plane, n x T points to the
// LEFT of the direction of travel, so G41 (tool left of the contour) is d = +r and G42 is d = -r.
// Motion along n (helices, 3-D splines) is carried over unchanged: only the in-plane part is
// offset. The offset is evaluated by its OWN arc length like every Curve; where the base curve
// bends tighter than |d| on the offset side the offset runs backwards (a loop): OffsetCurve keeps
// that loop, cutting it out is the compensation stage's job.
// A normal ramp adds  n * (c0 + (c1 - c0) (u - u_begin) / (u_end - u_begin))  to Q: the
// compensation stage shifts the motion along n of a shortened or joined stretch linearly in the
// base parameter (its first derivative gains n (c1 - c0) / (u_end - u_begin), the others stay).
#include "interp/geometry/arc_length_table.hpp"
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// Q and its first two derivatives with respect to the BASE arc length u.
struct OffsetDerivatives {
  Vec3 position = Vec3::Zero();
  Vec3 first = Vec3::Zero();   // dQ/du
  Vec3 second = Vec3::Zero();  // d2Q/du2
};

// Unit vector n x T_plane (left of travel); zero when the tangent is parallel to n.
Vec3 left_normal(const Vec3& tangent, const Vec3& plane_normal);

// Offset derivatives from the base point's differential geometry (needs tangent, curvature
// vector and curvature rate of the base). Where the tangent is parallel to n the offset
// direction is undefined and the base point is returned unchanged.
OffsetDerivatives offset_derivatives(const CurvePoint& base, double offset_mm, const Vec3& plane_normal);

// Shift along the plane normal at the two ends of the stretch, linear in between (mm).
struct NormalRamp {
  double at_begin = 0.0;
  double at_end = 0.0;
};

class OffsetCurve final : public Curve {
 public:
  // The offset of the whole base curve.
  OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal);
  // The offset of the stretch [u_begin, u_end] of the base (base arc lengths, clamped).
  OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal, double u_begin, double u_end);
  // The same with its motion along the normal shifted by `ramp`.
  OffsetCurve(CurvePtr base, double offset_mm, Vec3 plane_normal, double u_begin, double u_end, NormalRamp ramp);

  double length() const override { return table_.length(); }
  CurvePoint at(double s) const override;
  double max_curvature() const override { return max_curvature_; }

  // Base arc length of the offset point at offset arc length s.
  double base_parameter(double s) const;
  const Curve& base() const { return *base_; }
  double offset() const { return offset_; }

 private:
  // offset_derivatives of the base point at u plus the normal ramp.
  OffsetDerivatives derivatives(const CurvePoint& base_point, double u) const;
  double speed(double u) const;
  Vec3 curvature_vector_at(double u) const;

  CurvePtr base_;
  double offset_;
  Vec3 normal_;
  double u_begin_;
  double u_end_;
  NormalRamp ramp_;
  ArcLengthTable table_;
  double max_curvature_ = 0.0;
};

}  // namespace drycut::geometry
