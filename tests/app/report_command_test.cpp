// `drycut report`: a self-contained HTML page; block text shown literally; deviation against a
// reference; exit codes; no progress output when stderr is not a terminal.
#include <gtest/gtest.h>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;

TEST(ReportCommand, EscapesBlockTextAndIsSelfContained) {
  TempDir dir("drycut_report_cli_escape");
  write_file(dir.path / "EVIL.MPF",
             "N10 G0 X0 Y0\nN20 G1 X10 Y0 F1000\nN30 G1 X10 Y10\n"
             "N40 G1 QQ=5 ; <script>alert(\"x\")</script> & co\nN50 M30\n");
  const fs::path html = dir.path / "out.html";
  const fs::path err = dir.path / "stderr.txt";
  const CliRun r = run_drycut("report " + quoted(dir.path / "EVIL.MPF") + " -o " + quoted(html), err.string());
  EXPECT_EQ(r.exit_code, 1);  // the program raised an alarm; the report is still written
  const std::string page = read_file(html);
  ASSERT_FALSE(page.empty());
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_NE(page.find("N40 G1 QQ=5 ; &lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  for (const char* id : {"<svg id=\"top-view\"", "<svg id=\"velocity-time\"", "<svg id=\"velocity-length\""})
    EXPECT_NE(page.find(id), std::string::npos) << id;
  // stderr is a file here: the alarm, but no progress line (no carriage return).
  const std::string log = read_file(err);
  EXPECT_NE(log.find("12550"), std::string::npos) << log;
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
  EXPECT_EQ(run_drycut("report " + quoted(dir.path / "LONG.MPF") + " -o " + quoted(html)).exit_code, 0);
  const auto size = fs::file_size(html);
  EXPECT_GT(size, 10'000u);
  EXPECT_LT(size, 1'500'000u);
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
