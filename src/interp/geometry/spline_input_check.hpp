#pragma once
// Validation of spline block values; failures are AlarmError 12160 (value outside range)
// without a source location, which the interpreter adds.
#include <string>

#include "interp/geometry/curve.hpp"
#include "machine/alarm.hpp"

namespace drycut::geometry {

[[noreturn]] inline void throw_spline_value_alarm(const std::string& detail) {
  throw AlarmError(make_alarm(12160, detail, SourceLocation{}, std::string()));
}

inline void check_spline_point(const Vec3& p) {
  if (!p.allFinite()) throw_spline_value_alarm("spline point with a non-finite coordinate");
}

}  // namespace drycut::geometry
