// The JSON outputs match their published schemas (docs/schemas/*.schema.json): `run --json` (to
// a file and streamed to stdout), every line of `run --ndjson`, `check --json` and the
// `regress` baseline, for a clean program with a subprogram and a warning and for one stopped by
// an alarm. The file table holds each file once and the rows point into it; the rows' lengths
// add up to the summary's path length (hand-computed: G0 from the start Z100 down to Z5 = 95,
// plunge 5, X100 in the subprogram, Y50 back in the main program: 250 mm). The validator itself
// is checked to reject broken documents and unsupported schema keywords.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "json_schema_subset.hpp"
#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using drycut::testing::JsonSchemaSubset;
using nlohmann::json;

const fs::path kSchemas = fs::path(DRYCUT_SOURCE_DIR) / "docs" / "schemas";

constexpr const char* kMain =
    "G90 G17 G54 G64\n"
    "G0 X0 Y0 Z5\n"
    "G1 Z0 F1000\n"
    "CUT3DC\n"
    "SUBP\n"
    "G1 Y50\n"
    "M30\n";
constexpr const char* kSub = "G1 X100\nM17\n";
// The circle from (10,10) about (5,10) cannot end at (0,0), 11.18 mm from its centre: alarm 14040.
constexpr const char* kStops = "G0 X0 Y0 Z5\nG1 X10 F600\nG1 Y10\nG2 X0 Y0 I-5 J0\nM30\n";

std::string errors_text(const std::vector<std::string>& errors) {
  std::string t;
  for (const auto& e : errors) t += e + "\n";
  return t;
}

class JsonSchemas : public ::testing::Test {
 protected:
  JsonSchemas() : dir_("drycut_json_schema") {
    write_file(dir_.path / "MAIN.MPF", kMain);
    write_file(dir_.path / "SUBP.SPF", kSub);
    write_file(dir_.path / "STOPS.MPF", kStops);
  }
  fs::path program(const char* name) const { return dir_.path / name; }
  TempDir dir_;
};

TEST_F(JsonSchemas, RunDocumentHasAFileTableAndMatchesTheSchema) {
  const fs::path out = dir_.path / "run.json";
  ASSERT_EQ(run_drycut("run -q " + quoted(program("MAIN.MPF")) + " --json " + quoted(out)).exit_code, 0);
  const json j = json::parse(read_file(out));
  JsonSchemaSubset schema(kSchemas, "run.schema.json");
  EXPECT_TRUE(schema.validate(j).empty()) << errors_text(schema.validate(j));

  const auto& files = j["files"];
  ASSERT_EQ(files.size(), 2u) << files.dump();
  EXPECT_EQ(fs::path(files[0].get<std::string>()).filename(), "MAIN.MPF");
  EXPECT_EQ(fs::path(files[1].get<std::string>()).filename(), "SUBP.SPF");
  double length = 0;
  bool sub_row = false;
  for (const auto& row : j["blocks"]) {
    ASSERT_LT(row[0].get<size_t>(), files.size());
    length += row[4].get<double>();
    // The subprogram's G1 X100 is its line 1, 100 mm long.
    if (row[0] == 1 && row[1] == 1) sub_row = std::abs(row[4].get<double>() - 100.0) < 1e-6;
  }
  EXPECT_TRUE(sub_row);
  EXPECT_NEAR(length, 250.0, 1e-5);
  EXPECT_NEAR(j["summary"]["path_length_mm"].get<double>(), 250.0, 1e-9);
  ASSERT_EQ(j["warnings"].size(), 1u);  // CUT3DC (3-D circumferential milling) is not modelled
  EXPECT_EQ(j["warnings"][0]["number"], 990002);
}

TEST_F(JsonSchemas, RunStreamedToStdoutIsTheSameDocument) {
  const fs::path file = dir_.path / "file.json", err = dir_.path / "stderr.txt";
  ASSERT_EQ(run_drycut("run -q " + quoted(program("MAIN.MPF")) + " --json " + quoted(file)).exit_code, 0);
  const CliRun streamed = run_drycut("run -q " + quoted(program("MAIN.MPF")) + " --json -", err.string());
  ASSERT_EQ(streamed.exit_code, 0);
  EXPECT_EQ(json::parse(streamed.out), json::parse(read_file(file)));
  // The text summary went to stderr, out of the way of the JSON.
  EXPECT_NE(read_file(err).find("path length"), std::string::npos);
  // Two streams cannot share stdout.
  EXPECT_EQ(run_drycut("run -q " + quoted(program("MAIN.MPF")) + " --json - --trace -").exit_code, 2);
}

TEST_F(JsonSchemas, EveryNdjsonLineMatchesTheSchema) {
  for (const char* name : {"MAIN.MPF", "STOPS.MPF"}) {
    const CliRun r = run_drycut("run -q " + quoted(program(name)) + " --ndjson -");
    EXPECT_EQ(r.exit_code, std::string(name) == "MAIN.MPF" ? 0 : 1);
    JsonSchemaSubset schema(kSchemas, "run-ndjson.schema.json");
    std::istringstream lines(r.out);
    std::string line, first_type, last_type;
    size_t files = 0, blocks = 0, alarms = 0;
    while (std::getline(lines, line)) {
      const json j = json::parse(line);
      EXPECT_TRUE(schema.validate(j).empty()) << line << "\n" << errors_text(schema.validate(j));
      const std::string type = j.value("type", "");
      if (first_type.empty()) first_type = type;
      last_type = type;
      if (type == "file") {
        EXPECT_EQ(j["id"], files++);
      }
      if (type == "block") {
        EXPECT_LT(j["file"].get<size_t>(), files) << "a block before its file line";
        ++blocks;
      }
      if (type == "alarm") ++alarms;
    }
    EXPECT_EQ(first_type, "run");
    EXPECT_EQ(last_type, "summary");
    EXPECT_GT(blocks, 0u);
    EXPECT_EQ(alarms, std::string(name) == "MAIN.MPF" ? 0u : 1u);
  }
}

// A compressor span's row carries two more columns (compressed blocks, deviation), in both
// layouts: ten collinear 1 mm blocks under COMPCAD are one span of 10 blocks, deviation 0.
TEST_F(JsonSchemas, CompressedSpanRowsCarryBlocksAndDeviation) {
  std::string text = "G0 X0 Y0 Z0\nG64 COMPCAD F3000\n";
  for (int i = 1; i <= 10; ++i) text += "G1 X" + std::to_string(i) + "\n";
  write_file(dir_.path / "COMP.MPF", text + "M30\n");
  const fs::path out = dir_.path / "comp.json";
  ASSERT_EQ(run_drycut("run -q " + quoted(program("COMP.MPF")) + " --json " + quoted(out)).exit_code, 0);
  const json j = json::parse(read_file(out));
  JsonSchemaSubset schema(kSchemas, "run.schema.json");
  EXPECT_TRUE(schema.validate(j).empty()) << errors_text(schema.validate(j));
  int spans = 0;
  for (const auto& row : j["blocks"]) {
    if (row[2] != "COMPCAD") {
      EXPECT_EQ(row.size(), 9u) << row.dump();
      continue;
    }
    ++spans;
    ASSERT_EQ(row.size(), 11u) << row.dump();
    EXPECT_EQ(row[9], 10);
    EXPECT_NEAR(row[10].get<double>(), 0.0, 1e-9);
    EXPECT_NEAR(row[4].get<double>(), 10.0, 1e-6);
  }
  EXPECT_EQ(spans, 1);
  const CliRun r = run_drycut("run -q " + quoted(program("COMP.MPF")) + " --ndjson -");
  JsonSchemaSubset lines_schema(kSchemas, "run-ndjson.schema.json");
  std::istringstream lines(r.out);
  std::string line;
  int compressed_lines = 0;
  while (std::getline(lines, line)) {
    const json l = json::parse(line);
    EXPECT_TRUE(lines_schema.validate(l).empty()) << line;
    if (!l.contains("compressed_blocks")) continue;
    ++compressed_lines;
    EXPECT_EQ(l["compressed_blocks"], 10);
  }
  EXPECT_EQ(compressed_lines, 1);
}

TEST_F(JsonSchemas, CheckOutputMatchesTheSchema) {
  JsonSchemaSubset schema(kSchemas, "check.schema.json");
  for (const char* name : {"MAIN.MPF", "STOPS.MPF"}) {
    const CliRun r = run_drycut("check " + quoted(program(name)) + " --json");
    const json j = json::parse(r.out);
    EXPECT_TRUE(schema.validate(j).empty()) << name << "\n" << errors_text(schema.validate(j));
  }
}

TEST_F(JsonSchemas, DeviationOutputMatchesTheSchema) {
  // A circle r = 10 cut with G42 (tool judged) and without (not judged); the point (0, 10.5)
  // holds Y and its line passes over the circle: no crossing, counted.
  write_file(dir_.path / "CUT.MPF",
             "T=\"FR_4\"\nM6\nG1 X15 Y0 Z0 F1000\nG42 G1 X10 Y0\nG3 X10 Y0 I-10 J0\nG40 G1 X15 Y0\nM30\n");
  write_file(dir_.path / "LINE.MPF", "G1 X10 Y0 Z0 F1000\nG3 X10 Y0 I-10 J0\nM30\n");
  write_file(dir_.path / "cp.csv", "0,10.5\n-6,8\n0,10,x\n");
  JsonSchemaSubset schema(kSchemas, "deviation.schema.json");
  for (const char* name : {"CUT.MPF", "LINE.MPF"}) {
    const fs::path out = dir_.path / "d.json";
    const CliRun r = run_drycut("deviation " + quoted(program(name)) + " --polar 10 --control-points " +
                                quoted(dir_.path / "cp.csv") + " --json " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.out;
    std::ifstream in(out);
    const json j = json::parse(in);
    EXPECT_TRUE(schema.validate(j).empty()) << name << "\n" << errors_text(schema.validate(j));
    EXPECT_EQ(j["control_point_summary"]["programmed"]["without_crossing"].get<int>(), 1) << name;
  }
}

TEST_F(JsonSchemas, DeviationProgrammedPointsMatchesTheSchema) {
  // A square of G1 blocks rounded by nothing: the path is the polyline (0 both ways).
  write_file(dir_.path / "SQ.MPF", "G0 X0 Y0 Z5\nG1 Z0 F1000\nX10\nY10\nX0\nY0\nG0 Z5\nM30\n");
  JsonSchemaSubset schema(kSchemas, "deviation-points.schema.json");
  const fs::path out = dir_.path / "p.json";
  const CliRun r = run_drycut("deviation " + quoted(program("SQ.MPF")) + " --programmed-points --json " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::ifstream in(out);
  const json j = json::parse(in);
  EXPECT_TRUE(schema.validate(j).empty()) << errors_text(schema.validate(j));
  EXPECT_EQ(j["programmed_points"].get<int>(), 6);  // (0,0,5) and the five feed end points
  EXPECT_EQ(j["polylines"].get<int>(), 1);
  EXPECT_LT(j["path_to_polyline"]["max_mm"].get<double>(), 1e-9);
  EXPECT_LT(j["points_to_path"]["max_mm"].get<double>(), 1e-9);
}

TEST_F(JsonSchemas, RegressBaselineMatchesTheSchema) {
  const fs::path baseline = dir_.path / "baseline.json";
  ASSERT_EQ(run_drycut("regress -q " + quoted(dir_.path) + " --baseline " + quoted(baseline) + " --update").exit_code, 0);
  const json j = json::parse(read_file(baseline));
  JsonSchemaSubset schema(kSchemas, "regress-baseline.schema.json");
  EXPECT_TRUE(schema.validate(j).empty()) << errors_text(schema.validate(j));
  EXPECT_EQ(j["programs"].size(), 2u);  // MAIN.MPF and STOPS.MPF; SUBP.SPF is only called
}

TEST_F(JsonSchemas, TheValidatorRejectsBrokenDocuments) {
  const fs::path out = dir_.path / "run.json";
  ASSERT_EQ(run_drycut("run -q " + quoted(program("MAIN.MPF")) + " --json " + quoted(out)).exit_code, 0);
  const json good = json::parse(read_file(out));
  JsonSchemaSubset schema(kSchemas, "run.schema.json");
  ASSERT_TRUE(schema.validate(good).empty());

  json missing = good;
  missing.erase("summary");
  EXPECT_FALSE(schema.validate(missing).empty());
  json bad_limit = good;
  bad_limit["blocks"][0][7] = "bogus";
  EXPECT_FALSE(schema.validate(bad_limit).empty());
  json short_row = good;
  short_row["blocks"][0].erase(8);
  EXPECT_FALSE(schema.validate(short_row).empty());
  json extra = good;
  extra["summary"]["surprise"] = 1;
  EXPECT_FALSE(schema.validate(extra).empty());
  json wrong_type = good;
  wrong_type["summary"]["time_s"] = "9 s";
  EXPECT_FALSE(schema.validate(wrong_type).empty());

  write_file(dir_.path / "odd.schema.json", R"({"type": "object", "patternProperties": {}})");
  JsonSchemaSubset odd(dir_.path, "odd.schema.json");
  EXPECT_FALSE(odd.validate(json::object()).empty()) << "an unsupported keyword must not pass silently";
}

}  // namespace
