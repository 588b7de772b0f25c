#include "machine/profile_object_reader.hpp"

#include <cmath>
#include <sstream>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

using nlohmann::json;

namespace {

// "mm_h", "us", "in_min" look like a unit; "speed_mm_s" (after "max") does not.
bool looks_like_unit(const std::string& suffix) {
  static const char* const kTokens[] = {"mm", "m", "um", "cm", "km", "in", "inch", "ft", "s", "ms", "us", "min", "h"};
  std::string first = suffix.substr(0, suffix.find('_'));
  for (const char* t : kTokens)
    if (first == t) return true;
  return false;
}

}  // namespace

ProfileObjectReader::ProfileObjectReader(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object())
    throw ProfileError((path_.empty() ? std::string("<root>") : path_) + ": must be an object");
}

std::string ProfileObjectReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ProfileObjectReader::fail(const std::string& key, const std::string& message) const {
  throw ProfileError(key_path(key) + ": " + message);
}

const json* ProfileObjectReader::find_with_unit(const std::string& name, Dimension dimension,
                                                std::string& key, double& factor) {
  quantities_.emplace_back(name, dimension);
  const json* found = nullptr;
  for (const auto& unit : units_of(dimension)) {
    std::string candidate = name + "_" + std::string(unit.suffix);
    auto it = object_.find(candidate);
    if (it == object_.end()) continue;
    if (found) fail(candidate, "given twice (also as " + key + ")");
    found = &*it;
    key = candidate;
    factor = unit.to_internal;
  }
  if (found) consumed_.insert(key);
  return found;
}

std::optional<double> ProfileObjectReader::quantity(const std::string& name, Dimension dimension) {
  std::string key;
  double factor = 1.0;
  const json* value = find_with_unit(name, dimension, key, factor);
  if (!value) return std::nullopt;
  if (!value->is_number()) fail(key, "must be a number");
  double v = value->get<double>();
  if (!std::isfinite(v)) fail(key, "must be finite");
  return v * factor;
}

std::optional<Eigen::Vector3d> ProfileObjectReader::vector3(const std::string& name,
                                                             Dimension dimension) {
  std::string key;
  double factor = 1.0;
  const json* value = find_with_unit(name, dimension, key, factor);
  if (!value) return std::nullopt;
  if (!value->is_array() || value->size() != 3) fail(key, "must be an array of 3 numbers [x, y, z]");
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    const json& c = (*value)[static_cast<size_t>(i)];
    if (!c.is_number()) fail(key, "must be an array of 3 numbers [x, y, z]");
    out[i] = c.get<double>() * factor;
  }
  return out;
}

std::optional<double> ProfileObjectReader::number(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  consumed_.insert(key);
  if (!it->is_number()) fail(key, "must be a number");
  double v = it->get<double>();
  if (!std::isfinite(v)) fail(key, "must be finite");
  return v;
}

std::optional<long long> ProfileObjectReader::integer(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  consumed_.insert(key);
  if (!it->is_number_integer()) fail(key, "must be an integer");
  return it->get<long long>();
}

std::optional<bool> ProfileObjectReader::boolean(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  consumed_.insert(key);
  if (!it->is_boolean()) fail(key, "must be true or false");
  return it->get<bool>();
}

std::optional<std::string> ProfileObjectReader::string(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  consumed_.insert(key);
  if (!it->is_string()) fail(key, "must be a string");
  return it->get<std::string>();
}

const json* ProfileObjectReader::child(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) return nullptr;
  consumed_.insert(key);
  return &*it;
}

void ProfileObjectReader::reject_unknown_keys() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    const std::string& key = it.key();
    if (consumed_.count(key)) continue;
    // The longest quantity name that prefixes the key decides: a known quantity in a unit
    // nobody accepts is a unit error, not an unknown key.
    const std::pair<std::string, Dimension>* best = nullptr;
    for (const auto& q : quantities_) {
      if (key.size() > q.first.size() + 1 && key.compare(0, q.first.size(), q.first) == 0 &&
          key[q.first.size()] == '_' && (!best || q.first.size() > best->first.size()))
        best = &q;
    }
    if (best && looks_like_unit(key.substr(best->first.size() + 1))) {
      fail(key, "unknown unit '" + key.substr(best->first.size() + 1) + "' for " + best->first +
                    " (allowed: " + std::string(unit_list(best->second)) + ")");
    }
    fail(key, "unknown key");
  }
}

double require_positive(double value, const std::string& what) {
  if (!(value > 0)) throw ProfileError(what + ": must be > 0");
  return value;
}

double require_non_negative(double value, const std::string& what) {
  if (!(value >= 0)) throw ProfileError(what + ": must be >= 0");
  return value;
}

double require_range(double value, double low, double high, const std::string& what) {
  if (!(value >= low && value <= high)) {
    std::ostringstream msg;
    msg << what << ": must be in [" << low << ", " << high << "]";
    throw ProfileError(msg.str());
  }
  return value;
}

}  // namespace drycut::machine
