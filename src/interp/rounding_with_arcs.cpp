#include "interp/rounding_with_arcs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;

constexpr double kEps = 1e-9;

// A side of the corner as a locus: a line (point, direction) or a circle (centre, radius).
struct Side {
  const geometry::ArcCurve* arc = nullptr;  // null: a line
  Vec3 point, direction;                    // the line
  Vec3 inner;                               // unit normal towards the rounding at the corner
  double offset_radius = 0;                 // circle: R + σ·r
};

// Intersections of the offset loci of two sides (in the plane with normal n).
std::vector<Vec3> meet(const Side& a, const Side& b, double r, const Vec3& n) {
  std::vector<Vec3> out;
  const auto line_of = [&](const Side& s, Vec3& p, Vec3& d) {
    p = s.point + r * s.inner;
    d = s.direction;
  };
  if (!a.arc && !b.arc) {
    Vec3 p, d, q, e;
    line_of(a, p, d);
    line_of(b, q, e);
    const double den = d.cross(e).dot(n);
    if (std::abs(den) < kEps) return out;
    out.push_back(p + d * ((q - p).cross(e).dot(n) / den));
    return out;
  }
  if (!a.arc || !b.arc) {  // a line and a circle
    const Side& line = a.arc ? b : a;
    const Side& circle = a.arc ? a : b;
    Vec3 p, d;
    line_of(line, p, d);
    const Vec3 o = circle.arc->centre();
    const Vec3 f = p - o;
    const double bq = f.dot(d), cq = f.squaredNorm() - circle.offset_radius * circle.offset_radius;
    const double disc = bq * bq - cq;
    if (disc < 0) return out;
    for (const double sign : {-1.0, 1.0}) out.push_back(p + d * (-bq + sign * std::sqrt(disc)));
    return out;
  }
  // Two circles in the plane.
  const Vec3 o1 = a.arc->centre(), o2 = b.arc->centre();
  const double r1 = a.offset_radius, r2 = b.offset_radius;
  const Vec3 d = o2 - o1;
  const double dist = d.norm();
  if (dist < kEps) return out;
  const double x = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
  const double h2 = r1 * r1 - x * x;
  if (h2 < 0) return out;
  const Vec3 ex = d / dist, ey = n.cross(ex);
  for (const double sign : {-1.0, 1.0}) out.push_back(o1 + x * ex + sign * std::sqrt(h2) * ey);
  return out;
}

// The tangent point: the foot of M on the side.
Vec3 foot(const Side& s, const Vec3& m) {
  if (!s.arc) return s.point + s.direction * (m - s.point).dot(s.direction);
  const Vec3 o = s.arc->centre();
  return o + s.arc->radius() * (m - o).normalized();
}

// The arc length along `curve` of a point on it; -1 when it is not on the piece.
double arc_length_of(const geometry::CurvePtr& curve, const Vec3& p) {
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(curve.get());
  if (!arc) {
    const Vec3 u = (curve->end() - curve->start()).normalized();
    const double s = (p - curve->start()).dot(u);
    return s >= -kEps && s <= curve->length() + kEps ? std::clamp(s, 0.0, curve->length()) : -1.0;
  }
  const Vec3 q = p - arc->centre();
  const double phi = std::atan2(q.dot(arc->second_axis()), q.dot(arc->first_axis()));
  double rel = phi - arc->start_angle();
  const double two_pi = 2 * std::numbers::pi;
  if (arc->sweep() > 0) {
    rel = std::fmod(rel, two_pi);
    if (rel < -1e-12) rel += two_pi;
  } else {
    rel = std::fmod(rel, two_pi);
    if (rel > 1e-12) rel -= two_pi;
  }
  const double s = std::abs(rel) * arc->radius();
  return s <= curve->length() + kEps ? std::min(s, curve->length()) : -1.0;
}

}  // namespace

std::optional<CurvedRounding> rounding_with_arcs(const geometry::CurvePtr& first, const geometry::CurvePtr& second,
                                                 double radius, const Vec3& n) {
  if (!(radius > 0)) return std::nullopt;
  const Vec3 c = first->end();
  const Vec3 t1 = first->at(first->length()).tangent.normalized(), t2 = second->at(0).tangent.normalized();
  const double turn = t1.cross(t2).dot(n);
  const double theta = std::acos(std::clamp(t1.dot(t2), -1.0, 1.0));
  if (!(theta > kEps && theta < std::numbers::pi - kEps)) return std::nullopt;
  const Vec3 w = (turn >= 0 ? 1.0 : -1.0) * n.cross(t1);  // towards the inside of the turn (t1 side)
  const Vec3 w2 = (turn >= 0 ? 1.0 : -1.0) * n.cross(t2);
  const auto side_of = [&](const geometry::CurvePtr& curve, const Vec3& tangent, const Vec3& inner) {
    Side s;
    s.arc = dynamic_cast<const geometry::ArcCurve*>(curve.get());
    s.point = c;
    s.direction = tangent;
    s.inner = inner;
    if (s.arc) {
      const bool towards_centre = (s.arc->centre() - c).dot(inner) > 0;
      s.offset_radius = s.arc->radius() + (towards_centre ? -radius : radius);
      if (s.offset_radius <= kEps) s.offset_radius = -1;  // the rounding cannot lie inside it
    }
    return s;
  };
  const Side a = side_of(first, t1, w), b = side_of(second, t2, w2);
  if ((a.arc && a.offset_radius < 0) || (b.arc && b.offset_radius < 0)) return std::nullopt;
  std::optional<Vec3> m;
  for (const Vec3& candidate : meet(a, b, radius, n))
    if (!m || (candidate - c).norm() < (*m - c).norm()) m = candidate;
  if (!m) return std::nullopt;
  const Vec3 p1 = foot(a, *m), p2 = foot(b, *m);
  const double s1 = arc_length_of(first, p1), s2 = arc_length_of(second, p2);
  if (s1 <= kEps || s2 < 0 || s2 >= second->length() - kEps) return std::nullopt;
  CurvedRounding out;
  out.end_of_first = s1;
  out.start_of_second = s2;
  const Vec3 e1 = (p1 - *m) / radius;
  const Vec3 e2 = first->at(s1).tangent.normalized();
  const Vec3 q = p2 - *m;
  double sweep = std::atan2(q.dot(e2), q.dot(e1));
  if (sweep <= 0) sweep += 2 * std::numbers::pi;
  out.curve = std::make_shared<geometry::ArcCurve>(*m, radius, e1, e2, 0.0, sweep, 0.0);
  return out;
}

}  // namespace drycut::interp
