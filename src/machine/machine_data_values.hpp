#pragma once
// Machine data as a program reads it: every profile field that models a SINUMERIK machine or
// setting datum, under that datum's `$` name, plus the profile's own `machine_data` map (which
// wins). Axis data are given for the machine axis (X1, Y1, Z1) and the geometry axis (X, Y, Z).
#include <map>
#include <string>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

std::map<std::string, double, std::less<>> machine_data_values(const MachineProfile& profile);

}  // namespace drycut::machine
