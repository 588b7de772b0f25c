#pragma once
// Nearest-point queries against polylines in the XY plane: the segments are bucketed in a
// uniform grid, and a query searches rings of cells outwards until no unexamined cell can hold
// anything nearer. Used for the reference curve (dense polyline) and for tool-centre paths.
// Crossing queries (where a query segment meets the polylines) examine only the cells under the
// query segment's bounding box; a segment listed in several of them is tested once.
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace drycut::workload {

using Vec2 = Eigen::Vector2d;

struct NearestHit {
  double distance = std::numeric_limits<double>::infinity();
  size_t segment = 0;     // index in insertion order (polyline after polyline)
  double fraction = 0.0;  // position on the segment, 0 = its first point
  Vec2 point = Vec2::Zero();
  bool found() const { return distance < std::numeric_limits<double>::infinity(); }
};

class PolylineIndex {
 public:
  // Adds the segments between consecutive points (and last -> first when closed).
  void add_polyline(const std::vector<Vec2>& points, bool closed);
  // Builds the grid; call after the last add_polyline and before nearest().
  void build();
  // Nothing found (distance infinite) when the index holds no segment.
  NearestHit nearest(const Vec2& query) const;
  // Where the segment a-b meets the indexed segments: the fraction along a-b (0 = a) of each
  // crossing, ascending. Parallel (also collinear) segments do not count; a crossing at a shared
  // vertex may appear twice. Empty when the index holds no segment.
  std::vector<double> crossings(const Vec2& a, const Vec2& b) const;
  size_t segment_count() const { return from_.size(); }

 private:
  size_t cell_of(long ix, long iy) const { return static_cast<size_t>(iy) * nx_ + static_cast<size_t>(ix); }
  void examine_cell(long ix, long iy, const Vec2& q, NearestHit& best) const;

  std::vector<Vec2> from_, to_;
  Vec2 origin_ = Vec2::Zero();
  double cell_ = 1.0;
  size_t nx_ = 0, ny_ = 0;
  std::vector<size_t> cell_start_;   // CSR: segments of cell c are items_[cell_start_[c] .. cell_start_[c+1])
  std::vector<size_t> items_;
};

}  // namespace drycut::workload
