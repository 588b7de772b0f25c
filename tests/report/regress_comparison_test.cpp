// Tolerance parsing and the comparison of `drycut regress` figures with a baseline, the baseline
// file round trip, and the JUnit XML. Values are chosen by hand around the tolerance edges.
#include <gtest/gtest.h>

#include "machine/alarm.hpp"
#include "report/junit_writer.hpp"
#include "report/regress_baseline.hpp"
#include "report/regress_comparison.hpp"

namespace drycut::report {
namespace {

TEST(RegressTolerance, DefaultsAndOverrides) {
  const RegressTolerances d = parse_tolerances("");
  EXPECT_DOUBLE_EQ(d.time.relative, 0.02);
  EXPECT_DOUBLE_EQ(d.feed.relative, 0.05);
  EXPECT_DOUBLE_EQ(d.length.relative, 0.001);
  EXPECT_DOUBLE_EQ(d.dips.absolute, 0.0);

  const RegressTolerances t = parse_tolerances("time=0.5%,feed=12.5,dips=2");
  EXPECT_DOUBLE_EQ(t.time.relative, 0.005);
  EXPECT_DOUBLE_EQ(t.time.absolute, 0.0);
  EXPECT_DOUBLE_EQ(t.feed.relative, 0.0);  // absolute now: mm/min
  EXPECT_DOUBLE_EQ(t.feed.absolute, 12.5);
  EXPECT_DOUBLE_EQ(t.dips.absolute, 2.0);
  EXPECT_DOUBLE_EQ(t.length.relative, 0.001);  // unnamed: default kept
}

TEST(RegressTolerance, RejectsWhatIsNotAToleranceSpec) {
  for (const char* bad : {"speed=2%", "time", "time=", "time=-1%", "time=abc", "time=2%%", "time=1e999", "feed=nan"})
    EXPECT_THROW(parse_tolerances(bad), UsageError) << bad;
}

TEST(RegressTolerance, AllowsUpToTheEdge) {
  const Tolerance two_percent{0.02, 0};
  EXPECT_TRUE(two_percent.allows(100.0, 102.0));  // exactly 2 %
  EXPECT_TRUE(two_percent.allows(100.0, 98.0));
  EXPECT_FALSE(two_percent.allows(100.0, 102.1));
  EXPECT_FALSE(two_percent.allows(100.0, 97.9));  // faster is a change as well
  const Tolerance absolute{0, 3};
  EXPECT_TRUE(absolute.allows(10, 13));
  EXPECT_FALSE(absolute.allows(10, 13.1));
  EXPECT_EQ(two_percent.text(), "2 %");
  EXPECT_EQ(absolute.text(), "3");
}

ProgramFigures figures(const std::string& program, double time_s) {
  ProgramFigures f;
  f.program = program;
  f.time_s = time_s;
  f.min_feed_mm_min = 800;
  f.path_length_mm = 250;
  return f;
}

TEST(RegressComparison, ASlowerProgramIsAChangeWithItsNumbers) {
  const Baseline base{"M", {figures("a/P.MPF", 10.0), figures("b/Q.MPF", 20.0)}};
  const std::vector<ProgramFigures> now{figures("a/P.MPF", 10.15), figures("b/Q.MPF", 21.0)};
  const auto changes = compare_with_baseline(base, now, RegressTolerances{});
  ASSERT_EQ(changes.size(), 1u);  // P: +1.5 % within 2 %; Q: +5 %
  EXPECT_EQ(changes[0].program, "b/Q.MPF");
  EXPECT_EQ(changes[0].what, "time");
  EXPECT_EQ(changes[0].message(), "time 20.00 s -> 21.00 s (+5.0 %, tolerance 2 %)");
  const std::string table = change_table(changes);
  EXPECT_NE(table.find("program"), std::string::npos);
  EXPECT_NE(table.find("b/Q.MPF  time  20.00 s   21.00 s  +5.0 %, tolerance 2 %"), std::string::npos) << table;
}

TEST(RegressComparison, AlarmsWarningsAndProgramsThatCameOrWent) {
  ProgramFigures before = figures("P.MPF", 10), after = figures("P.MPF", 10);
  Alarm alarm = make_alarm(14040, "", {"/abs/dir/P.MPF", 4, 1}, "G2 X0 Y0 I-5");
  set_diagnostics(after, {alarm});
  ASSERT_EQ(after.alarms.size(), 1u);
  EXPECT_EQ(after.alarms[0].text(), "14040 at P.MPF:4");  // the file without its folders
  const Baseline base{"M", {before, figures("GONE.MPF", 1)}};
  const auto changes = compare_with_baseline(base, {after, figures("NEW.MPF", 1)}, RegressTolerances{});
  ASSERT_EQ(changes.size(), 3u);
  EXPECT_EQ(changes[0].program, "GONE.MPF");
  EXPECT_EQ(changes[0].what, "missing program");
  EXPECT_EQ(changes[1].program, "NEW.MPF");
  EXPECT_EQ(changes[1].what, "new program");
  EXPECT_EQ(changes[2].message(), "alarm - -> 14040 at P.MPF:4 (new)");
}

TEST(RegressBaseline, RoundTripsRoundedAndSorted) {
  ProgramFigures f = figures("z/LAST.MPF", 12.345678);
  f.path_length_mm = 7376.12890000001;
  Alarm w = make_alarm(990002, "FFWON", {"/x/LAST.MPF", 7, 1}, "FFWON");
  w.severity = Severity::Warning;
  set_diagnostics(f, {w, w});
  const Baseline b{"MCV", {f, figures("a/FIRST.MPF", 1)}};
  const std::string text = baseline_json(b);
  EXPECT_NE(text.find("\"time_s\": 12.3457"), std::string::npos) << text;
  EXPECT_NE(text.find("\"path_length_mm\": 7376.1289,"), std::string::npos) << text;
  EXPECT_LT(text.find("a/FIRST.MPF"), text.find("z/LAST.MPF"));
  const Baseline back = parse_baseline(text);
  ASSERT_EQ(back.programs.size(), 2u);
  EXPECT_EQ(back.machine, "MCV");
  EXPECT_EQ(back.programs[1].warnings.size(), 1u);
  EXPECT_EQ(back.programs[1].warnings[0].count, 2u);
  EXPECT_TRUE(compare_with_baseline(back, {back.programs[0], back.programs[1]}, RegressTolerances{}).empty());
  EXPECT_THROW(parse_baseline("{\"format\": \"other\"}"), UsageError);
  EXPECT_THROW(parse_baseline("not json"), UsageError);
}

TEST(JUnitXml, CountsFailuresAndEscapes) {
  const std::string xml = junit_xml("suite", {{"a/<P>.MPF", "drycut.regress.a", 0.5, {}},
                                              {"b/Q.MPF", "drycut.regress.b", 1.25, {"time 1 s -> 2 s", "alarm \"x\""}}});
  EXPECT_NE(xml.find("<testsuites name=\"suite\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\" time=\"1.750\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase name=\"a/&lt;P&gt;.MPF\" classname=\"drycut.regress.a\" time=\"0.500\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"time 1 s -&gt; 2 s (and 1 more)\" type=\"regression\">time 1 s -&gt; 2 s\n"
                     "alarm &quot;x&quot;\n</failure>"),
            std::string::npos)
      << xml;
  EXPECT_EQ(xml_escape(std::string("a\x01" "b\tc")), "ab\tc");
}

}  // namespace
}  // namespace drycut::report
