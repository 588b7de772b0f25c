#include "workload/deviation_program_run.hpp"

#include <algorithm>

#include "interp/block_compressor.hpp"
#include "interp/corner_smoothing.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp/interpreter.hpp"
#include "parser/loader_machine.hpp"
#include "parser/program_loader.hpp"

namespace drycut::workload {
namespace {

// Hands every element to the programmed sampler and to the compensation branch; the branch
// is dropped at its first alarm.
class TeeSink : public interp::ElementSink {
 public:
  TeeSink(interp::ElementSink& programmed, interp::ElementSink* compensation, std::optional<Alarm>& branch_alarm)
      : programmed_(programmed), compensation_(compensation), branch_alarm_(branch_alarm) {}

  void consume(interp::PathElement&& element) override {
    if (compensation_) guarded([&] { compensation_->consume(interp::PathElement(element)); });  // a copy
    programmed_.consume(std::move(element));
  }
  void finish() override {
    if (compensation_) guarded([&] { compensation_->finish(); });
    programmed_.finish();
  }

 private:
  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const AlarmError& e) {
      branch_alarm_ = e.alarm();
      compensation_ = nullptr;
    }
  }
  interp::ElementSink& programmed_;
  interp::ElementSink* compensation_;
  std::optional<Alarm>& branch_alarm_;
};

// The path the block just made (its elements from `first` on) when one of them is an arc and
// they end where the block ended: their points without the block's end point. None for any other
// block (straight lines add nothing to the polyline; an arc held back by a corner word belongs
// to a later point and is judged against its chord there).
std::vector<Vec3> arc_points(const std::vector<SampledElement>& elements, size_t first, const Vec3& end) {
  std::vector<Vec3> via;
  if (first >= elements.size() || (elements.back().end() - end).norm() > 1e-9) return via;
  if (std::none_of(elements.begin() + static_cast<long>(first), elements.end(), [](const SampledElement& e) { return e.arc; }))
    return via;
  for (size_t i = first; i < elements.size(); ++i) via.insert(via.end(), elements[i].points.begin() + 1, elements[i].points.end());
  via.pop_back();  // `end` itself
  return via;
}

}  // namespace

SampledProgram sample_program(const std::filesystem::path& main_program, const machine::MachineProfile& profile,
                              const SampleOptions& options) {
  SampledProgram result;
  PathSampler programmed(options.step_mm), tool_centre(options.step_mm);
  Diagnostics compensation_diagnostics;
  // The cut path as the planner gets it: compensated, compressed (COMPON/COMPCURV/COMPCAD), then
  // its corners rounded (G641..G645).
  interp::CornerSmoothing smoothing(tool_centre, profile);
  interp::BlockCompressor compressor(smoothing, profile);
  std::optional<interp::CutterCompensation> compensation;
  if (options.tool_centre) compensation.emplace(compressor, profile, compensation_diagnostics);
  TeeSink tee(programmed, compensation ? &*compensation : nullptr, result.compensation_alarm);

  parser::LoaderOptions loader_options = options.loader;
  if (loader_options.axis_names.empty()) parser::add_machine(loader_options, profile);
  parser::ProgramLoader loader(loader_options, result.diagnostics);
  loader.open_main(main_program);
  interp::Interpreter interpreter(profile, tee, result.diagnostics);
  parser::Block block;
  result.programmed_points.push_back({interpreter.position(), true, {}, {}});
  try {
    while (loader.next(block)) {
      const size_t elements_before = programmed.elements().size();
      interpreter.execute(block);
      // A full circle ends where it started: a point too.
      std::vector<Vec3> via = arc_points(programmed.elements(), elements_before, interpreter.position());
      if ((interpreter.position() - result.programmed_points.back().position).norm() > 1e-12 || !via.empty())
        result.programmed_points.push_back({interpreter.position(),
                                            interpreter.state().motion == interp::MotionMode::Rapid,
                                            BlockRef{block.file, block.line, block.text}, std::move(via)});
      if (interpreter.ended()) break;
    }
  } catch (const AlarmError& e) {
    result.program_alarm = e.alarm();
  }
  try {
    interpreter.finish();
  } catch (const AlarmError& e) {
    if (!result.program_alarm) result.program_alarm = e.alarm();
  }
  for (const Alarm& a : compensation_diagnostics.items()) result.diagnostics.report(a);
  result.programmed = programmed.elements();
  if (options.tool_centre) result.tool_centre = tool_centre.elements();
  return result;
}

}  // namespace drycut::workload
