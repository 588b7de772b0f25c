#pragma once
// The machine-profile fields `drycut calibrate` can fit: each a planner datum with its
// SINUMERIK machine-data name, its unit as written on the command line and in reports, and the
// bounds a fit keeps it in (physically usual ranges, docs/calibrate.md). Only fields the motion
// planner reads are listed: the interpreter and the tool radius compensation do not see them, so a
// program's tool-centre element stream can be recorded once and re-planned for every trial value.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine_profile.hpp"

namespace drycut::calibrate {

struct ProfileField {
  std::string name;         // command-line name: "jerk", "path_jerk", ...
  std::string machine_data;  // "MD32431 MAX_AX_JERK"
  std::string unit;         // unit of the value as reported ("m/s3", "ms", "")
  double lower = 0;         // bounds in that unit (lower > 0: fits run in log space)
  double upper = 0;
  // Value in the reported unit; setting writes every axis X, Y, Z where the datum is per axis.
  double (*get)(const machine::MachineProfile&) = nullptr;
  void (*set)(machine::MachineProfile&, double) = nullptr;
};

// Every fittable field, in a fixed order.
const std::vector<ProfileField>& profile_fields();
// The field of that name, or none.
const ProfileField* find_profile_field(std::string_view name);
// "jerk, transition_jerk, ..." for messages.
std::string profile_field_names();

}  // namespace drycut::calibrate
