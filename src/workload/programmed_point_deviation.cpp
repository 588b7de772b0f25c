#include "workload/programmed_point_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drycut::workload {
namespace {

constexpr size_t kChunk = 32;
constexpr double kInf = std::numeric_limits<double>::infinity();

double segment_distance(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

class StatsSum {
 public:
  void add(double v, const BlockRef& where) {
    ++s_.count;
    if (s_.count == 1 || v > s_.max_mm) s_.max_mm = v, s_.max_at = where;
    sum_ += v;
  }
  DistanceStats result() const {
    DistanceStats r = s_;
    if (r.count) r.mean_mm = sum_ / static_cast<double>(r.count);
    return r;
  }

 private:
  DistanceStats s_;
  double sum_ = 0.0;
};

}  // namespace

PolylineDistance::PolylineDistance(const std::vector<std::vector<Vec3>>& polylines) {
  for (const auto& line : polylines) {
    if (line.size() == 1) from_.push_back(line[0]), to_.push_back(line[0]);
    for (size_t i = 0; i + 1 < line.size(); ++i) from_.push_back(line[i]), to_.push_back(line[i + 1]);
  }
  for (size_t first = 0; first < from_.size(); first += kChunk) {
    Chunk c{from_[first], from_[first], first, std::min(first + kChunk, from_.size())};
    for (size_t i = first; i < c.last; ++i) {
      c.lo = c.lo.cwiseMin(from_[i]).cwiseMin(to_[i]);
      c.hi = c.hi.cwiseMax(from_[i]).cwiseMax(to_[i]);
    }
    chunks_.push_back(c);
  }
}

double PolylineDistance::chunk_distance(const Chunk& c, const Vec3& p) const {
  double best = kInf;
  for (size_t i = c.first; i < c.last; ++i) best = std::min(best, segment_distance(from_[i], to_[i], p));
  return best;
}

double PolylineDistance::distance(const Vec3& p) const {
  if (chunks_.empty()) return kInf;
  double best = chunk_distance(chunks_[hint_], p);
  for (size_t k = 0; k < chunks_.size(); ++k) {
    if (k == hint_) continue;
    const Vec3 outside = (chunks_[k].lo - p).cwiseMax(p - chunks_[k].hi).cwiseMax(Vec3::Zero());
    if (outside.norm() >= best) continue;  // nothing in this box can be nearer
    const double d = chunk_distance(chunks_[k], p);
    if (d < best) best = d, hint_ = k;
  }
  return best;
}

ProgrammedPointDeviation programmed_point_deviation(const std::vector<ProgrammedPoint>& points,
                                                    const std::vector<SampledElement>& elements) {
  // `programmed`: the programmed points of each run, as the polylines' corners; `contour`: the
  // same runs with the points of the programmed arcs between them, what the path is measured to.
  std::vector<std::vector<Vec3>> programmed, contour, path;
  std::vector<std::vector<const BlockRef*>> programmed_source;
  for (const ProgrammedPoint& p : points) {
    if (p.rapid || programmed.empty()) programmed.emplace_back(), programmed_source.emplace_back(), contour.emplace_back();
    if (!p.rapid) contour.back().insert(contour.back().end(), p.via.begin(), p.via.end());
    programmed.back().push_back(p.position);
    contour.back().push_back(p.position);
    programmed_source.back().push_back(&p.source);
  }
  bool in_run = false;
  for (const SampledElement& e : elements) {
    if (e.rapid) {
      in_run = false;
      continue;
    }
    if (!in_run) path.emplace_back();
    in_run = true;
    path.back().insert(path.back().end(), e.points.begin(), e.points.end());
  }
  // A run of one point is a rapid's end with no feed block after it.
  for (size_t i = programmed.size(); i-- > 0;)
    if (programmed[i].size() < 2) {
      programmed.erase(programmed.begin() + static_cast<long>(i));
      programmed_source.erase(programmed_source.begin() + static_cast<long>(i));
      contour.erase(contour.begin() + static_cast<long>(i));
    }
  ProgrammedPointDeviation result;
  result.polylines = programmed.size();
  const PolylineDistance to_programmed(contour), to_path(path);
  StatsSum along, at_points;
  for (const SampledElement& e : elements)
    if (!e.rapid)
      for (const Vec3& p : e.points) along.add(to_programmed.distance(p), e.source);
  for (size_t r = 0; r < programmed.size(); ++r) {
    result.programmed_points += programmed[r].size();
    for (size_t i = 0; i < programmed[r].size(); ++i)
      at_points.add(to_path.distance(programmed[r][i]), *programmed_source[r][i]);
  }
  result.path_to_polyline = along.result();
  result.points_to_path = at_points.result();
  return result;
}

}  // namespace drycut::workload
