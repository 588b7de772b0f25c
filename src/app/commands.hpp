#pragma once
// The subcommands of the drycut command line. Each returns the process exit code:
// 0 = ran clean, 1 = the program raised alarms, 2 = usage or I/O error.
#include <CLI/CLI.hpp>

namespace drycut::app {

// Each registers its subcommand (options and callback) on the application.
void register_check(CLI::App& app);
void register_path(CLI::App& app);
void register_generate(CLI::App& app);
void register_run(CLI::App& app);
void register_deviation(CLI::App& app);
void register_sweep(CLI::App& app);
void register_language(CLI::App& app);
void register_report(CLI::App& app);
void register_compare(CLI::App& app);
void register_experiment(CLI::App& app);
void register_calibrate(CLI::App& app);
void register_regress(CLI::App& app);
void register_profile(CLI::App& app);

}  // namespace drycut::app
