#pragma once
// Runs a part program through loader -> interpreter (-> tool radius compensation) and samples
// both the programmed path and the tool-centre path. An alarm ends the programmed run as on the
// control; an alarm in the compensation only ends the tool-centre branch, so the programmed
// contour can still be judged when the compensation cannot follow it.
#include <filesystem>
#include <optional>
#include <vector>

#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"
#include "parser/program_loader.hpp"
#include "workload/deviation_path_sampler.hpp"

namespace drycut::workload {

// A programmed end point: where the interpreter stands after a block that moved (machine
// coordinates, as the elements), and whether the block was a rapid. Spline blocks give their
// knots here, which the spline's own elements need not pass through (BSPLINE).
struct ProgrammedPoint {
  Vec3 position = Vec3::Zero();
  bool rapid = false;
  BlockRef source;  // the block that ends here (none for the start position)
  // Points of an arc the block programs (G2/G3, CIP, CT), between the previous point and this
  // one: the programmed contour follows the circle there, not its chord.
  std::vector<Vec3> via;
};

struct SampledProgram {
  std::vector<SampledElement> programmed;
  std::vector<ProgrammedPoint> programmed_points;  // the start position first (as a rapid)
  std::vector<SampledElement> tool_centre;
  std::optional<Alarm> program_alarm;       // the run stopped here
  std::optional<Alarm> compensation_alarm;  // the tool-centre path stops here
  Diagnostics diagnostics;                  // warnings of both branches
};

struct SampleOptions {
  // The loader's options as the other commands set them up (search path with the standard
  // cycles, definition files such as CYCLE_MACROS.DEF, step limit): a program must read the same
  // language here as in `run`. The machine's data and axis names are added from the profile when
  // the options have none (parser::add_machine).
  parser::LoaderOptions loader;
  double step_mm = 0.01;
  bool tool_centre = true;
};

// Throws UsageError when the program cannot be read.
SampledProgram sample_program(const std::filesystem::path& main_program, const machine::MachineProfile& profile,
                              const SampleOptions& options);

}  // namespace drycut::workload
