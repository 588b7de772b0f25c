#pragma once
// Reads the header of a conformance program (tests/conformance/<topic>/NAME.mpf): the leading
// comment lines state the rule and what drycut must do with the program.
//   ; rule: <the rule in own words> (source: <manual, chapter>)   -- once, required
//   ; expect: ok  |  ; expect: alarm <number> line <n>               -- once, required
//   ; expect-warning: <number>                                       -- zero or more
//   ; expect-end: X10 Y20 Z5          -- machine position after the last motion (any of X Y Z)
//   ; expect-time: 12.5 tol 0.01      -- `run` total time in s, absolute tolerance
//   ; expect-listing: NAME.elements   -- expected `drycut path --elements` output beside it
//   ; expect-tool-centre: NAME.elements -- expected `drycut path --tool-centre --elements` output
//   ; profile: NAME.json              -- machine profile beside it (default: the embedded one)
// The header is the run of lines before the first program line: comments, blank lines and a
// leading `%_N_..` file line. Other comment lines in it (the hand computation) are free text,
// and a rule may go on over the following comment lines up to the next directive; the rule
// must name its source. Anything that looks like a directive but is not one of these
// (a misspelt key, a capitalised key, a bad value, a repeated single directive, a directive
// below the first program line) is an error, so that no expectation is silently ignored.
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace drycut::testing {

struct ConformanceSpec {
  std::string rule;
  bool expect_alarm = false;  // false: `; expect: ok`
  int alarm_number = 0;
  int alarm_line = 0;
  std::vector<int> warnings;
  std::array<std::optional<double>, 3> end_mm;  // X, Y, Z; only the given axes are checked
  bool has_end = false;
  std::optional<double> time_s;
  double time_tolerance_s = 0;
  std::string listing;  // file name beside the program, empty = none
  std::string tool_centre_listing;  // the same for the tool-centre path (G41/G42 applied)
  std::string profile;  // machine profile file beside the program, empty = the embedded one
};

namespace conformance_detail {

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

inline std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  for (char c : s) {
    if (c == ' ' || c == '\t') {
      if (!w.empty()) out.push_back(w), w.clear();
    } else {
      w += c;
    }
  }
  if (!w.empty()) out.push_back(w);
  return out;
}

// A whole word as a finite decimal number (no trailing characters).
inline bool to_double(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

inline bool to_int(const std::string& s, int& v) {
  if (s.empty() || s.size() > 9) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  v = std::stoi(s);
  return true;
}

// The key of a comment that is shaped like a directive ("word:" at the start), or "".
inline std::string directive_key(const std::string& body) {
  size_t i = 0;
  while (i < body.size() && (std::isalpha(static_cast<unsigned char>(body[i])) || body[i] == '-')) ++i;
  if (i == 0 || i >= body.size() || body[i] != ':') return "";
  return body.substr(0, i);
}

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A key drycut's harness owns: `rule` or anything starting with `expect`, in any case.
inline bool looks_like_directive(const std::string& key) {
  const std::string k = lower(key);
  return k == "rule" || k == "profile" || k.rfind("expect", 0) == 0;
}

inline bool parse_expect(const std::string& value, ConformanceSpec& spec, std::string& error) {
  const auto w = words(value);
  if (w.size() == 1 && w[0] == "ok") return true;
  if (w.size() == 4 && w[0] == "alarm" && w[2] == "line" && to_int(w[1], spec.alarm_number) &&
      to_int(w[3], spec.alarm_line) && spec.alarm_number > 0 && spec.alarm_line > 0) {
    spec.expect_alarm = true;
    return true;
  }
  error = "expect: must be 'ok' or 'alarm <number> line <n>', not '" + value + "'";
  return false;
}

inline bool parse_end(const std::string& value, ConformanceSpec& spec, std::string& error) {
  const auto w = words(value);
  for (const auto& word : w) {
    const char axis = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
    const int i = axis == 'X' ? 0 : axis == 'Y' ? 1 : axis == 'Z' ? 2 : -1;
    double v = 0;
    if (i < 0 || spec.end_mm[i] || !to_double(word.substr(1), v)) {
      error = "expect-end: each of X, Y, Z at most once with a number, not '" + value + "'";
      return false;
    }
    spec.end_mm[i] = v;
  }
  if (w.empty()) {
    error = "expect-end: needs at least one axis value";
    return false;
  }
  spec.has_end = true;
  return true;
}

inline bool parse_time(const std::string& value, ConformanceSpec& spec, std::string& error) {
  const auto w = words(value);
  double t = 0, tol = 0;
  if (w.size() != 3 || w[1] != "tol" || !to_double(w[0], t) || !to_double(w[2], tol) || t < 0 || tol <= 0) {
    error = "expect-time: must be '<seconds> tol <positive tolerance>', not '" + value + "'";
    return false;
  }
  spec.time_s = t;
  spec.time_tolerance_s = tol;
  return true;
}

// One directive; `seen` guards the single ones against repetition.
inline bool apply_directive(const std::string& key, const std::string& value, ConformanceSpec& spec,
                            std::vector<std::string>& seen, std::string& error) {
  const bool single = key != "expect-warning";
  for (const auto& s : seen)
    if (single && s == key) {
      error = key + ": given twice";
      return false;
    }
  seen.push_back(key);
  if (key == "rule") {
    spec.rule = value;
    if (value.empty()) error = "rule: is empty";
    return !value.empty();
  }
  if (key == "expect") return parse_expect(value, spec, error);
  if (key == "expect-warning") {
    int n = 0;
    if (words(value).size() != 1 || !to_int(value, n) || n <= 0) {
      error = "expect-warning: must be one warning number, not '" + value + "'";
      return false;
    }
    spec.warnings.push_back(n);
    return true;
  }
  if (key == "expect-end") return parse_end(value, spec, error);
  if (key == "expect-time") return parse_time(value, spec, error);
  if (key == "expect-listing" || key == "expect-tool-centre") {
    if (value.empty() || words(value).size() != 1 || value.find('/') != std::string::npos) {
      error = key + ": must be one file name beside the program, not '" + value + "'";
      return false;
    }
    (key == "expect-listing" ? spec.listing : spec.tool_centre_listing) = value;
    return true;
  }
  if (key == "profile") {
    if (value.empty() || words(value).size() != 1 || value.find('/') != std::string::npos) {
      error = "profile: must be one file name beside the program, not '" + value + "'";
      return false;
    }
    spec.profile = value;
    return true;
  }
  error = "unknown directive '" + key + ":' (known: rule, expect, expect-warning, expect-end, expect-time, "
          "expect-listing, expect-tool-centre, profile)";
  return false;
}

}  // namespace conformance_detail

// Reads the whole program text; returns false with `error` ("line N: ...") on a malformed or
// incomplete header.
inline bool read_conformance_header(std::istream& in, ConformanceSpec& spec, std::string& error) {
  using namespace conformance_detail;
  spec = ConformanceSpec{};
  std::vector<std::string> seen;
  std::string raw;
  int line_no = 0;
  bool in_header = true;
  bool in_rule = false;  // comment lines after `rule:` continue it up to the next directive
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = trim(raw);
    const std::string where = "line " + std::to_string(line_no) + ": ";
    if (line.empty()) continue;
    if (line[0] != ';') {
      if (!(line_no == 1 && line[0] == '%')) in_header = false;
      in_rule = false;
      continue;
    }
    const std::string body = trim(line.substr(1));
    const std::string key = directive_key(body);
    if (key.empty() || !looks_like_directive(key)) {
      if (in_header && in_rule && !body.empty()) spec.rule += " " + body;
      in_rule = in_rule && !body.empty();
      continue;
    }
    if (!in_header) {
      error = where + "'" + key + ":' below the first program line: directives belong in the header";
      return false;
    }
    if (key != lower(key)) {
      error = where + "directive keys are lower case: '" + key + ":'";
      return false;
    }
    if (!apply_directive(key, trim(body.substr(key.size() + 1)), spec, seen, error)) {
      error = where + error;
      return false;
    }
    in_rule = key == "rule";
  }
  const auto given = [&](const char* k) {
    for (const auto& s : seen)
      if (s == k) return true;
    return false;
  };
  if (!given("rule")) error = "no '; rule:' line in the header: every conformance program states its rule";
  else if (!given("expect")) error = "no '; expect:' line in the header: every conformance program states its outcome";
  else if (spec.rule.find("source:") == std::string::npos)
    error = "the rule does not name its source: '; rule: ... (source: <manual, chapter>)'";
  return error.empty();
}

}  // namespace drycut::testing
