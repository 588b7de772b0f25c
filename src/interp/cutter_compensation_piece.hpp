#pragma once
// One stretch of the tool-centre path while tool radius compensation is active: the offset of a
// programmed curve (or a corner curve inserted by the compensation, offset 0) restricted to the
// base arc lengths [u_begin, u_end]. Pieces stay editable (trimmed at intersections) until the
// compensation window releases them; only then are they turned into a Curve.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "interp/geometry/curve.hpp"
#include "interp/geometry/offset_curve.hpp"

namespace drycut::interp {

// The compensation plane: its normal and two in-plane axes for 2-D geometry.
struct CompensationPlane {
  geometry::Vec3 normal = geometry::Vec3::UnitZ();
  geometry::Vec3 first = geometry::Vec3::UnitX();
  geometry::Vec3 second = geometry::Vec3::UnitY();

  // plane_normal_axis: 2 = G17, 1 = G18, 0 = G19.
  static CompensationPlane from_normal_axis(int plane_normal_axis);
  Eigen::Vector2d project(const geometry::Vec3& p) const { return {p.dot(first), p.dot(second)}; }
};

class OffsetPiece {
 public:
  OffsetPiece(geometry::CurvePtr base, double offset_mm, const CompensationPlane& plane);

  geometry::Vec3 position(double u) const { return derivatives(u).position; }
  geometry::OffsetDerivatives derivatives(double u) const;
  geometry::Vec3 start() const { return position(u_begin_); }
  geometry::Vec3 end() const { return position(u_end_); }

  double u_begin() const { return u_begin_; }
  double u_end() const { return u_end_; }
  void trim(double u_begin, double u_end);

  // In-plane polyline of the current stretch (for intersection search), with base parameters.
  const std::vector<double>& sample_parameters() const { return sample_u_; }
  const std::vector<Eigen::Vector2d>& sample_points() const { return sample_xy_; }

  // True where the offset runs against the programmed direction somewhere in the stretch (an
  // arc or bend tighter than the tool radius that bottleneck detection did not cut out).
  // Cached until the next trim (the window asks it of every piece after every block).
  bool runs_backwards() const {
    if (!backwards_) backwards_ = runs_backwards(u_begin_, u_end_);
    return *backwards_;
  }
  // The same within the base parameters [u0, u1] of the stretch.
  bool runs_backwards(double u0, double u1) const;

  // The tool-centre curve of the stretch: an exact LineCurve or ArcCurve where the base is a line
  // or an arc in the compensation plane, an OffsetCurve otherwise. `shift` moves it along the
  // plane normal: by shift.at_begin at its start and shift.at_end at its end, linearly in the base
  // parameter in between (a line stays a line, a helix about the normal a helix).
  geometry::CurvePtr build_curve(geometry::NormalRamp shift = {}) const;

  // Length of the stretch in the plane (its polyline: exact for lines, 2e-5 relative for curves).
  double in_plane_length() const;
  // Coordinate of the start and end along the plane normal.
  double normal_start() const { return plane_.normal.dot(start()); }
  double normal_end() const { return plane_.normal.dot(end()); }
  // The stretch still ends where its base ends (not shortened there by an intersection).
  bool reaches_base_end() const { return u_end_ >= base_->length() - 1e-9; }

  const geometry::Curve& base() const { return *base_; }
  double offset() const { return offset_; }

 private:
  void resample();

  geometry::CurvePtr base_;
  double offset_;
  CompensationPlane plane_;
  double u_begin_ = 0.0;
  double u_end_ = 0.0;
  bool straight_ = false;  // base curvature zero: the offset is straight too
  mutable std::optional<bool> backwards_;  // runs_backwards() of the current stretch
  std::vector<double> sample_u_;
  std::vector<Eigen::Vector2d> sample_xy_;
};

}  // namespace drycut::interp
