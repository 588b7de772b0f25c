#pragma once
// Exit codes shared by every subcommand. Nothing else is ever returned.

namespace drycut::app {

inline constexpr int kExitOk = 0;      // ran clean (warnings allowed)
inline constexpr int kExitAlarm = 1;   // the program raised alarms
inline constexpr int kExitUsage = 2;   // usage or I/O error

// Subcommand callbacks throw this to end the process with a code (CLI11 callbacks return void).
struct ExitRequest {
  int code;
};

}  // namespace drycut::app
