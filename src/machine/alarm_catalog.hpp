#pragma once
// The alarm catalogue: every alarm number drycut raises, in one place, with its text and where
// the number comes from (the catalogue says which source gives each number).
#include <span>

#include "machine/alarm.hpp"

namespace drycut {

enum class AlarmSource {
  Siemens,      // number and meaning stated by a Siemens source
  ThirdParty,   // number used by a third-party SINUMERIK interpreter
  Memory,       // number from memory, not confirmed by a public source
  Drycut,       // no SINUMERIK number known: drycut's own number (range 990000+)
};

struct AlarmInfo {
  int number;
  Severity severity;
  const char* text;
  AlarmSource source;
};

// The whole catalogue, sorted by number.
std::span<const AlarmInfo> alarm_catalog();
// nullptr when the number is not catalogued.
const AlarmInfo* find_alarm(int number);

}  // namespace drycut
