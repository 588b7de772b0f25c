#include "parser/loader_machine.hpp"

#include "machine/machine_data_values.hpp"
#include "parser/ascii_case.hpp"
#include "parser/command_table.hpp"

namespace drycut::parser {

void add_machine(LoaderOptions& o, const machine::MachineProfile& profile) {
  for (const auto& [name, value] : machine::machine_data_values(profile)) o.machine_data[name] = value;
  for (const auto& [name, text] : machine::machine_data_texts(profile)) o.machine_data_texts[name] = text;
  for (const auto& axis : profile.axes) o.axis_names.push_back(axis.name);
  // The channel's further axes by the names the profile gives them (MD20080: MZ, MAG, ZR).
  for (const auto& axis : profile.extra_axes) o.axis_names.push_back(axis.name);
  // MD20150 GCODE_RESET_VALUES[group - 1]: the internal number, in its G group, of each code of
  // the profile's reset list (G1 is 2 in group 1). Groups drycut does not number stay unknown.
  for (const std::string& code : profile.reset_gcodes) {
    int group = 0, index = 0;
    if (g_group_of_name(upper_ascii(code), group, index))
      o.machine_data["$MC_GCODE_RESET_VALUES[" + std::to_string(group - 1) + "]"] = index;
  }
}

}  // namespace drycut::parser
