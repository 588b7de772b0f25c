// `drycut regress PATH... --baseline FILE [--update] [--jobs N] [--junit FILE] [--tolerance ...]`:
// dry-runs every main program under the paths (in parallel across files) and compares time,
// time after M0, lowest feed, path length, feed dips, alarms and warnings with a committed
// baseline; exit 1 with a table of what changed, 0 when nothing did; `--update` rewrites the
// baseline instead. See docs/regress.md.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "app/output_file.hpp"
#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/program_discovery.hpp"
#include "app/regress_runner.hpp"
#include "report/junit_writer.hpp"
#include "report/progress_display.hpp"
#include "report/regress_comparison.hpp"

namespace drycut::app {
namespace {

namespace fs = std::filesystem;

struct RegressOptions {
  ProgramOptions program;  // everything but the program name is shared by all runs
  std::vector<std::string> paths;
  std::string baseline_file;
  bool update = false;
  unsigned jobs = 0;  // 0 = the core count
  std::string junit_file;
  std::string tolerance;
};

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read the baseline " + path + " (write one with --update)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The baseline key: the program's path relative to the baseline's folder, with '/'.
std::string baseline_key(const fs::path& program, const fs::path& baseline_dir) {
  std::error_code ec;
  const fs::path abs_program = fs::weakly_canonical(fs::absolute(program), ec);
  const fs::path rel = abs_program.lexically_relative(baseline_dir);
  return (rel.empty() ? abs_program : rel).generic_string();
}

std::vector<RegressJob> make_jobs(const RegressOptions& o) {
  std::error_code ec;
  const fs::path baseline_dir = fs::weakly_canonical(fs::absolute(o.baseline_file), ec).parent_path();
  std::vector<RegressJob> jobs;
  for (const auto& program : find_main_programs(o.paths)) jobs.push_back({program, baseline_key(program, baseline_dir)});
  std::sort(jobs.begin(), jobs.end(), [](const RegressJob& a, const RegressJob& b) { return a.key < b.key; });
  return jobs;
}

std::string junit_classname(const std::string& key) {
  std::string folder = fs::path(key).parent_path().generic_string();
  // Folders become dotted packages (Jenkins groups by them); a dot of a name would split one.
  for (char& c : folder) {
    if (c == '.') c = '_';
    else if (c == '/') c = '.';
  }
  return folder.empty() ? "drycut.regress" : "drycut.regress." + folder;
}

void write_junit(const std::string& path, const std::vector<RegressResult>& results,
                 const std::vector<report::RegressChange>& changes) {
  std::vector<report::JUnitCase> cases;
  for (const auto& r : results) {
    report::JUnitCase c{r.figures.program, junit_classname(r.figures.program), r.wall_s, {}};
    for (const auto& change : changes)
      if (change.program == r.figures.program) c.failures.push_back(change.message());
    cases.push_back(std::move(c));
  }
  // A change that belongs to no program of this run (one of the baseline that was not run, the
  // machine) fails as a case of its own.
  std::set<std::string> run;
  for (const auto& r : results) run.insert(r.figures.program);
  for (const auto& change : changes)
    if (!run.count(change.program)) cases.push_back({change.program, junit_classname(change.program), 0, {change.message()}});
  write_output_file(path, report::junit_xml("drycut regress", cases));
}

int run_regress(const RegressOptions& o) {
  const report::RegressTolerances tolerances = report::parse_tolerances(o.tolerance);
  const machine::MachineProfile profile = load_machine(o.program);
  const std::vector<RegressJob> jobs = make_jobs(o);
  // Read the baseline before the runs: a missing one fails at once, not after minutes of work.
  std::optional<report::Baseline> baseline;
  if (!o.update) baseline = report::parse_baseline(read_file(o.baseline_file));

  const unsigned threads = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  auto display = report::ProgressDisplay::for_stderr(o.program.quiet);
  const double start_s = report::ProgressDisplay::steady_seconds();
  const auto progress = [&display, start_s](size_t done, size_t total) {
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "  %.1f s", report::ProgressDisplay::steady_seconds() - start_s);
    display.show("  " + std::to_string(done) + " of " + std::to_string(total) + " programs" + elapsed);
  };
  const std::vector<RegressResult> results = run_in_parallel(jobs, o.program, profile, threads, progress);
  display.finish();

  report::Baseline now{profile.name, {}};
  for (const auto& r : results) now.programs.push_back(r.figures);
  if (o.update) {
    write_output_file(o.baseline_file, report::baseline_json(now));
    if (!o.junit_file.empty()) write_junit(o.junit_file, results, {});
    std::printf("regress: baseline %s written, %zu programs\n", o.baseline_file.c_str(), results.size());
    return kExitOk;
  }
  std::vector<report::RegressChange> changes = report::compare_with_baseline(*baseline, now.programs, tolerances);
  if (baseline->machine != now.machine)
    changes.insert(changes.begin(), {"(all)", "machine", baseline->machine, now.machine, "another machine profile"});
  if (!o.junit_file.empty()) write_junit(o.junit_file, results, changes);
  size_t changed_programs = 0;
  for (size_t i = 0; i < changes.size(); ++i)
    if (i == 0 || changes[i].program != changes[i - 1].program) ++changed_programs;
  if (!changes.empty()) std::fputs(report::change_table(changes).c_str(), stdout);
  std::printf("regress: %zu programs, %zu changed (%s)\n", results.size(), changed_programs,
              changes.empty() ? "as the baseline" : "run with --update to accept");
  return changes.empty() ? kExitOk : kExitAlarm;
}

}  // namespace

void register_regress(CLI::App& app) {
  auto o = std::make_shared<RegressOptions>();
  CLI::App* cmd = app.add_subcommand(
      "regress", "Dry-run every main program under the paths and compare with a baseline (CI regression)");
  cmd->add_option("PATHS", o->paths, "Folders, main programs or quoted globs ('programs/**/*.MPF')")->required();
  cmd->add_option("--baseline", o->baseline_file, "Baseline JSON (docs/regress.md); written by --update")->required();
  cmd->add_flag("--update", o->update, "Write the baseline from this run instead of comparing");
  cmd->add_option("--jobs,-j", o->jobs, "Programs run at the same time (default: the core count)");
  cmd->add_option("--junit", o->junit_file, "Write a JUnit XML report (one test case per program)");
  cmd->add_option("--tolerance", o->tolerance,
                  "Allowed differences, e.g. time=2%,feed=5%,length=0.1%,dips=0 (these are the defaults)");
  add_run_options(*cmd, o->program);  // --search-path, --machine, --tools ... as for one program
  cmd->callback([o] {
    try {
      throw ExitRequest{run_regress(*o)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut regress: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
