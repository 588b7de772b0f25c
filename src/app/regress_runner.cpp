#include "app/regress_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "motion/planner.hpp"

namespace drycut::app {

RegressResult measure_program(const RegressJob& job, const ProgramOptions& common,
                              const machine::MachineProfile& profile) {
  RegressResult r;
  r.figures.program = job.key;
  const auto start = std::chrono::steady_clock::now();
  try {
    ProgramOptions options = common;
    options.program = job.program.string();
    options.quiet = true;  // one progress line for all programs, drawn by the caller
    motion::PlanObserver none;
    motion::Planner planner(profile, none, motion::PlannerOptions{});
    const PipelineOutcome outcome = run_program_tool_centre(options, profile, planner);
    const motion::PlanSummary& s = planner.summary();
    r.figures.time_s = s.time_s;
    r.figures.time_after_m0_s = s.time_after_m0_s;
    r.figures.min_feed_mm_min = s.min_feed_mm_s * 60.0;
    r.figures.path_length_mm = s.path_length_mm;
    r.figures.dips = s.dips.size() + s.dips_not_listed;
    r.figures.complete = !outcome.alarm && !outcome.diagnostics.has_alarms();
    report::set_diagnostics(r.figures, outcome.diagnostics.items());
  } catch (const std::exception& e) {
    r.figures.error = e.what();
    r.figures.complete = false;
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<RegressResult> run_in_parallel(const std::vector<RegressJob>& jobs, const ProgramOptions& common,
                                           const machine::MachineProfile& profile, unsigned threads,
                                           const std::function<void(size_t, size_t)>& progress) {
  std::vector<RegressResult> results(jobs.size());
  std::atomic<size_t> next{0};
  size_t done = 0;
  std::mutex mutex;
  std::condition_variable changed;
  const auto work = [&] {
    const machine::MachineProfile own = profile;  // each worker reads its own copy
    for (size_t i = next++; i < jobs.size(); i = next++) {
      RegressResult r = measure_program(jobs[i], common, own);
      const std::lock_guard<std::mutex> lock(mutex);
      results[i] = std::move(r);
      ++done;
      changed.notify_one();
    }
  };
  const unsigned n = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<size_t>(1, jobs.size()))));
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < n; ++t) workers.emplace_back(work);
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (done < jobs.size()) {
      changed.wait_for(lock, std::chrono::milliseconds(200));
      const size_t now_done = done;
      lock.unlock();
      if (progress) progress(now_done, jobs.size());
      lock.lock();
    }
  }
  for (auto& w : workers) w.join();
  if (progress) progress(jobs.size(), jobs.size());
  return results;
}

}  // namespace drycut::app
