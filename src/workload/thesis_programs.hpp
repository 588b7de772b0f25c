#pragma once
// The reference experiment's programs (EXPERIMENT.md §2–§5): 6 knot sets × 4 methods for the 3-D
// finishing, and the 2-D single-loop variants, all on the contour r = 18 + 4 cos 6θ cos 2θ.
#include <string>
#include <vector>

#include "workload/spline_program_writer.hpp"

namespace drycut::workload {

struct KnotSet {
  std::string id;          // "EKVI_90", "POLAR_5"
  bool equidistant;        // per-quadrant equal arc length (true) or polar angle step (false)
  int value;               // knots per quadrant, or step in degrees
  int overlap_2d;          // knots repeated before and after the seam in the 2-D programs
};

// The six sets of the experiment, in the order of its tables.
const std::vector<KnotSet>& thesis_knot_sets();

std::vector<Knot> thesis_knots(const KnotSet& set);

struct ProgramFile {
  std::string file_name;   // e.g. "EKVI_A_90.MPF"
  std::string text;
};

struct ThesisProgram {
  KnotSet set;
  Method method;
  MillingMode mode;
  ProgramFile main;
  ProgramFile sub;
};

// All programs: for every set and method the 3-D finishing program and the 2-D program.
std::vector<ThesisProgram> thesis_programs();

}  // namespace drycut::workload
