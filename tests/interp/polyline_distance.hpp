#pragma once
// Exact distance from a point to a long dense polyline (a reference for tests that check
// a tool-centre path against densely sampled programmed paths), in time independent of the
// polyline's length for most queries: the polyline is cut into chunks of kChunk segments, each
// with a bounding circle (centre = mean of its points, radius = farthest point); a chunk whose
// circle lies farther from the query than the best distance found so far cannot hold a nearer
// segment, so the chunks are visited nearest circle first and the search stops at the first
// chunk beyond the best. Plain doubles: the sanitized suite builds tests at -O0, where the
// former scans over every segment with Eigen took minutes per test.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace drycut::test {

class PolylineDistance {
 public:
  // An in-plane polyline (z = 0; query with z = 0).
  explicit PolylineDistance(const std::vector<Eigen::Vector2d>& points) {
    for (const auto& p : points) add(p.x(), p.y(), 0.0);
    index();
  }
  explicit PolylineDistance(const std::vector<Eigen::Vector3d>& points) {
    for (const auto& p : points) add(p.x(), p.y(), p.z());
    index();
  }

  double distance(double px, double py, double pz = 0.0) const {
    std::vector<std::pair<double, size_t>> order;  // lower bound of the chunk's distance, chunk
    order.reserve(chunks_.size());
    for (size_t k = 0; k < chunks_.size(); ++k) {
      const Chunk& c = chunks_[k];
      const double dx = px - c.cx, dy = py - c.cy, dz = pz - c.cz;
      order.emplace_back(std::max(0.0, std::sqrt(dx * dx + dy * dy + dz * dz) - c.radius), k);
    }
    std::sort(order.begin(), order.end());
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [bound, k] : order) {
      if (bound > best) break;
      for (size_t j = chunks_[k].first; j < chunks_[k].last; ++j) best = std::min(best, segment(px, py, pz, j));
    }
    return best;
  }

 private:
  static constexpr size_t kChunk = 64;
  struct Chunk {
    size_t first, last;
    double cx, cy, cz, radius;
  };

  void add(double x, double y, double z) {
    x_.push_back(x);
    y_.push_back(y);
    z_.push_back(z);
  }

  void index() {
    for (size_t first = 0; first + 1 < x_.size(); first += kChunk) {
      const size_t last = std::min(first + kChunk, x_.size() - 1);  // segments first .. last-1
      Chunk c{first, last, 0, 0, 0, 0};
      const auto n = static_cast<double>(last - first + 1);
      for (size_t i = first; i <= last; ++i) {
        c.cx += x_[i] / n;
        c.cy += y_[i] / n;
        c.cz += z_[i] / n;
      }
      for (size_t i = first; i <= last; ++i) {
        const double dx = x_[i] - c.cx, dy = y_[i] - c.cy, dz = z_[i] - c.cz;
        c.radius = std::max(c.radius, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
      chunks_.push_back(c);
    }
  }

  double segment(double px, double py, double pz, size_t j) const {
    const double ax = x_[j], ay = y_[j], az = z_[j];
    const double bx = x_[j + 1] - ax, by = y_[j + 1] - ay, bz = z_[j + 1] - az;
    const double len2 = bx * bx + by * by + bz * bz;
    const double t =
        len2 > 1e-300 ? std::clamp(((px - ax) * bx + (py - ay) * by + (pz - az) * bz) / len2, 0.0, 1.0) : 0.0;
    const double dx = ax + t * bx - px, dy = ay + t * by - py, dz = az + t * bz - pz;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }

  std::vector<double> x_, y_, z_;
  std::vector<Chunk> chunks_;
};

}  // namespace drycut::test
