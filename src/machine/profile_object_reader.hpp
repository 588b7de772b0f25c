#pragma once
// Reads one JSON object of a machine profile and remembers which keys it consumed, so that
// whatever is left over is reported as an unknown key (or a known quantity in an unknown
// unit). Every error names the full key path, e.g. `axes.X.max_accel_m_s2: must be > 0`.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "machine/profile_units.hpp"

namespace drycut::machine {

class ProfileObjectReader {
 public:
  // Throws ProfileError when `object` is not a JSON object.
  ProfileObjectReader(const nlohmann::json& object, std::string path);

  // A quantity with a unit suffix (`max_accel` + `_m_s2`), converted to internal units.
  std::optional<double> quantity(const std::string& name, Dimension dimension);
  // A 3-vector quantity (`start_position` + `_mm`): [x, y, z].
  std::optional<Eigen::Vector3d> vector3(const std::string& name, Dimension dimension);
  std::optional<double> number(const std::string& key);
  std::optional<long long> integer(const std::string& key);
  std::optional<bool> boolean(const std::string& key);
  std::optional<std::string> string(const std::string& key);
  // The raw value of a nested object or array (marks the key as consumed).
  const nlohmann::json* child(const std::string& key);
  // The key path of a key of this object ("axes.X.max_mm").
  std::string key_path(const std::string& key) const;
  // Throws for the first key nobody asked for.
  void reject_unknown_keys() const;
  // Throws ProfileError("<path>.<key>: <message>").
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  // Finds the key `name_<unit>`; nullptr when absent. Throws when given in two units.
  const nlohmann::json* find_with_unit(const std::string& name, Dimension dimension,
                                       std::string& key, double& factor);

  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> consumed_;
  // Quantities asked for, to tell "unknown unit" from "unknown key".
  std::vector<std::pair<std::string, Dimension>> quantities_;
};

// Value checks shared by the profile loader; `what` is the full key path.
double require_positive(double value, const std::string& what);
double require_non_negative(double value, const std::string& what);
double require_range(double value, double low, double high, const std::string& what);

}  // namespace drycut::machine
