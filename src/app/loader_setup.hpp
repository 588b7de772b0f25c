#pragma once
// The loader's options as every command sets them up: search path (then drycut's standard
// cycles), step limit, definition files, and the machine's data and axis names from the profile, so that `check`, `run` and the
// other commands read the same language against the same machine.
#include <cstdint>
#include <string>
#include <vector>

#include "machine/machine_profile.hpp"
#include "parser/program_loader.hpp"

namespace drycut::app {

parser::LoaderOptions make_loader_options(const std::vector<std::string>& search_path, uint64_t max_steps,
                                          const std::vector<std::string>& definition_dirs,
                                          bool missing_programs_warn, bool standard_cycles,
                                          const machine::MachineProfile& profile);

}  // namespace drycut::app
