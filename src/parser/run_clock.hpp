#pragma once
// The run clock a program reads: run-time counters ($AC_OPERATING_TIME, $AC_CYCLE_TIME,
// $AN_SETUP_TIME, $AN_POWERON_TIME in min) and the control's clock
// ($A_YEAR ... $A_MSECOND) (Job Planning, list of system variables). The dry-run control has run
// nothing but the program, so the counters start at 0 with it; the clock is deterministic, so a
// run does not depend on when it is made: it reads 08:00:00 on Monday 1 January 2024 at the
// program start. Both run with the interpreter's time (ControllerStateView::poll_clock).
#include <optional>
#include <string_view>

namespace drycut::parser {

// The value of clock variable `upper_name` `elapsed_s` into the program; nullopt for any other name.
std::optional<double> run_clock_reading(std::string_view upper_name, double elapsed_s);

}  // namespace drycut::parser
