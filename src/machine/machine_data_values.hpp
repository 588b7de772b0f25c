#pragma once
// Machine data as a program reads it: every profile field that models a SINUMERIK machine or
// setting datum, under that datum's `$` name, plus the profile's own `machine_data` map (which
// wins). Axis data are given for the machine axis (X1, Y1, Z1) and the geometry axis (X, Y, Z).
#include <map>
#include <string>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

std::map<std::string, double, std::less<>> machine_data_values(const MachineProfile& profile);

// The axis configuration as machine data of type STRING (machine-builder macros read the names
// to find an axis): MD20060 $MC_AXCONF_GEOAX_NAME_TAB (the geometry axes), MD20080
// $MC_AXCONF_CHANAX_NAME_TAB (geometry axes, then the further channel axes in profile order)
// and MD10000 $MN_AXCONF_MACHAX_NAME_TAB (the machine axes: channel axis name + "1", as the
// defaults X1, Y1, Z1 ...). Indices from 0, as the control's arrays.
std::map<std::string, std::string, std::less<>> machine_data_texts(const MachineProfile& profile);

}  // namespace drycut::machine
