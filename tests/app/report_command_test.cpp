// `drycut report`: a self-contained HTML page; block text shown literally; deviation against a
// reference; the 3D view with three.js inlined, or a note when three.js is missing; exit codes;
// no progress output when stderr is not a terminal.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "report/viewer_library.hpp"
#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;

// Where drycut reads three.js, for the child processes of one test (DRYCUT_THREE_JS_DIR).
struct ThreeJsDir {
  explicit ThreeJsDir(const fs::path& dir) { ::setenv("DRYCUT_THREE_JS_DIR", dir.c_str(), 1); }
  ~ThreeJsDir() { ::unsetenv("DRYCUT_THREE_JS_DIR"); }
};

// A stand-in for Debian's libjs-three: every file the viewer inlines, each one line of script.
fs::path fake_three_js(const fs::path& dir) {
  for (const char* f : drycut::report::kViewerLibraryFiles) {
    fs::create_directories((dir / f).parent_path());
    write_file(dir / f, std::string("/* fake ") + f + " */ var fake_lib;\n");
  }
  return dir;
}

// The JSON in <script type="application/json" id="trace-data">.
nlohmann::json trace_data(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"trace-data\">";
  const size_t a = page.find(open);
  if (a == std::string::npos) return nullptr;
  const size_t b = page.find("</script>", a);
  return nlohmann::json::parse(page.substr(a + open.size(), b - a - open.size()));
}

TEST(ReportCommand, EscapesBlockTextAndIsSelfContained) {
  TempDir dir("drycut_report_cli_escape");
  write_file(dir.path / "EVIL.MPF",
             "N10 G0 X0 Y0\nN20 G1 X10 Y0 F1000\nN30 G1 X10 Y10\n"
             "N40 G1 QQ=5 ; <script>alert(\"x\")</script> & co\nN50 M30\n");
  const fs::path html = dir.path / "out.html";
  const fs::path err = dir.path / "stderr.txt";
  const ThreeJsDir no_three(dir.path / "no-three-js-here");  // without three.js: no script at all
  const CliRun r = run_drycut("report " + quoted(dir.path / "EVIL.MPF") + " -o " + quoted(html), err.string());
  EXPECT_EQ(r.exit_code, 1);  // the program raised an alarm; the report is still written
  const std::string page = read_file(html);
  ASSERT_FALSE(page.empty());
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_NE(page.find("id=\"trace-viewer-missing\""), std::string::npos);  // the note says why
  EXPECT_NE(page.find("N40 G1 QQ=5 ; &lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  for (const char* id : {"<svg id=\"top-view\"", "<svg id=\"velocity-time\"", "<svg id=\"velocity-length\""})
    EXPECT_NE(page.find(id), std::string::npos) << id;
  // stderr is a file here: the alarm, but no progress line (no carriage return).
  const std::string log = read_file(err);
  EXPECT_NE(log.find("12550"), std::string::npos) << log;
  EXPECT_NE(log.find("no 3D view in the page"), std::string::npos) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos);
}

TEST(ReportCommand, DeviationFromAReferenceCircle) {
  TempDir dir("drycut_report_cli_deviation");
  // A full circle of radius 10 about the origin.
  write_file(dir.path / "CIRCLE.MPF", "N10 G0 X10 Y0\nN20 G2 X10 Y0 I-10 J0 F1200\nN30 M30\n");
  const fs::path same = dir.path / "same.html", wider = dir.path / "wider.html";
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "CIRCLE.MPF") + " -o " + quoted(same) + " --polar 10").exit_code, 0);
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "CIRCLE.MPF") + " -o " + quoted(wider) + " --polar 10.5").exit_code, 0);
  const std::string a = read_file(same), b = read_file(wider);
  EXPECT_NE(a.find("<svg id=\"deviation\""), std::string::npos);
  // The circle lies on r = 10 (polyline sag ~1e-6 mm) and 0.5 mm inside r = 10.5.
  EXPECT_NE(a.find("0.0000 mm"), std::string::npos);
  EXPECT_NE(b.find("0.5000 mm"), std::string::npos);
  // Without a curve option there is no reference and no deviation plot.
  const fs::path none = dir.path / "none.html";
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "CIRCLE.MPF") + " -o " + quoted(none)).exit_code, 0);
  EXPECT_EQ(read_file(none).find("id=\"deviation\""), std::string::npos);
}

TEST(ReportCommand, FileStaysSmallForLongPrograms) {
  TempDir dir("drycut_report_cli_long");
  // 20000 short blocks on a zigzag (X up to 400 mm, inside the travel limits): the page must not grow with the block count.
  std::string text = "N1 G0 X0 Y0\nG1 F3000\n";
  for (int i = 1; i <= 20000; ++i) text += "X" + std::to_string(i * 0.02) + " Y" + std::to_string(i % 2) + "\n";
  text += "M30\n";
  write_file(dir.path / "LONG.MPF", text);
  const fs::path html = dir.path / "long.html";
  const ThreeJsDir three(fake_three_js(dir.path / "three"));  // the page without three.js's 850 kB
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "LONG.MPF") + " -o " + quoted(html)).exit_code, 0);
  const auto size = fs::file_size(html);
  EXPECT_GT(size, 10'000u);
  EXPECT_LT(size, 1'000'000u);
  // The 3D trace is decimated as the plots are: at most 2 × 4000 + 2 points of 7 numbers.
  const auto data = trace_data(read_file(html));
  ASSERT_TRUE(data.is_object());
  EXPECT_LE(data["p"].size(), 7u * 8002u);
  EXPECT_GT(data["samples"].get<uint64_t>(), 8002u);  // so there was something to decimate
}

TEST(ReportCommand, ThreeDViewInlinesThreeJsAndTheTrace) {
  TempDir dir("drycut_report_cli_3d");
  // A rapid down to Z5, a 10 x 10 square at F600 with a block text that must stay text.
  write_file(dir.path / "SQ.MPF",
             "N10 G0 X0 Y0 Z5\nN20 G1 X10 F600\nN30 Y10 ; </script><b>\nN40 X0\nN50 Y0\nN60 M30\n");
  const fs::path html = dir.path / "sq.html";
  const ThreeJsDir three(fake_three_js(dir.path / "three"));
  ASSERT_EQ(run_drycut("report " + quoted(dir.path / "SQ.MPF") + " -o " + quoted(html)).exit_code, 0);
  const std::string page = read_file(html);
  EXPECT_NE(page.find("<canvas id=\"trace-canvas\""), std::string::npos);
  for (const char* f : drycut::report::kViewerLibraryFiles)
    EXPECT_NE(page.find(std::string("/* fake ") + f + " */"), std::string::npos) << f;
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  const auto data = trace_data(page);
  ASSERT_TRUE(data.is_object());
  const auto& p = data["p"];
  ASSERT_EQ(p.size() % 7, 0u);
  ASSERT_GE(p.size(), 14u);
  // The trace ends where N50 ends (X0 Y0 Z5; the last IPO sample may fall up to one cycle short
  // of the stop, well under 0.05 mm while braking); time rises; the rapid is flagged 1 and first.
  const size_t last = p.size() - 7;
  EXPECT_NEAR(p[last].get<double>(), 0.0, 0.05);
  EXPECT_NEAR(p[last + 1].get<double>(), 0.0, 0.05);
  EXPECT_NEAR(p[last + 2].get<double>(), 5.0, 1e-3);
  EXPECT_EQ(p[6], 1);
  EXPECT_EQ(p[last + 6], 0);
  for (size_t i = 7; i < p.size(); i += 7) EXPECT_GE(p[i + 3].get<double>(), p[i - 4].get<double>());
  // Every block of the square is named with its file, line and text; F600 for the cuts.
  bool saw_n30 = false;
  for (const auto& b : data["blocks"]) {
    EXPECT_EQ(data["files"][b[0].get<size_t>()], "SQ.MPF");
    if (b[1] == 3) {
      saw_n30 = true;
      EXPECT_EQ(b[2], "N30 Y10 ; </script><b>");
      EXPECT_EQ(b[3], 600);
    }
  }
  EXPECT_TRUE(saw_n30);
}

TEST(ReportCommand, UsageErrorsExitTwo) {
  TempDir dir("drycut_report_cli_usage");
  write_file(dir.path / "A.MPF", "G1 X1 F100\nM30\n");
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "A.MPF")).exit_code, 2);  // no -o
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "A.MPF") + " -o /nonexistent/dir/x.html").exit_code, 2);
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "MISSING.MPF") + " -o " + quoted(dir.path / "x.html")).exit_code, 2);
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "A.MPF") + " -o " + quoted(dir.path / "x.html") + " --polar 'COS('")
                .exit_code,
            2);
}

}  // namespace
