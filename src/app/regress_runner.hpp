#pragma once
// Runs many programs for `drycut regress`, in parallel across files. Each program runs on one
// worker thread with its own loader, interpreter, compensation and planner and its own copy of
// the machine profile; nothing mutable is shared between runs (the loader's and planner's caches
// are per instance, the library's statics are const tables built once and thread-safe, nothing
// logs through spdlog on this path). Workers take the next program from an atomic counter;
// results land in their program's slot, so the output order does not depend on the timing.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/program_pipeline.hpp"
#include "machine/machine_profile.hpp"
#include "report/regress_baseline.hpp"

namespace drycut::app {

struct RegressJob {
  std::filesystem::path program;
  std::string key;  // the baseline key (path relative to the baseline's folder)
};

struct RegressResult {
  report::ProgramFigures figures;
  double wall_s = 0;
};

// One program through loader -> interpreter -> compensation -> planner. Never throws: a run
// that cannot start (unreadable file, bad option) has `figures.error` set.
RegressResult measure_program(const RegressJob& job, const ProgramOptions& common, const machine::MachineProfile& profile);

// Every job on `jobs` threads (at least 1). `progress(done, total)` is called on the calling
// thread a few times a second while they run, and once at the end.
std::vector<RegressResult> run_in_parallel(const std::vector<RegressJob>& jobs, const ProgramOptions& common,
                                           const machine::MachineProfile& profile, unsigned threads,
                                           const std::function<void(size_t, size_t)>& progress);

}  // namespace drycut::app
