#include "parser/run_clock.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::parser {
namespace {

constexpr double kClockStartS = 8 * 3600.0;  // 08:00:00

std::optional<double> clock_field(std::string_view n, double elapsed_s) {
  const double t = kClockStartS + elapsed_s;
  const double day = std::floor(t / 86400.0);
  const double in_day = t - day * 86400.0;
  if (n == "$A_HOUR") return std::floor(in_day / 3600.0);
  if (n == "$A_MINUTE") return std::floor(std::fmod(in_day, 3600.0) / 60.0);
  if (n == "$A_SECOND") return std::floor(std::fmod(in_day, 60.0));
  if (n == "$A_MSECOND") return std::floor(std::fmod(in_day * 1000.0, 1000.0));
  // Days beyond the first stay in January (a dry run of more than 30 days is not a use case).
  if (n == "$A_DAY") return 1.0 + std::min(day, 30.0);
  if (n == "$A_MONTH") return 1.0;
  if (n == "$A_YEAR") return 2024.0;
  return std::nullopt;
}

}  // namespace

std::optional<double> run_clock_reading(std::string_view n, double elapsed_s) {
  if (n.size() < 4 || n[1] != 'A') return std::nullopt;  // $A_..., $AC_..., $AN_...
  if (n == "$AC_OPERATING_TIME" || n == "$AC_CYCLE_TIME") return elapsed_s;
  if (n == "$AN_SETUP_TIME" || n == "$AN_POWERON_TIME") return elapsed_s / 60.0;
  return clock_field(n, elapsed_s);
}

}  // namespace drycut::parser
