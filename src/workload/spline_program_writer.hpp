#pragma once
// Writes SINUMERIK programs that mill a closed contour through given knots, as the reference
// experiment did (EXPERIMENT.md §3–§5): a main program (.MPF) that sets up, approaches with G42
// and selects the method, and a subprogram (.SPF) with one block per knot.
#include <string>
#include <vector>

#include "workload/knot_distribution.hpp"

namespace drycut::workload {

enum class Method { Linear, ASpline, BSpline, CSpline };

const char* method_name(Method method);   // "linear", "aspline", "bspline", "cspline"
Method parse_method(const std::string& name);  // throws std::invalid_argument

enum class MillingMode {
  Progressive3D,  // entry, three loops (Z 0 → −depth, at −depth, back to 0), exit (§4)
  Loop2D,         // one loop at Z = −depth with overlap knots at the seam (§5)
};

struct ProgramSpec {
  Method method = Method::ASpline;
  MillingMode mode = MillingMode::Progressive3D;
  std::string main_name = "MAIN";
  std::string sub_name = "CONTOUR";
  std::string tool = "FR_4";
  double feed_mm_min = 1530;
  double spindle_rpm = 17000;
  double depth_mm = 6.0;
  double entry_angle_rad = 0.5235987755982988;  // 30°: entry and exit arcs of the 3-D mode
  double entry_height_mm = 0.5;
  Vec3 entry_point = Vec3::Zero();  // the curve point at the entry angle before the seam
  int overlap_knots = 0;  // 2-D mode: knots repeated before and after the seam
  double bspline_weight = 3.0;  // PW on every B-spline knot (the experiment used 3)
};

struct GeneratedProgram {
  std::string main_text;
  std::string sub_text;
};

// `knots` are the distinct knots of one loop in the order of travel, the first at the seam
// (t = t_begin), parameters increasing over one period of length `period`.
GeneratedProgram write_contour_program(const std::vector<Knot>& knots, double period, const ProgramSpec& spec);

}  // namespace drycut::workload
