// `drycut generate`: spline (or polygon) programs through knots on an analytic curve, and the
// reference experiment's programs with `--thesis DIR`.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>

#include "app/output_file.hpp"
#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/curve_options.hpp"
#include "machine/alarm.hpp"
#include "workload/thesis_programs.hpp"

namespace drycut::app {
namespace {

struct GenerateOptions {
  std::string thesis_dir;
  CurveOptions curve;
  std::string out_dir = ".";
  std::string name = "CONTOUR";
  std::string method = "aspline";
  std::string mode = "3d";
  double step_deg = 0;
  int per_quadrant = 0;
  int count = 0;
  double chord_error_mm = 0;
  double feed = 1530;
  double spindle = 17000;
  double depth = 6;
  int overlap = 0;
  std::string tool = "FR_4";
};

int generate_thesis(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  size_t files = 0;
  for (const auto& p : workload::thesis_programs()) {
    write_output_file(dir / p.main.file_name, p.main.text);
    write_output_file(dir / p.sub.file_name, p.sub.text);
    files += 2;
  }
  std::printf("wrote %zu files to %s\n", files, dir.string().c_str());
  return kExitOk;
}

int generate_one(const GenerateOptions& o) {
  const workload::CurveSource curve = make_curve(o.curve);
  const int chosen = (o.step_deg > 0) + (o.per_quadrant > 0) + (o.count > 0) + (o.chord_error_mm > 0);
  if (chosen != 1)
    throw UsageError("choose exactly one knot distribution: --step-deg, --per-quadrant, --count or --chord-error");
  std::vector<workload::Knot> knots;
  if (o.step_deg > 0) knots = workload::parameter_step_knots(curve, o.step_deg * std::numbers::pi / 180.0);
  if (o.per_quadrant > 0) knots = workload::equal_arc_per_quadrant_knots(curve, o.per_quadrant);
  if (o.count > 0) knots = workload::equal_arc_knots(curve, o.count);
  if (o.chord_error_mm > 0) knots = workload::chord_error_knots(curve, o.chord_error_mm);

  workload::ProgramSpec spec;
  try {
    spec.method = workload::parse_method(o.method);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (o.mode != "3d" && o.mode != "2d") throw UsageError("--mode must be 3d or 2d");
  spec.mode = o.mode == "3d" ? workload::MillingMode::Progressive3D : workload::MillingMode::Loop2D;
  spec.main_name = o.name;
  spec.sub_name = o.name + "_SUB";
  spec.tool = o.tool;
  spec.feed_mm_min = o.feed;
  spec.spindle_rpm = o.spindle;
  spec.depth_mm = o.depth;
  spec.overlap_knots = o.overlap;
  spec.entry_point = curve.point(curve.t_end - spec.entry_angle_rad);
  const auto program = workload::write_contour_program(knots, curve.t_end - curve.t_begin, spec);
  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  write_output_file(dir / (spec.main_name + ".MPF"), program.main_text);
  write_output_file(dir / (spec.sub_name + ".SPF"), program.sub_text);
  std::printf("%zu knots per loop; wrote %s and %s (%zu + %zu bytes)\n", knots.size(),
              (dir / (spec.main_name + ".MPF")).string().c_str(), (dir / (spec.sub_name + ".SPF")).string().c_str(),
              program.main_text.size(), program.sub_text.size());
  return kExitOk;
}

}  // namespace

void register_generate(CLI::App& app) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("generate", "Write a spline or polygon program through knots on a curve");
  cmd->add_option("--thesis", o->thesis_dir, "Write the reference experiment's programs into this folder");
  add_curve_options(*cmd, o->curve);
  cmd->add_option("--out", o->out_dir, "Output folder")->default_val(".");
  cmd->add_option("--name", o->name, "Main program name (the subprogram is NAME_SUB)")->default_val("CONTOUR");
  cmd->add_option("--method", o->method, "linear, aspline, bspline or cspline")->default_val("aspline");
  cmd->add_option("--mode", o->mode, "3d (entry, three loops, exit) or 2d (one loop)")->default_val("3d");
  cmd->add_option("--step-deg", o->step_deg, "Knot every STEP of the curve parameter (degrees)");
  cmd->add_option("--per-quadrant", o->per_quadrant, "N knots per quadrant at equal arc length");
  cmd->add_option("--count", o->count, "N knots at equal arc length over the whole curve");
  cmd->add_option("--chord-error", o->chord_error_mm, "Curvature-adaptive knots: chord error at most MM");
  cmd->add_option("--feed", o->feed, "Feed F in mm/min")->default_val(1530);
  cmd->add_option("--spindle", o->spindle, "Spindle speed S in rpm")->default_val(17000);
  cmd->add_option("--depth", o->depth, "Depth of the contour below Z0 in mm")->default_val(6);
  cmd->add_option("--overlap", o->overlap, "2-D mode: knots repeated before and after the seam")->default_val(0);
  cmd->add_option("--tool", o->tool, "Tool name for T=\"...\"")->default_val("FR_4");
  cmd->callback([o] {
    try {
      throw ExitRequest{o->thesis_dir.empty() ? generate_one(*o) : generate_thesis(o->thesis_dir)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut generate: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    } catch (const AlarmError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      throw ExitRequest{kExitAlarm};
    }
  });
}

}  // namespace drycut::app
