#include "machine/machine_data_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace drycut::machine {
namespace {

std::string trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The line without its comment (a ';' outside a string).
std::string strip_comment(const std::string& line) {
  bool in_string = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') in_string = !in_string;
    if (line[i] == ';' && !in_string) return trim(std::string_view(line).substr(0, i));
  }
  return trim(line);
}

// "N32000 $MA_..." or "N32000$MA_..." (MD number as block number): the rest after the number.
std::string strip_md_number(const std::string& line) {
  if (line.size() < 2 || (line[0] != 'N' && line[0] != 'n') || !std::isdigit(static_cast<unsigned char>(line[1])))
    return line;
  size_t i = 1;
  while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
  return trim(std::string_view(line).substr(i));
}

std::optional<double> parse_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  const char* begin = s.data();
  if (*begin == '+') ++begin;
  double v = 0;
  auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// 'H3F' or 'B101': a bit pattern as the control writes masks.
std::optional<double> parse_based(const std::string& s) {
  if (s.size() < 4 || s.front() != '\'' || s.back() != '\'') return std::nullopt;
  const char base = static_cast<char>(std::toupper(static_cast<unsigned char>(s[1])));
  if (base != 'H' && base != 'B') return std::nullopt;
  const std::string digits = s.substr(2, s.size() - 3);
  unsigned long long v = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, base == 'H' ? 16 : 2);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return static_cast<double>(v);
}

// The value text after '=' (a trailing line checksum 'xxxx already removed).
std::optional<std::variant<double, std::string>> parse_value(const std::string& text) {
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') return text.substr(1, text.size() - 2);
  const std::string u = upper(text);
  if (u == "TRUE") return 1.0;
  if (u == "FALSE") return 0.0;
  if (auto v = parse_based(text)) return *v;
  if (auto v = parse_number(text)) return *v;
  return std::nullopt;
}

// Splits "value 'ABCD" into the value and drops the checksum (a blank, an apostrophe, 4 hex digits).
std::string drop_checksum(const std::string& text) {
  if (!text.empty() && text.front() == '"') {
    const size_t close = text.find('"', 1);
    return close == std::string::npos ? text : text.substr(0, close + 1);
  }
  const size_t blank = text.find_first_of(" \t");
  if (blank == std::string::npos) return text;
  const std::string rest = trim(std::string_view(text).substr(blank));
  if (rest.size() >= 2 && rest.front() == '\'') return trim(std::string_view(text).substr(0, blank));
  return text;  // something else follows: parse_value will refuse it
}

std::vector<std::string> split_index(const std::string& inside) {
  std::vector<std::string> out;
  std::stringstream ss(inside);
  std::string part;
  while (std::getline(ss, part, ',')) out.push_back(upper(trim(part)));
  return out;
}

// "$MA_MAX_AX_VELO[AX1]=30000": fills `d` and returns true, or false when the line is not one.
bool parse_assignment(const std::string& line, MachineDatum& d) {
  if (line.size() < 4 || line[0] != '$') return false;
  size_t i = 1;
  while (i < line.size() && std::isalpha(static_cast<unsigned char>(line[i]))) ++i;
  if (i == 1 || i >= line.size() || line[i] != '_') return false;
  d.area = upper(line.substr(1, i - 1));
  const size_t name_begin = ++i;
  while (i < line.size() && is_word_char(line[i])) ++i;
  if (i == name_begin) return false;
  d.name = upper(line.substr(name_begin, i - name_begin));
  d.index.clear();
  if (i < line.size() && line[i] == '[') {
    const size_t close = line.find(']', i);
    if (close == std::string::npos) return false;
    d.index = split_index(line.substr(i + 1, close - i - 1));
    i = close + 1;
  }
  while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
  if (i >= line.size() || line[i] != '=') return false;
  auto value = parse_value(drop_checksum(trim(std::string_view(line).substr(i + 1))));
  if (!value) return false;
  d.value = *value;
  return true;
}

// CHANDATA(n): the channel of the following channel data; returns n or 0.
int parse_chandata(const std::string& line) {
  const std::string u = upper(line);
  if (u.rfind("CHANDATA(", 0) != 0 || u.back() != ')') return 0;
  auto n = parse_number(u.substr(9, u.size() - 10));
  return n && *n >= 1 && *n <= 99 ? static_cast<int>(*n) : 0;
}

bool is_structure(const std::string& line) {
  if (line.empty() || line[0] == ';' || line[0] == '%') return true;
  const std::string u = upper(line);
  return u == "M17" || u == "M30" || u == "M02" || u == "M2";
}

}  // namespace

void parse_machine_data_text(const std::string& text, const std::string& file, MachineDataText& out) {
  std::istringstream in(text);
  std::string raw;
  int line_number = 0;
  int channel = 1;
  while (std::getline(in, raw)) {
    ++line_number;
    const std::string whole = trim(raw);
    if (is_structure(whole)) continue;
    const std::string line = strip_md_number(strip_comment(whole));
    if (line.empty()) continue;
    if (int n = parse_chandata(line)) {
      channel = n;
      continue;
    }
    MachineDatum d;
    if (parse_assignment(line, d)) {
      d.channel = channel;
      d.file = file;
      d.line = line_number;
      out.data.push_back(std::move(d));
    } else {
      out.not_understood.push_back(file + ":" + std::to_string(line_number) + ": " + whole.substr(0, 120));
    }
  }
}

void read_machine_data_file(const std::string& path, MachineDataText& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": machine data file cannot be opened");
  std::ostringstream text;
  text << in.rdbuf();
  parse_machine_data_text(text.str(), path, out);
}

}  // namespace drycut::machine
