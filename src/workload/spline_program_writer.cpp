#include "workload/spline_program_writer.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace drycut::workload {
namespace {

// Three decimals as in the experiment's listings; never "-0.000".
std::string coord(char axis, double value) {
  char buf[48];
  double v = std::round(value * 1000.0) / 1000.0;
  if (v == 0.0) v = 0.0;
  std::snprintf(buf, sizeof buf, "%c%.3f", axis, v);
  return buf;
}

class BlockWriter {
 public:
  explicit BlockWriter(std::string& out) : out_(out) {}
  void block(const std::string& words) {
    out_ += "N" + std::to_string(number_) + " " + words + "\n";
    number_ += step_;
  }
  void set_numbering(int first, int step) { number_ = first; step_ = step; }

 private:
  std::string& out_;
  int number_ = 1;
  int step_ = 1;
};

std::string knot_words(const ProgramSpec& spec, const Vec3& p, double z) {
  std::string words;
  if (spec.method == Method::Linear) words = "G1 ";
  words += coord('X', p.x()) + " " + coord('Y', p.y()) + " " + coord('Z', z);
  if (spec.method == Method::BSpline) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " PW=%g", spec.bspline_weight);
    words += buf;
  }
  return words;
}

// Progressive 3-D milling (§4): entry, three loops, exit.
void write_progressive_loops(BlockWriter& sub, const std::vector<Knot>& knots, double period,
                             const ProgramSpec& spec) {
  const double t0 = knots.front().t;
  const Vec3 seam = knots.front().point;
  const double depth = spec.depth_mm;
  // Entry: knots with t in (t0 - entry, t0), Z falling linearly in t from the entry height to 0.
  for (const Knot& k : knots) {
    const double rel = k.t - t0 - period;  // the knots at the end of the loop, seen before the seam
    if (rel > -spec.entry_angle_rad + 1e-9 && rel < -1e-12)
      sub.block(knot_words(spec, k.point, spec.entry_height_mm * (-rel) / spec.entry_angle_rad));
  }
  sub.block(knot_words(spec, seam, 0.0));
  // Three loops: Z from 0 to -depth, at -depth, back to 0, linearly in t.
  for (int loop = 0; loop < 3; ++loop) {
    for (size_t i = 1; i <= knots.size(); ++i) {
      const Knot& k = knots[i % knots.size()];
      const double frac = i == knots.size() ? 1.0 : (k.t - t0) / period;
      const double z = loop == 0 ? -depth * frac : loop == 1 ? -depth : -depth + depth * frac;
      sub.block(knot_words(spec, k.point, z));
    }
  }
  // Exit: knots with t in (t0, t0 + entry], Z rising to the entry height.
  for (const Knot& k : knots) {
    const double rel = k.t - t0;
    if (rel > 1e-12 && rel <= spec.entry_angle_rad + 1e-9)
      sub.block(knot_words(spec, k.point, spec.entry_height_mm * rel / spec.entry_angle_rad));
  }
}

// 2-D milling: one loop at -depth, with `overlap_knots` knots before and after the seam (§5).
void write_single_loop(BlockWriter& sub, const std::vector<Knot>& knots, const ProgramSpec& spec) {
  const double depth = spec.depth_mm;
  const size_t n = knots.size();
  const size_t overlap = static_cast<size_t>(spec.overlap_knots) % n;
  for (size_t i = n - overlap; i < n; ++i) sub.block(knot_words(spec, knots[i].point, -depth));
  for (size_t i = 0; i <= n + overlap; ++i) sub.block(knot_words(spec, knots[i % n].point, -depth));
}

// The subprogram: one block per knot.
std::string subprogram_text(const std::vector<Knot>& knots, double period, const ProgramSpec& spec) {
  std::string text = "; " + spec.sub_name + ": " + std::to_string(knots.size()) + " knots per loop, " +
                     method_name(spec.method) + "\n";
  BlockWriter sub(text);
  if (spec.mode == MillingMode::Progressive3D)
    write_progressive_loops(sub, knots, period, spec);
  else
    write_single_loop(sub, knots, spec);
  text += "M17\n";
  return text;
}

// Tool, spindle and the approach up to G42.
void write_setup(BlockWriter& main, const ProgramSpec& spec) {
  char buf[96];
  main.block("G54");
  main.block("T=\"" + spec.tool + "\"");
  main.block("M6");
  main.block("G64");
  main.block("SOFT");
  std::snprintf(buf, sizeof buf, "M3 S%g M8", spec.spindle_rpm);
  main.block(buf);
  if (spec.mode == MillingMode::Progressive3D) {
    std::snprintf(buf, sizeof buf, "G1 Z10 F%g", spec.feed_mm_min);
    main.block(buf);
    main.block("M0");
    main.block("G4 F2");
    main.block("G42");
  } else {
    main.block("G1 Z-2 F2000");
    std::snprintf(buf, sizeof buf, "G1 X40 Y0 F%g", spec.feed_mm_min);
    main.block(buf);
    main.block("G42");
  }
}

// 3-D mode: the method's lead-in to the entry point.
void write_entry(BlockWriter& main, const ProgramSpec& spec) {
  // The first contour point of the run is the entry point (-30°), 0.5 mm above the part.
  const Vec3& entry = spec.entry_point;
  const std::string entry_words =
      coord('X', entry.x()) + " " + coord('Y', entry.y()) + " " + coord('Z', spec.entry_height_mm);
  char buf[96];
  switch (spec.method) {
    case Method::Linear:
      main.block("G1 X37 Y-15");
      main.block("G1 " + entry_words);
      break;
    case Method::CSpline:
      main.block("G1 X40");
      main.block("G1 X37");
      main.block("BTAN ETAN");
      main.block("CSPLINE");
      main.block(entry_words);
      break;
    case Method::ASpline:
      main.block("G1 X37");
      main.block("BTAN ETAN");
      main.block("ASPLINE");
      main.block(entry_words);
      break;
    case Method::BSpline:
      main.block("G1 X37");
      main.block("BSPLINE");
      std::snprintf(buf, sizeof buf, " PW=%g", spec.bspline_weight);
      main.block(entry_words + buf);
      break;
  }
}

// 2-D mode: the lead-in and the method.
void write_loop_start(BlockWriter& main, const ProgramSpec& spec) {
  main.block("G1 X37");
  if (spec.method == Method::ASpline || spec.method == Method::CSpline) main.block("BTAN ETAN");
  if (spec.method == Method::ASpline) main.block("ASPLINE");
  if (spec.method == Method::BSpline) main.block("BSPLINE");
  if (spec.method == Method::CSpline) main.block("CSPLINE");
}

// The main program (EXPERIMENT.md §4; numbering as in the thesis listing).
std::string main_program_text(const ProgramSpec& spec) {
  std::string text = "; " + spec.main_name + ": " + method_name(spec.method) + " finishing, subprogram " +
                     spec.sub_name + "\n";
  BlockWriter main(text);
  main.set_numbering(10, 10);
  write_setup(main, spec);
  if (spec.mode == MillingMode::Progressive3D)
    write_entry(main, spec);
  else
    write_loop_start(main, spec);
  main.block(spec.sub_name);
  main.block("G40");
  main.block("G1 X30 Y30 F700");
  main.block("G1 Z10 F5000");
  main.block("Y100");
  main.block("M5");
  main.block("M30");
  return text;
}

}  // namespace

const char* method_name(Method method) {
  switch (method) {
    case Method::Linear: return "linear";
    case Method::ASpline: return "aspline";
    case Method::BSpline: return "bspline";
    case Method::CSpline: return "cspline";
  }
  return "?";
}

Method parse_method(const std::string& name) {
  for (Method m : {Method::Linear, Method::ASpline, Method::BSpline, Method::CSpline})
    if (name == method_name(m)) return m;
  throw std::invalid_argument("unknown method '" + name + "' (linear, aspline, bspline, cspline)");
}

GeneratedProgram write_contour_program(const std::vector<Knot>& knots, double period, const ProgramSpec& spec) {
  if (knots.size() < 3) throw std::invalid_argument("a contour needs at least 3 knots");
  GeneratedProgram program;
  program.sub_text = subprogram_text(knots, period, spec);
  program.main_text = main_program_text(spec);
  return program;
}

}  // namespace drycut::workload
