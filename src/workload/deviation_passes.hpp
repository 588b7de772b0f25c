#pragma once
// Picks the contour out of a sampled program and splits it into passes at the seam.
//
// Contour: the feed moves (not G0) whose start and end both lie within `capture_mm` of the
// reference curve; approach, retract and the spline span that leads onto the first knot do not.
// The tool-centre elements of the same blocks form the compensated contour.
// Passes: each sample's nearest reference point gives its parameter fraction u; unwrapped along
// the travel, every crossing of u = 0 (the seam) starts a new pass. A pass that covers the whole
// curve is a loop ("loop 1", "loop 2", ...); partial passes before the first loop are "entry",
// after the last "exit" (the 3-D thesis programs: entry, three loops, exit; the 2-D ones:
// overlap knots, one loop, overlap knots).
#include <cstddef>
#include <string>
#include <vector>

#include "workload/deviation_program_run.hpp"
#include "workload/deviation_reference.hpp"

namespace drycut::workload {

struct ContourPass {
  std::string name;
  bool full_loop = false;
  double u_low = 0.0, u_high = 0.0;  // unwrapped parameter fractions covered
  double mean_z_mm = 0.0;
  std::vector<Vec3> programmed;      // samples in travel order
  std::vector<Vec3> tool_centre;     // empty without compensation
};

struct ContourSplit {
  std::vector<ContourPass> passes;
  size_t contour_elements = 0;
  double tool_radius_mm = 0.0;       // 0: no compensation on the contour
  // The full loop at the lowest Z (the finished wall at the bottom: loop 2 at Z = -6 in the
  // 3-D programs); the longest pass when no pass is a full loop. passes.size() when empty.
  size_t bottom_loop = 0;
};

ContourSplit split_contour(const SampledProgram& program, const ReferenceContour& reference, double capture_mm = 0.5);

}  // namespace drycut::workload
