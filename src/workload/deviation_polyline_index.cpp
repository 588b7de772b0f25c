#include "workload/deviation_polyline_index.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::workload {

void PolylineIndex::add_polyline(const std::vector<Vec2>& points, bool closed) {
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    from_.push_back(points[i]);
    to_.push_back(points[i + 1]);
  }
  if (closed && points.size() > 2) {
    from_.push_back(points.back());
    to_.push_back(points.front());
  }
  // A lone point is a degenerate segment so that it can still be found.
  if (points.size() == 1) {
    from_.push_back(points[0]);
    to_.push_back(points[0]);
  }
}

void PolylineIndex::build() {
  cell_start_.clear();
  items_.clear();
  if (from_.empty()) return;
  Vec2 lo = from_[0], hi = from_[0];
  double total_length = 0.0;
  for (size_t i = 0; i < from_.size(); ++i) {
    lo = lo.cwiseMin(from_[i]).cwiseMin(to_[i]);
    hi = hi.cwiseMax(from_[i]).cwiseMax(to_[i]);
    total_length += (to_[i] - from_[i]).norm();
  }
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-6});
  // About one cell per sqrt(n) of the extent keeps both the grid and the cell lists small;
  // never finer than the mean segment so a segment touches few cells.
  const double mean_segment = total_length / static_cast<double>(from_.size());
  cell_ = std::max({extent / std::sqrt(static_cast<double>(from_.size())), mean_segment, 1e-6});
  origin_ = lo;
  nx_ = static_cast<size_t>((hi.x() - lo.x()) / cell_) + 1;
  ny_ = static_cast<size_t>((hi.y() - lo.y()) / cell_) + 1;

  auto cell_range = [&](size_t i, long& x0, long& x1, long& y0, long& y1) {
    const Vec2 a = (from_[i].cwiseMin(to_[i]) - origin_) / cell_;
    const Vec2 b = (from_[i].cwiseMax(to_[i]) - origin_) / cell_;
    x0 = std::clamp(static_cast<long>(a.x()), 0L, static_cast<long>(nx_) - 1);
    x1 = std::clamp(static_cast<long>(b.x()), 0L, static_cast<long>(nx_) - 1);
    y0 = std::clamp(static_cast<long>(a.y()), 0L, static_cast<long>(ny_) - 1);
    y1 = std::clamp(static_cast<long>(b.y()), 0L, static_cast<long>(ny_) - 1);
  };
  std::vector<size_t> count(nx_ * ny_ + 1, 0);
  long x0, x1, y0, y1;
  for (size_t i = 0; i < from_.size(); ++i) {
    cell_range(i, x0, x1, y0, y1);
    for (long y = y0; y <= y1; ++y)
      for (long x = x0; x <= x1; ++x) ++count[cell_of(x, y) + 1];
  }
  for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  cell_start_ = count;
  items_.resize(count.back());
  std::vector<size_t> fill(count.begin(), count.end() - 1);
  for (size_t i = 0; i < from_.size(); ++i) {
    cell_range(i, x0, x1, y0, y1);
    for (long y = y0; y <= y1; ++y)
      for (long x = x0; x <= x1; ++x) items_[fill[cell_of(x, y)]++] = i;
  }
}

void PolylineIndex::examine_cell(long ix, long iy, const Vec2& q, NearestHit& best) const {
  const size_t c = cell_of(ix, iy);
  for (size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const size_t i = items_[k];
    const Vec2 d = to_[i] - from_[i];
    const double len2 = d.squaredNorm();
    const double f = len2 > 0 ? std::clamp((q - from_[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    const Vec2 p = from_[i] + f * d;
    const double dist = (q - p).norm();
    if (dist < best.distance) best = {dist, i, f, p};
  }
}

NearestHit PolylineIndex::nearest(const Vec2& q) const {
  NearestHit best;
  if (cell_start_.empty()) return best;
  const Vec2 g = (q - origin_) / cell_;
  const long cx = std::clamp(static_cast<long>(std::floor(g.x())), 0L, static_cast<long>(nx_) - 1);
  const long cy = std::clamp(static_cast<long>(std::floor(g.y())), 0L, static_cast<long>(ny_) - 1);
  const long max_ring = static_cast<long>(std::max(nx_, ny_));
  for (long k = 0; k <= max_ring; ++k) {
    for (long y = cy - k; y <= cy + k; ++y) {
      if (y < 0 || y >= static_cast<long>(ny_)) continue;
      const bool edge_row = y == cy - k || y == cy + k;
      for (long x = cx - k; x <= cx + k; x += edge_row ? 1 : 2 * k) {
        if (x >= 0 && x < static_cast<long>(nx_)) examine_cell(x, y, q, best);
        if (k == 0) break;
      }
    }
    // Everything not yet examined lies outside the block of rings 0..k; its distance is at
    // least the distance from q to that block's border (sides at the grid edge hold nothing).
    double bound = std::numeric_limits<double>::infinity();
    const double left = origin_.x() + static_cast<double>(cx - k) * cell_;
    const double right = origin_.x() + static_cast<double>(cx + k + 1) * cell_;
    const double bottom = origin_.y() + static_cast<double>(cy - k) * cell_;
    const double top = origin_.y() + static_cast<double>(cy + k + 1) * cell_;
    if (cx - k > 0) bound = std::min(bound, std::max(0.0, q.x() - left));
    if (cx + k + 1 < static_cast<long>(nx_)) bound = std::min(bound, std::max(0.0, right - q.x()));
    if (cy - k > 0) bound = std::min(bound, std::max(0.0, q.y() - bottom));
    if (cy + k + 1 < static_cast<long>(ny_)) bound = std::min(bound, std::max(0.0, top - q.y()));
    if (best.distance <= bound) break;
  }
  return best;
}

std::vector<double> PolylineIndex::crossings(const Vec2& a, const Vec2& b) const {
  std::vector<double> result;
  if (cell_start_.empty()) return result;
  auto clamped = [](double v, size_t n) { return std::clamp(static_cast<long>(std::floor(v)), 0L, static_cast<long>(n) - 1); };
  const Vec2 lo = (a.cwiseMin(b) - origin_) / cell_, hi = (a.cwiseMax(b) - origin_) / cell_;
  std::vector<size_t> candidates;
  for (long y = clamped(lo.y(), ny_); y <= clamped(hi.y(), ny_); ++y)
    for (long x = clamped(lo.x(), nx_); x <= clamped(hi.x(), nx_); ++x) {
      const size_t c = cell_of(x, y);
      candidates.insert(candidates.end(), items_.begin() + static_cast<long>(cell_start_[c]),
                        items_.begin() + static_cast<long>(cell_start_[c + 1]));
    }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const Vec2 ab = b - a;
  for (size_t i : candidates) {
    // a + t (b - a) = from + s (to - from), solved by Cramer's rule.
    const Vec2 cd = to_[i] - from_[i], ac = from_[i] - a;
    const double denom = cross(ab, cd);
    if (std::abs(denom) <= 1e-12 * ab.norm() * cd.norm()) continue;  // parallel or degenerate
    const double t = cross(ac, cd) / denom, s = cross(ac, ab) / denom;
    constexpr double kEnds = 1e-12;  // a crossing exactly at a vertex belongs to both segments
    if (t >= 0.0 && t <= 1.0 && s >= -kEnds && s <= 1.0 + kEnds) result.push_back(t);
  }
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace drycut::workload
