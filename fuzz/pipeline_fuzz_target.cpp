// libFuzzer target over the whole dry run: loader (lexer, parser, expressions, control flow,
// subprogram calls) -> interpreter -> tool radius compensation -> motion planner.
// The input becomes the main program FUZZ.MPF in a private folder, so a call of FUZZ recurses
// into itself and any other call is an unknown subprogram.
// Acceptable outcomes: a clean end or an AlarmError. Anything else (another exception, a crash,
// a sanitizer report, a hang, a non-finite or negative time) is a finding.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "interp/controller_state_view.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp/interpreter.hpp"
#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"
#include "motion/planner.hpp"
#include "parser/loader_machine.hpp"
#include "parser/program_loader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace drycut;

// Blocks executed before the loader's endless-loop alarm: small so that loops stay fast.
constexpr uint64_t kMaxSteps = 20'000;

struct Workspace {
  fs::path dir;
  fs::path program;
  machine::MachineProfile profile = machine::default_profile();

  Workspace() {
    dir = fs::temp_directory_path() / ("drycut_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    program = dir / "FUZZ.MPF";
  }
  ~Workspace() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

void write_file(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

void run_pipeline(const Workspace& w) {
  Diagnostics diagnostics;
  motion::PlanObserver observer;
  motion::Planner planner(w.profile, observer);
  interp::CutterCompensation compensation(planner, w.profile, diagnostics);
  parser::LoaderOptions options;
  options.max_steps = kMaxSteps;
  parser::add_machine(options, w.profile);  // $MN_/$MA_/... reads and axis names as in `run`
  parser::ProgramLoader loader(options, diagnostics);
  loader.open_main(w.program);
  interp::Interpreter interpreter(w.profile, compensation, diagnostics);
  interp::InterpreterStateView state_view(interpreter, w.profile);
  loader.set_state_view(&state_view);  // $P_/$AA_/$TC_ reads see the interpreted state, as in `run`
  parser::Block block;
  try {
    while (loader.next(block)) {
      interpreter.execute(block);
      if (interpreter.ended()) break;
    }
  } catch (const AlarmError&) {
  }
  try {
    interpreter.finish();
  } catch (const AlarmError&) {
  }
  // The report must never show an absurd time: finite and not negative.
  const motion::PlanSummary& s = planner.summary();
  if (!std::isfinite(s.time_s) || s.time_s < 0 || !std::isfinite(s.path_length_mm) || s.path_length_mm < 0) {
    std::fprintf(stderr, "absurd summary: time %g s, path %g mm\n", s.time_s, s.path_length_mm);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const Workspace workspace;
  write_file(workspace.program, data, size);
  run_pipeline(workspace);
  return 0;
}
