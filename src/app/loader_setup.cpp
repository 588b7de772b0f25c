#include "app/loader_setup.hpp"

#include "app/standard_cycles.hpp"
#include "parser/loader_machine.hpp"

namespace drycut::app {

parser::LoaderOptions make_loader_options(const std::vector<std::string>& search_path, uint64_t max_steps,
                                          const std::vector<std::string>& definition_dirs,
                                          bool missing_programs_warn, bool standard_cycles,
                                          const machine::MachineProfile& profile) {
  parser::LoaderOptions o;
  o.search_path = search_path_with_cycles(search_path, standard_cycles);
  // drycut's own definitions (the cycles' plain-text parameter names, CYCLE_MACROS.DEF) come
  // first, so the user's definition files can redefine every name.
  if (standard_cycles) {
    if (const auto folder = standard_cycles_folder()) o.definition_dirs.push_back(*folder);
    o.standard_definition_dirs = o.definition_dirs.size();
  }
  for (const auto& dir : definition_dirs) o.definition_dirs.emplace_back(dir);
  o.max_steps = max_steps;
  o.missing_programs_warn = missing_programs_warn;
  parser::add_machine(o, profile);
  return o;
}

}  // namespace drycut::app
