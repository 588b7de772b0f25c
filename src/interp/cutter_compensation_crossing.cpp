#include "interp/cutter_compensation_crossing.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::interp {
namespace {

using Point2 = Eigen::Vector2d;

// Parameters of a shared joint closer than this (mm of base arc length) are the joint itself.
constexpr double kJointTolerance = 1e-6;
constexpr double kSegmentSlack = 1e-9;
// A crossing this close to the shared joint of consecutive pieces is the joint itself: at a cusp
// of a looping offset the point hardly moves with the parameter, so the parameter test misses it.
constexpr double kJointPositionTolerance = 1e-5;  // mm

double cross2(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Proper crossing of segments p0-p1 and q0-q1: their parameters t, s in [0, 1].
std::optional<std::pair<double, double>> segment_crossing(const Point2& p0, const Point2& p1, const Point2& q0,
                                                          const Point2& q1) {
  const Point2 r = p1 - p0, e = q1 - q0;
  const double denom = cross2(r, e);
  // Parallel (or degenerate) segments: overlapping collinear offsets are tangential joints.
  if (std::abs(denom) <= 1e-14 * r.norm() * e.norm() || denom == 0.0) return std::nullopt;
  const Point2 w = q0 - p0;
  const double t = cross2(w, e) / denom, s = cross2(w, r) / denom;
  if (t < -kSegmentSlack || t > 1.0 + kSegmentSlack || s < -kSegmentSlack || s > 1.0 + kSegmentSlack)
    return std::nullopt;
  return std::make_pair(std::clamp(t, 0.0, 1.0), std::clamp(s, 0.0, 1.0));
}

bool boxes_apart(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1) {
  constexpr double slack = 1e-9;
  return std::max(p0.x(), p1.x()) + slack < std::min(q0.x(), q1.x()) ||
         std::max(q0.x(), q1.x()) + slack < std::min(p0.x(), p1.x()) ||
         std::max(p0.y(), p1.y()) + slack < std::min(q0.y(), q1.y()) ||
         std::max(q0.y(), q1.y()) + slack < std::min(p0.y(), p1.y());
}

// Newton on Pa(ua) = Pb(ub) in the plane, from the polyline estimate; keeps the estimate when
// the iteration does not settle (tangential crossing).
PieceCrossing refine(const OffsetPiece& a, const OffsetPiece& b, PieceCrossing guess, const CompensationPlane& plane) {
  PieceCrossing c = guess;
  for (int it = 0; it < 30; ++it) {
    const geometry::OffsetDerivatives da = a.derivatives(c.u_earlier), db = b.derivatives(c.u_later);
    const Point2 f = plane.project(da.position) - plane.project(db.position);
    if (f.norm() < 1e-12) return c;
    Eigen::Matrix2d jac;
    jac.col(0) = plane.project(da.first);
    jac.col(1) = -plane.project(db.first);
    const double det = jac.determinant();
    if (std::abs(det) < 1e-14) break;
    const Point2 step = jac.inverse() * f;
    c.u_earlier = std::clamp(c.u_earlier - step.x(), a.u_begin(), a.u_end());
    c.u_later = std::clamp(c.u_later - step.y(), b.u_begin(), b.u_end());
  }
  const Point2 miss = plane.project(a.position(c.u_earlier)) - plane.project(b.position(c.u_later));
  return miss.norm() < 1e-7 ? c : guess;
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// Bounding boxes of two polylines apart: no crossing at all (saves the pairwise segment test
// while a fold holds a long window).
bool polylines_apart(const std::vector<Point2>& a, const std::vector<Point2>& b) {
  constexpr double slack = 1e-9;
  Point2 a_min = a.front(), a_max = a.front(), b_min = b.front(), b_max = b.front();
  for (const Point2& p : a) a_min = a_min.cwiseMin(p), a_max = a_max.cwiseMax(p);
  for (const Point2& p : b) b_min = b_min.cwiseMin(p), b_max = b_max.cwiseMax(p);
  return a_max.x() + slack < b_min.x() || b_max.x() + slack < a_min.x() || a_max.y() + slack < b_min.y() ||
         b_max.y() + slack < a_min.y();
}

bool before(const PieceCrossing& x, const std::optional<PieceCrossing>& best) {  // for self crossings
  return !best || x.u_earlier < best->u_earlier ||
         (x.u_earlier == best->u_earlier && x.u_later > best->u_later);
}

}  // namespace

std::vector<PieceCrossing> find_crossings(const OffsetPiece& earlier, const OffsetPiece& later, bool consecutive,
                                          const CompensationPlane& plane) {
  const auto& pu = earlier.sample_parameters();
  const auto& pxy = earlier.sample_points();
  const auto& qu = later.sample_parameters();
  const auto& qxy = later.sample_points();
  std::vector<PieceCrossing> all;
  if (pxy.empty() || qxy.empty() || polylines_apart(pxy, qxy)) return all;
  const Point2 joint = plane.project(earlier.end());
  for (size_t i = 0; i + 1 < pxy.size(); ++i) {
    for (size_t j = 0; j + 1 < qxy.size(); ++j) {
      if (boxes_apart(pxy[i], pxy[i + 1], qxy[j], qxy[j + 1])) continue;
      const auto ts = segment_crossing(pxy[i], pxy[i + 1], qxy[j], qxy[j + 1]);
      if (!ts) continue;
      PieceCrossing c{lerp(pu[i], pu[i + 1], ts->first), lerp(qu[j], qu[j + 1], ts->second)};
      c = refine(earlier, later, c, plane);
      if (consecutive && ((earlier.u_end() - c.u_earlier < kJointTolerance &&
                           c.u_later - later.u_begin() < kJointTolerance) ||
                          (plane.project(earlier.position(c.u_earlier)) - joint).norm() < kJointPositionTolerance))
        continue;
      all.push_back(c);
    }
  }
  std::sort(all.begin(), all.end(), [](const PieceCrossing& x, const PieceCrossing& y) {
    return x.u_earlier < y.u_earlier || (x.u_earlier == y.u_earlier && x.u_later > y.u_later);
  });
  return all;
}

std::optional<PieceCrossing> find_self_crossing(const OffsetPiece& piece, const CompensationPlane& plane) {
  const auto& u = piece.sample_parameters();
  const auto& xy = piece.sample_points();
  std::optional<PieceCrossing> best;
  for (size_t i = 0; i + 1 < xy.size(); ++i) {
    for (size_t j = i + 2; j + 1 < xy.size(); ++j) {
      if (boxes_apart(xy[i], xy[i + 1], xy[j], xy[j + 1])) continue;
      const auto ts = segment_crossing(xy[i], xy[i + 1], xy[j], xy[j + 1]);
      if (!ts) continue;
      const PieceCrossing guess{lerp(u[i], u[i + 1], ts->first), lerp(u[j], u[j + 1], ts->second)};
      PieceCrossing c = refine(piece, piece, guess, plane);
      if (c.u_later - c.u_earlier < kJointTolerance) c = guess;  // Newton fell onto one point
      if (c.u_later - c.u_earlier < kJointTolerance) continue;
      if (before(c, best)) best = c;
    }
    if (best) break;
  }
  return best;
}

}  // namespace drycut::interp
