// The tool table file of `--tools` (CSV and JSON) and the tool-change machine data.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "machine/machine_profile.hpp"
#include "machine/tool_table_file.hpp"

namespace drycut::machine {
namespace {

// The error a CSV table gives, or "no error".
std::string csv_error(const std::string& text) {
  try {
    load_tool_table_csv(text, "t.csv");
  } catch (const ProfileError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

TEST(ToolTableCsv, OneRowPerEdgeMergedByNumber) {
  const auto tools = load_tool_table_csv(
      "# job 42\nnumber,name,d,length_mm,radius_mm\n1,FR_4,1,75.5,2\n\n1,FR_4,2,80,2.5\n7,,1,120,\n", "t.csv");
  ASSERT_EQ(tools.size(), 2u);
  EXPECT_EQ(tools[0].name, "FR_4");
  ASSERT_EQ(tools[0].edges.size(), 2u);
  EXPECT_DOUBLE_EQ(tools[0].edges[0].length_mm, 75.5);
  EXPECT_DOUBLE_EQ(tools[0].edges[1].radius_mm, 2.5);
  EXPECT_EQ(tools[1].name, "7");  // no name: the number
  EXPECT_EQ(tools[1].number, 7);
  EXPECT_DOUBLE_EQ(tools[1].edges[0].length_mm, 120.0);
  EXPECT_DOUBLE_EQ(tools[1].edges[0].radius_mm, 0.0);
}

TEST(ToolTableCsv, ARowMustHaveTheHeadersFields) {
  // A missing value is an empty field, not a short row: "1,FR,1,10" under five columns lost its
  // radius and read 0; an extra field is refused too. Empty fields still take the defaults.
  EXPECT_EQ(csv_error("number,name,d,length_mm,radius_mm\n1,FR,1,10\n"), "t.csv:2: 4 fields, the header has 5");
  EXPECT_EQ(csv_error("number,name,d,length_mm,radius_mm\n1,FR,1,10,2,3\n"), "t.csv:2: 6 fields, the header has 5");
  EXPECT_EQ(csv_error("number,name,d,length_mm,radius_mm\n1,FR,1,10,\n"), "no error");
}

TEST(ToolTableCsv, AByteOrderMarkBeforeTheHeaderIsSkipped) {
  // Excel's "CSV UTF-8" writes one; the first column was read as "\ufeffnumber".
  const auto tools = load_tool_table_csv("\xEF\xBB\xBFnumber,d,radius_mm\n3,1,4\n", "t.csv");
  ASSERT_EQ(tools.size(), 1u);
  EXPECT_EQ(tools[0].number, 3);
  EXPECT_DOUBLE_EQ(tools[0].edges[0].radius_mm, 4.0);
}

TEST(ToolTableCsv, TeethColumnIsOptional) {
  // teeth: the number of teeth $TC_DPNT for G95 FZ; empty or absent = 0 (not known).
  const auto tools = load_tool_table_csv("number,d,radius_mm,teeth\n1,1,5,4\n1,2,5,\n", "t.csv");
  ASSERT_EQ(tools.size(), 1u);
  ASSERT_EQ(tools[0].edges.size(), 2u);
  EXPECT_EQ(tools[0].edges[0].teeth, 4);
  EXPECT_EQ(tools[0].edges[1].teeth, 0);
  EXPECT_THROW(load_tool_table_csv("number,d,teeth\n1,1,2.5\n", "t.csv"), ProfileError);
  // JSON: the profile's edge key, written back by the profile writer when known.
  const auto json_tools = load_tools_json(R"([{"name":"FR","number":1,"edges":[{"d":1,"teeth":3}]}])", "t.json");
  EXPECT_EQ(json_tools[0].edges[0].teeth, 3);
}

TEST(ToolTableCsv, LengthsThreeBaseAndEdgePosition) {
  // Length 3 ($TC_DP5), base lengths ($TC_DP21..23), cutting edge position ($TC_DP2).
  const auto tools = load_tool_table_csv(
      "number,d,type,length3_mm,base_length1_mm,base_length2_mm,base_length3_mm,cutting_edge_position\n"
      "1,1,500,4.5,1,2,3,3\n", "t.csv");
  const ToolEdge& e = tools.at(0).edges.at(0);
  EXPECT_DOUBLE_EQ(e.length3_mm, 4.5);
  EXPECT_DOUBLE_EQ(e.base_mm[0], 1.0);
  EXPECT_DOUBLE_EQ(e.base_mm[2], 3.0);
  EXPECT_EQ(e.edge_position, 3);
  EXPECT_THROW(load_tool_table_csv("number,d,cutting_edge_position\n1,1,10\n", "t.csv"), ProfileError);
  // JSON: the profile's edge keys.
  const auto json_tools = load_tools_json(
      R"([{"name":"T","number":1,"edges":[{"d":1,"length3_mm":2,"base_length2_mm":7,"cutting_edge_position":8}]}])", "t.json");
  EXPECT_DOUBLE_EQ(json_tools[0].edges[0].length3_mm, 2.0);
  EXPECT_DOUBLE_EQ(json_tools[0].edges[0].base_mm[1], 7.0);
  EXPECT_EQ(json_tools[0].edges[0].edge_position, 8);
}

TEST(ToolTableCsv, ColumnsMayComeInAnyOrder) {
  const auto tools = load_tool_table_csv("d,radius_mm,number\n2,3,5\n", "t.csv");
  ASSERT_EQ(tools.size(), 1u);
  EXPECT_EQ(tools[0].number, 5);
  EXPECT_EQ(tools[0].edges[0].d, 2);
  EXPECT_DOUBLE_EQ(tools[0].edges[0].radius_mm, 3.0);
}

TEST(ToolTableCsv, SisterToolsShareANameWithTheirDuploNumbers) {
  // A name under two numbers is a pair of sister tools ($TC_TP1): duplo from the column, else the
  // next free one; a name's duplo twice is an error, as is a tool's duplo changing between rows.
  const auto tools = load_tool_table_csv(
      "number,name,d,length_mm,radius_mm,duplo\n4,FR_D10,1,80,5,\n14,FR_D10,1,81,5,\n24,FR_D10,1,79,5,7\n24,FR_D10,2,79,5,7\n",
      "t.csv");
  ASSERT_EQ(tools.size(), 3u);
  EXPECT_EQ(tools[0].duplo, 1);
  EXPECT_EQ(tools[1].duplo, 2);
  EXPECT_EQ(tools[2].duplo, 7);
  EXPECT_EQ(tools[2].edges.size(), 2u);
  EXPECT_EQ(find_sister_tool(tools, "FR_D10")->number, 4);
  EXPECT_EQ(find_sister_tool(tools, "FR_D10", 7)->number, 24);
  EXPECT_EQ(find_sister_tool(tools, "FR_D10", 3), nullptr);
  EXPECT_NE(csv_error("number,name,d,duplo\n1,A,1,1\n2,A,1,1\n").find("t.csv:3: tool name 'A' duplo 1 used by two numbers"),
            std::string::npos);
  EXPECT_NE(csv_error("number,name,d,duplo\n1,A,1,1\n1,A,2,2\n").find("has duplo 1 before"), std::string::npos);
}

TEST(ToolTableCsv, BadInputNamesFileAndLine) {
  EXPECT_NE(csv_error("number,d,colour\n").find("t.csv:1: unknown column 'colour'"), std::string::npos);
  EXPECT_NE(csv_error("number,name\n").find("needs columns number and d"), std::string::npos);
  EXPECT_NE(csv_error("number,d\n1,x\n").find("t.csv:2 d"), std::string::npos);
  EXPECT_NE(csv_error("number,d\n1,1.5\n").find("whole number"), std::string::npos);
  EXPECT_NE(csv_error("number,d\n1,1\n1,1\n").find("edge D1 twice"), std::string::npos);
  EXPECT_NE(csv_error("number,d,radius_mm\n1,1,-2\n").find("must be >= 0"), std::string::npos);
  EXPECT_NE(csv_error("").find("no header"), std::string::npos);
}

TEST(ToolTableJson, ArrayOrObjectLikeTheProfile) {
  const std::string array = R"([{"name": "A", "number": 3, "edges": [{"d": 1, "length_mm": 40, "radius_mm": 5}]}])";
  const auto a = load_tools_json(array, "t.json");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_DOUBLE_EQ(a[0].edges[0].length_mm, 40.0);
  const auto b = load_tools_json("{\"tools\": " + array + "}", "t.json");
  EXPECT_EQ(b[0].number, 3);
  EXPECT_THROW(load_tools_json("{\"tool\": []}", "t.json"), ProfileError);
}

TEST(ToolChangeData, ReadValidatedAndWrittenBack) {
  const MachineProfile& d = default_profile();
  EXPECT_EQ(d.tool_change_mode, 1);
  EXPECT_EQ(d.tool_change_m_code, 6);
  EXPECT_EQ(d.cutting_edge_default, 1);
  EXPECT_FALSE(d.tool_table_complete);
  auto j = nlohmann::json::parse(profile_to_json(d));
  j["program"]["tool_change_mode"] = 0;
  j["program"]["cutting_edge_default"] = -2;
  j["program"]["tool_table_complete"] = true;
  const MachineProfile p = load_profile_json(j.dump(), "t");
  EXPECT_EQ(p.tool_change_mode, 0);
  EXPECT_EQ(p.cutting_edge_default, -2);
  EXPECT_TRUE(p.tool_table_complete);
  j["program"]["tool_change_mode"] = 2;
  EXPECT_THROW(load_profile_json(j.dump(), "t"), ProfileError);
}

}  // namespace
}  // namespace drycut::machine
