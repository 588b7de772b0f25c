#include "workload/thesis_programs.hpp"

#include <numbers>

namespace drycut::workload {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Method letters in program names. The experiment's subprograms are EKVI_POSTUPNE_45 (A),
// EKVI_POSTUPNE_B_45 and EKVI_POSTUPNE_LIN_45; the C-spline one gets C.
std::string method_tag(Method m) {
  switch (m) {
    case Method::Linear: return "LIN";
    case Method::ASpline: return "A";
    case Method::BSpline: return "B";
    case Method::CSpline: return "C";
  }
  return "?";
}

}  // namespace

const std::vector<KnotSet>& thesis_knot_sets() {
  static const std::vector<KnotSet> sets{
      {"EKVI_90", true, 90, 12}, {"EKVI_45", true, 45, 6}, {"EKVI_15", true, 15, 2},
      {"POLAR_1", false, 1, 10}, {"POLAR_5", false, 5, 3}, {"POLAR_15", false, 15, 2},
  };
  return sets;
}

std::vector<Knot> thesis_knots(const KnotSet& set) {
  const CurveSource curve = polar_curve(thesis_radius);
  return set.equidistant ? equal_arc_per_quadrant_knots(curve, set.value)
                         : parameter_step_knots(curve, set.value * kDeg);
}

std::vector<ThesisProgram> thesis_programs() {
  std::vector<ThesisProgram> out;
  const CurveSource curve = polar_curve(thesis_radius);
  for (const KnotSet& set : thesis_knot_sets()) {
    const std::vector<Knot> knots = thesis_knots(set);
    const std::string family = set.equidistant ? "EKVI" : "POLAR";
    const std::string number = std::to_string(set.value);
    for (Method method : {Method::Linear, Method::ASpline, Method::BSpline, Method::CSpline}) {
      for (MillingMode mode : {MillingMode::Progressive3D, MillingMode::Loop2D}) {
        ProgramSpec spec;
        spec.method = method;
        spec.mode = mode;
        const std::string tag = method_tag(method);
        const std::string kind = mode == MillingMode::Progressive3D ? "POSTUPNE" : "2D";
        spec.sub_name = family + "_" + kind + (method == Method::ASpline ? "" : "_" + tag) + "_" + number;
        spec.main_name = family + "_" + tag + "_" + number + (mode == MillingMode::Loop2D ? "_2D" : "");
        spec.feed_mm_min = mode == MillingMode::Progressive3D ? 1530 : 1270;
        spec.overlap_knots = set.overlap_2d;
        spec.entry_point = curve.point(-spec.entry_angle_rad);
        GeneratedProgram g = write_contour_program(knots, 2.0 * std::numbers::pi, spec);
        out.push_back({set, method, mode, {spec.main_name + ".MPF", std::move(g.main_text)},
                       {spec.sub_name + ".SPF", std::move(g.sub_text)}});
      }
    }
  }
  return out;
}

}  // namespace drycut::workload
