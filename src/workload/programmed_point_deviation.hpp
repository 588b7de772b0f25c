#pragma once
// How far the interpolated path strays from the program's own points (`drycut deviation
// --programmed-points`): the programmed polyline joins the end points of the feed blocks as the
// interpreter reaches them (G1 end points, spline knots, arcs along their circle; a rapid's end
// point starts a new polyline), and the path is the interpolated feed path sampled by arc length. Two figures, both in 3-D:
//   path -> polyline: for every path sample its distance to the nearest point of any programmed
//     polyline (how far smoothing or a spline bulges between the points);
//   points -> path: for every programmed point its distance to the sampled path (how far the
//     path misses the points: 0 for straight G1 and for interpolating splines, the corner
//     rounding of G642 or a compressor's tolerance otherwise).
// Distances are exact point-to-segment distances; the segments are grouped in chunks of 32 with
// a bounding box each, and a chunk whose box is farther than the best distance so far is
// skipped (the previous query's best chunk is tried first, so a walk along the path stays cheap).
// A programmed arc (G2/G3, CIP, CT) is part of the programmed contour as the circle it is, not
// its chord: the polyline runs through the arc's own points (ProgrammedPoint::via).
#include <cstddef>
#include <vector>

#include "workload/deviation_program_run.hpp"

namespace drycut::workload {

// Nearest distance from points to a set of 3-D polylines.
class PolylineDistance {
 public:
  explicit PolylineDistance(const std::vector<std::vector<Vec3>>& polylines);
  // Infinite when there is no segment (a polyline of one point is a segment of length 0).
  double distance(const Vec3& p) const;

 private:
  struct Chunk {
    Vec3 lo, hi;
    size_t first = 0, last = 0;  // segments [first, last)
  };
  double chunk_distance(const Chunk& c, const Vec3& p) const;
  std::vector<Vec3> from_, to_;
  std::vector<Chunk> chunks_;
  mutable size_t hint_ = 0;
};

struct DistanceStats {
  size_t count = 0;
  double max_mm = 0.0, mean_mm = 0.0;
  BlockRef max_at;  // the block of the sample or point farthest off
};

struct ProgrammedPointDeviation {
  size_t programmed_points = 0, polylines = 0;
  DistanceStats path_to_polyline;  // per path sample
  DistanceStats points_to_path;    // per programmed point
};

// `points` in program order (the start position first), `elements` the sampled path; feed
// elements only, rapids left out.
ProgrammedPointDeviation programmed_point_deviation(const std::vector<ProgrammedPoint>& points,
                                                    const std::vector<SampledElement>& elements);

}  // namespace drycut::workload
