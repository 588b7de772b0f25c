#pragma once
// What the loader takes from the machine profile: its machine and setting data under their `$`
// names (for $MN_/$MA_/... reads) and its axis names (bare axis names in expressions).
#include "machine/machine_profile.hpp"
#include "parser/program_loader.hpp"

namespace drycut::parser {

void add_machine(LoaderOptions& options, const machine::MachineProfile& profile);

}  // namespace drycut::parser
