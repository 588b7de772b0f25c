#include "parser/loader_machine.hpp"

#include "machine/machine_data_values.hpp"

namespace drycut::parser {

void add_machine(LoaderOptions& o, const machine::MachineProfile& profile) {
  for (const auto& [name, value] : machine::machine_data_values(profile)) o.machine_data[name] = value;
  for (const auto& [name, text] : machine::machine_data_texts(profile)) o.machine_data_texts[name] = text;
  for (const auto& axis : profile.axes) o.axis_names.push_back(axis.name);
}

}  // namespace drycut::parser
