#pragma once
// Ctrl-C (SIGINT) or SIGTERM while a program runs: the first asks the run to stop before its
// next block, as an alarm stops it (990022): the figures cover the blocks before it, the reports
// written so far are finished and marked incomplete, the exit code is 1. The handler is reset by
// the first signal, so a second one ends the process at once, as without drycut's handler.
// Installed by the commands that run one program (run, path, report, check).
namespace drycut::app {

void install_interrupt_handlers();
bool interrupt_requested();

}  // namespace drycut::app
