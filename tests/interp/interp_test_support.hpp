#pragma once
// Runs NC text through the real loader and interpreter and collects the element stream.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "interp/cutting_speed_pieces.hpp"
#include "interp/interpreter.hpp"
#include "parser/program_loader.hpp"

namespace drycut::interp::testing {

class CollectingSink : public ElementSink {
 public:
  void consume(PathElement&& e) override { elements.push_back(std::move(e)); }
  void finish() override { finished = true; }
  std::vector<PathElement> motions() const {
    std::vector<PathElement> out;
    for (const auto& e : elements)
      if (e.is_motion()) out.push_back(e);
    return out;
  }
  std::vector<PathElement> elements;
  bool finished = false;
};

// The motions after the G96 stage (cutting_speed_pieces.hpp), as the planner receives them.
inline std::vector<PathElement> with_cutting_speed_pieces(const std::vector<PathElement>& motions) {
  CollectingSink out;
  CuttingSpeedPieces stage(out);
  for (const auto& e : motions) stage.consume(PathElement(e));
  stage.finish();
  return out.motions();
}

// A small machine: axes ±1000 mm, G54 = (10, 20, 0), tool FR_4 (T1) with D1 r = 2 mm.
inline machine::MachineProfile test_profile() {
  machine::MachineProfile p;
  p.name = "test";
  for (int i = 0; i < 3; ++i) {
    auto& a = p.axes[static_cast<size_t>(i)];
    a.name = std::string(1, "XYZ"[i]);
    a.min_mm = -1000;
    a.max_mm = 1000;
    a.max_velocity_mm_s = 40000.0 / 60.0;
    a.max_accel_mm_s2 = 5000;
    a.max_jerk_mm_s3 = 50000;
  }
  p.reset_gcodes = {"G1", "G17", "G40", "G500", "G60", "G71", "G90", "G94", "BRISK", "BNAT", "ENAT", "NORM", "G450", "CDOF"};
  p.work_offsets["G54"] = Eigen::Vector3d(10, 20, 0);
  p.tools.push_back({"FR_4", 1, {{1, 2.0, 50.0}}});
  p.start_position = Eigen::Vector3d(0, 0, 100);
  return p;
}

struct RunResult {
  CollectingSink sink;
  Diagnostics diagnostics;
  std::optional<Alarm> alarm;
  Eigen::Vector3d end_position = Eigen::Vector3d::Zero();
};

// Writes `text` as MAIN.MPF (and `subprograms` as NAME.SPF) into a fresh folder and runs it.
inline std::unique_ptr<RunResult> run_program(const std::string& text,
                                              const machine::MachineProfile& profile = test_profile(),
                                              const std::vector<std::pair<std::string, std::string>>& subprograms = {}) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("drycut_interp_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "MAIN.MPF") << text;
  for (const auto& [name, body] : subprograms) std::ofstream(dir / (name + ".SPF")) << body;
  auto result = std::make_unique<RunResult>();
  parser::ProgramLoader loader({}, result->diagnostics);
  loader.open_main(dir / "MAIN.MPF");
  Interpreter interp(profile, result->sink, result->diagnostics);
  parser::Block block;
  try {
    while (loader.next(block) && !interp.ended()) interp.execute(block);
    interp.finish();
  } catch (const AlarmError& e) {
    result->alarm = e.alarm();
  }
  result->end_position = interp.position();
  std::filesystem::remove_all(dir);
  return result;
}

inline ::testing::AssertionResult near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-9) {
  if ((a - b).norm() <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.transpose() << ") vs (" << b.transpose() << ")";
}

}  // namespace drycut::interp::testing
