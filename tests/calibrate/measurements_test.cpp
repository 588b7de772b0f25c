// The MEASUREMENTS.json reader: paths relative to the file, defaults, errors naming the key.
#include "calibrate/measurements.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace drycut::calibrate {
namespace {

struct TempDir {
  std::filesystem::path path = std::filesystem::temp_directory_path() / ("drycut-meas-" + std::to_string(::getpid()));
  TempDir() {
    std::filesystem::create_directories(path / "progs");
    std::ofstream(path / "progs" / "A.MPF") << "G1 X1 F100\nM30\n";
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& text) const {
    const auto f = path / "m.json";
    std::ofstream(f) << text;
    return f.string();
  }
};

TEST(Measurements, ReadsRunsRelativeToTheFile) {
  TempDir d;
  const auto m = load_measurements(d.write(R"({"span": "after_m0..end", "runs": [
      {"program": "progs/A.MPF", "time": 12.5, "min_feed": 300, "knots": 5},
      {"program": "progs/A.MPF", "time": 3, "span": "start..contour_end"}]})"));
  ASSERT_EQ(m.runs.size(), 2u);
  EXPECT_EQ(m.runs[0].program, (d.path / "progs" / "A.MPF").string());
  EXPECT_EQ(m.runs[0].time_s, 12.5);
  EXPECT_EQ(m.runs[0].min_feed_mm_min, 300.0);
  EXPECT_EQ(report::span_name(m.runs[0].span), "after_m0..end");
  EXPECT_EQ(report::span_name(m.runs[1].span), "start..contour_end");
  EXPECT_FALSE(m.runs[1].min_feed_mm_min);
  EXPECT_FALSE(m.feed_window);
}

TEST(Measurements, ErrorsNameTheRunAndKey) {
  TempDir d;
  auto message = [&](const std::string& text) {
    try {
      load_measurements(d.write(text));
    } catch (const MeasurementsError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"({"runs": []})").find("non-empty array"), std::string::npos);
  EXPECT_NE(message(R"({"runs": [{"program": "progs/A.MPF", "time": -1}]})").find("runs[0].time"), std::string::npos);
  EXPECT_NE(message(R"({"runs": [{"program": "nope.MPF", "time": 1}]})").find("program not found"), std::string::npos);
  EXPECT_NE(message(R"({"span": "x..y", "runs": [{"program": "progs/A.MPF", "time": 1}]})").find("span"),
            std::string::npos);
}

}  // namespace
}  // namespace drycut::calibrate
