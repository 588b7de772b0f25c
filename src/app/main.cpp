// drycut: a software SINUMERIK 840D controller for dry-running part programs.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <string>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "drycut_version.hpp"

int main(int argc, char** argv) {
  // The name is fixed so help texts (and the man page made from them) never show a build path.
  CLI::App app{"drycut: dry-run SINUMERIK 840D part programs before cutting metal", "drycut"};
  app.require_subcommand(1);
  // Version and the git description of the tree it was built from ("unknown" without git).
  app.set_version_flag("--version", std::string("drycut ") + kDrycutVersion + " (" + kDrycutGitDescription + ")");
  int verbosity = 0;
  app.add_flag("-v,--verbose", verbosity, "More log output (-v info, -vv debug)");
  app.parse_complete_callback([&] {
    spdlog::set_level(verbosity >= 2 ? spdlog::level::debug
                      : verbosity == 1 ? spdlog::level::info
                                       : spdlog::level::warn);
  });

  drycut::app::register_check(app);
  drycut::app::register_path(app);
  drycut::app::register_run(app);
  drycut::app::register_report(app);
  drycut::app::register_compare(app);
  drycut::app::register_experiment(app);
  drycut::app::register_calibrate(app);
  drycut::app::register_regress(app);
  drycut::app::register_generate(app);
  drycut::app::register_deviation(app);
  drycut::app::register_sweep(app);
  drycut::app::register_language(app);
  drycut::app::register_profile(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 exits 0 for --help/--version and 1..n for errors; usage errors must be 2.
    int rc = app.exit(e);
    return rc == 0 ? 0 : drycut::app::kExitUsage;
  } catch (const drycut::app::ExitRequest& r) {
    return r.code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drycut: internal error: %s\n", e.what());
    return drycut::app::kExitUsage;
  }
  return drycut::app::kExitOk;
}
