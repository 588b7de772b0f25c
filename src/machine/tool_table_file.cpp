#include "machine/tool_table_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace drycut::machine {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double number_cell(const std::string& text, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || !end || *end != '\0' || !std::isfinite(v)) throw ProfileError(where + ": '" + text + "' is not a number");
  return v;
}

int integer_cell(const std::string& text, int low, int high, const std::string& where) {
  const double v = number_cell(text, where);
  if (v != std::floor(v) || v < low || v > high)
    throw ProfileError(where + ": must be a whole number " + std::to_string(low) + ".." + std::to_string(high));
  return static_cast<int>(v);
}

}  // namespace

std::vector<Tool> load_tool_table_csv(const std::string& text, const std::string& origin) {
  static const std::vector<std::string> kColumns{"number",          "name",           "d",
                                                 "length_mm",       "radius_mm",      "teeth",
                                                 "type",            "length2_mm",     "length3_mm",
                                                 "base_length1_mm", "base_length2_mm", "base_length3_mm",
                                                 "cutting_edge_position", "duplo"};
  std::istringstream in(text);
  std::string line;
  std::map<std::string, size_t> column;
  size_t header_fields = 0;
  std::vector<Tool> tools;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const std::string where = origin + ":" + std::to_string(line_no);
    // Excel's "CSV UTF-8" starts the file with a byte order mark.
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    const auto cells = split(line);
    // A row with fewer or more fields than the header has lost or gained a value: taking the rest
    // as empty read a missing radius as 0, silently.
    if (!column.empty() && cells.size() != header_fields)
      throw ProfileError(where + ": " + std::to_string(cells.size()) + " fields, the header has " +
                         std::to_string(header_fields));
    if (column.empty()) {
      header_fields = cells.size();
      for (size_t i = 0; i < cells.size(); ++i) {
        if (std::find(kColumns.begin(), kColumns.end(), cells[i]) == kColumns.end())
          throw ProfileError(where + ": unknown column '" + cells[i] +
                             "' (columns: number,name,d,length_mm,radius_mm,teeth,type,length2_mm,length3_mm,"
                             "base_length1_mm,base_length2_mm,base_length3_mm,cutting_edge_position,duplo)");
        column[cells[i]] = i;
      }
      if (!column.count("number") || !column.count("d")) throw ProfileError(where + ": the header needs columns number and d");
      continue;
    }
    auto cell = [&](const std::string& name) -> std::string {
      auto it = column.find(name);
      return it != column.end() && it->second < cells.size() ? cells[it->second] : "";
    };
    const int number = integer_cell(cell("number"), 0, 32000, where + " number");
    ToolEdge edge;
    edge.d = integer_cell(cell("d"), 1, 32000, where + " d");
    if (!cell("length_mm").empty()) edge.length_mm = number_cell(cell("length_mm"), where + " length_mm");
    if (!cell("radius_mm").empty()) edge.radius_mm = number_cell(cell("radius_mm"), where + " radius_mm");
    if (edge.radius_mm < 0) throw ProfileError(where + " radius_mm: must be >= 0");
    if (!cell("teeth").empty()) edge.teeth = integer_cell(cell("teeth"), 0, 32000, where + " teeth");
    if (!cell("type").empty()) edge.type = integer_cell(cell("type"), 0, 999, where + " type");
    if (!cell("length2_mm").empty()) edge.length2_mm = number_cell(cell("length2_mm"), where + " length2_mm");
    if (!cell("length3_mm").empty()) edge.length3_mm = number_cell(cell("length3_mm"), where + " length3_mm");
    for (size_t i = 0; i < 3; ++i) {
      const std::string base = "base_length" + std::to_string(i + 1) + "_mm";
      if (!cell(base).empty()) edge.base_mm[i] = number_cell(cell(base), where + " " + base);
    }
    if (!cell("cutting_edge_position").empty())
      edge.edge_position = integer_cell(cell("cutting_edge_position"), 0, 9, where + " cutting_edge_position");
    const std::string name = cell("name").empty() ? std::to_string(number) : cell("name");
    auto it = std::find_if(tools.begin(), tools.end(), [&](const Tool& t) { return t.number == number; });
    if (it == tools.end()) {
      // A name under another number is a sister tool: its duplo number from the column, else the
      // next free one ($TC_TP1).
      int duplo = 1;
      for (const Tool& t : tools)
        if (t.name == name) duplo = std::max(duplo, t.duplo + 1);
      if (!cell("duplo").empty()) duplo = integer_cell(cell("duplo"), 1, 32000, where + " duplo");
      if (std::any_of(tools.begin(), tools.end(), [&](const Tool& t) { return t.name == name && t.duplo == duplo; }))
        throw ProfileError(where + ": tool name '" + name + "' duplo " + std::to_string(duplo) + " used by two numbers");
      tools.push_back({name, number, {}, duplo});
      it = tools.end() - 1;
    } else if (it->name != name) {
      throw ProfileError(where + ": tool " + std::to_string(number) + " named '" + it->name + "' before");
    } else if (!cell("duplo").empty() && integer_cell(cell("duplo"), 1, 32000, where + " duplo") != it->duplo) {
      throw ProfileError(where + ": tool " + std::to_string(number) + " has duplo " + std::to_string(it->duplo) + " before");
    }
    for (const auto& e : it->edges)
      if (e.d == edge.d) throw ProfileError(where + ": tool " + std::to_string(number) + " edge D" + std::to_string(edge.d) + " twice");
    it->edges.push_back(edge);
  }
  if (column.empty()) throw ProfileError(origin + ": no header row");
  return tools;
}

std::vector<Tool> load_tool_table_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ProfileError(path + ": tool table file cannot be opened");
  std::ostringstream text;
  text << in.rdbuf();
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".csv") return load_tool_table_csv(text.str(), path);
  if (ext == ".json") return load_tools_json(text.str(), path);
  throw ProfileError(path + ": tool table must be a .csv or .json file");
}

}  // namespace drycut::machine
