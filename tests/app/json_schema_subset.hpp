#pragma once
// A validator for the subset of JSON Schema (draft 2020-12) that docs/schemas/*.schema.json use,
// so that tests can check drycut's JSON outputs against the published schemas without a new
// dependency. Keywords: type, properties, required, additionalProperties (false or a schema),
// items, prefixItems, minItems, maxItems, enum, const, minimum, oneOf, allOf, $ref ("#/..." or
// "FILE#/..." for another schema in the same folder), $defs; $schema, $id, title and
// description are annotations. Any other keyword is reported as an error, so a schema can never
// rely on a rule this validator silently skips.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace drycut::testing {

class JsonSchemaSubset {
 public:
  // `folder` holds the schema files; `file` is the one to validate against.
  JsonSchemaSubset(std::filesystem::path folder, const std::string& file) : folder_(std::move(folder)), root_(file) {}

  // The errors of `value` (empty when it is valid), each "at /path: what".
  std::vector<std::string> validate(const nlohmann::json& value) {
    errors_.clear();
    check(value, schema_file(root_), root_, "");
    return errors_;
  }

 private:
  using json = nlohmann::json;

  const json& schema_file(const std::string& name) {
    auto it = files_.find(name);
    if (it == files_.end()) {
      std::ifstream in(folder_ / name);
      json j = in ? json::parse(in) : json();
      it = files_.emplace(name, std::move(j)).first;
    }
    return it->second;
  }

  void error(const std::string& where, const std::string& what) { errors_.push_back("at " + (where.empty() ? "/" : where) + ": " + what); }

  static bool has_type(const json& v, const std::string& type) {
    if (type == "object") return v.is_object();
    if (type == "array") return v.is_array();
    if (type == "string") return v.is_string();
    if (type == "boolean") return v.is_boolean();
    if (type == "null") return v.is_null();
    if (type == "number") return v.is_number();
    if (type == "integer") return v.is_number_integer() || (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
    return false;
  }

  // Errors of one subschema, without adding them (for oneOf).
  size_t error_count(const json& v, const json& schema, const std::string& file, const std::string& where) {
    std::vector<std::string> saved;
    saved.swap(errors_);
    check(v, schema, file, where);
    const size_t n = errors_.size();
    errors_.swap(saved);
    return n;
  }

  void check_ref(const json& v, const std::string& ref, const std::string& file, const std::string& where) {
    const auto hash = ref.find('#');
    const std::string target_file = hash == 0 ? file : ref.substr(0, hash);
    const json& doc = schema_file(target_file);
    const std::string pointer = hash == std::string::npos ? "" : ref.substr(hash + 1);
    if (doc.is_null() || !doc.contains(json::json_pointer(pointer))) {
      error(where, "unresolved $ref " + ref);
      return;
    }
    check(v, doc.at(json::json_pointer(pointer)), target_file, where);
  }

  void check_object(const json& v, const json& s, const std::string& file, const std::string& where) {
    if (s.contains("required"))
      for (const auto& key : s["required"])
        if (!v.contains(key.get<std::string>())) error(where, "missing required \"" + key.get<std::string>() + "\"");
    const json props = s.value("properties", json::object());
    for (const auto& [key, item] : v.items()) {
      if (props.contains(key)) {
        check(item, props[key], file, where + "/" + key);
      } else if (s.contains("additionalProperties")) {
        const json& extra = s["additionalProperties"];
        if (extra.is_boolean() && !extra.get<bool>()) error(where, "unexpected property \"" + key + "\"");
        else if (extra.is_object()) check(item, extra, file, where + "/" + key);
      }
    }
  }

  void check_array(const json& v, const json& s, const std::string& file, const std::string& where) {
    if (s.contains("minItems") && v.size() < s["minItems"].get<size_t>()) error(where, "fewer items than minItems");
    if (s.contains("maxItems") && v.size() > s["maxItems"].get<size_t>()) error(where, "more items than maxItems");
    size_t first_free = 0;
    if (s.contains("prefixItems")) {
      const json& prefix = s["prefixItems"];
      for (size_t i = 0; i < prefix.size() && i < v.size(); ++i)
        check(v[i], prefix[i], file, where + "/" + std::to_string(i));
      first_free = prefix.size();
    }
    if (s.contains("items"))
      for (size_t i = first_free; i < v.size(); ++i) check(v[i], s["items"], file, where + "/" + std::to_string(i));
  }

  void check(const json& v, const json& s, const std::string& file, const std::string& where) {
    static const std::set<std::string> kKnown{
        "$schema", "$id",        "title",       "description", "$defs",    "type",     "properties", "required",
        "additionalProperties",  "items",       "prefixItems", "minItems", "maxItems", "enum",       "const",
        "minimum", "oneOf",      "allOf",       "$ref"};
    if (!s.is_object()) {
      error(where, "schema is not an object");
      return;
    }
    for (const auto& [key, _] : s.items())
      if (!kKnown.count(key)) error(where, "schema keyword \"" + key + "\" is not supported by this validator");
    if (s.contains("$ref")) check_ref(v, s["$ref"].get<std::string>(), file, where);
    if (s.contains("type")) {
      const json types = s["type"].is_array() ? s["type"] : json::array({s["type"]});
      bool any = false;
      for (const auto& t : types) any = any || has_type(v, t.get<std::string>());
      if (!any) {
        error(where, "expected type " + s["type"].dump() + ", got " + v.dump().substr(0, 60));
        return;
      }
    }
    if (s.contains("const") && v != s["const"]) error(where, "expected " + s["const"].dump());
    if (s.contains("enum") && std::find(s["enum"].begin(), s["enum"].end(), v) == s["enum"].end())
      error(where, v.dump() + " is not one of " + s["enum"].dump());
    if (s.contains("minimum") && v.is_number() && v.get<double>() < s["minimum"].get<double>())
      error(where, v.dump() + " is below the minimum " + s["minimum"].dump());
    if (v.is_object()) check_object(v, s, file, where);
    if (v.is_array()) check_array(v, s, file, where);
    if (s.contains("allOf"))
      for (const auto& sub : s["allOf"]) check(v, sub, file, where);
    if (s.contains("oneOf")) {
      size_t matching = 0;
      for (const auto& sub : s["oneOf"]) matching += error_count(v, sub, file, where) == 0 ? 1 : 0;
      if (matching != 1) error(where, "matches " + std::to_string(matching) + " of the oneOf schemas, not exactly one");
    }
  }

  std::filesystem::path folder_;
  std::string root_;
  std::map<std::string, json> files_;
  std::vector<std::string> errors_;
};

}  // namespace drycut::testing
