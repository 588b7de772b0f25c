#include "report/html_run_report.hpp"

#include <gtest/gtest.h>

#include "report/html_compare_report.hpp"
#include "report_test_support.hpp"

namespace drycut::report {
namespace {

using namespace drycut::report::test;

const char* kEvilBlock = "N30 G1 X5 ; <script>alert(\"pwn\")</script> & <b>";

RunReportInput sample_input() {
  RunReportInput in;
  in.program = "/tmp/A<B>&.MPF";
  in.machine = "TEST <machine>";
  in.summary.time_s = 12.345;
  in.summary.time_after_m0_s = 2.5;
  in.summary.path_length_mm = 136.2;
  in.summary.min_feed_mm_s = 5;
  in.summary.max_feed_mm_s = 20;
  motion::FeedDip dip;
  dip.min_source = block(30, kEvilBlock);
  dip.source = dip.min_source;
  dip.v_min_mm_s = 5;
  dip.programmed_feed_mm_s = 20;
  dip.limit = motion::Limit::Curvature;
  dip.element_count = 3;
  in.summary.dips = {dip};
  in.dip_locations = {DipLocation{true, 1, 1, 0.5, 3}};
  Alarm a = make_alarm(12550, "name QQ not defined", SourceLocation{"/tmp/A.MPF", 30, 1}, kEvilBlock);
  in.diagnostics = {a};
  for (int i = 0; i <= 100; ++i) {
    const double t = i * 0.01;
    in.plots.tool_path.push_back(PlotPoint{std::cos(t * 6), std::sin(t * 6), t, t * 10, i == 50 ? 5.0 : 20.0, 0});
  }
  in.plots.programmed_path = in.plots.tool_path;
  in.plots.feed = {PlotPoint{0, 0, 0, 0, 20, 20}, PlotPoint{0, 0, 1, 10, 20, 20}};
  in.plots.knots = {PlotPoint{1, 0, 0, 0, 0, 0}};
  in.plots.knot_count = 1;
  return in;
}

TEST(HtmlRunReport, BlockTextIsShownLiterallyNeverAsMarkup) {
  const std::string html = render_run_report(sample_input());
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("N30 G1 X5 ; &lt;script&gt;alert(&quot;pwn&quot;)&lt;/script&gt; &amp; &lt;b&gt;"), std::string::npos);
  EXPECT_NE(html.find("A&lt;B&gt;&amp;.MPF"), std::string::npos);
  EXPECT_NE(html.find("TEST &lt;machine&gt;"), std::string::npos);
}

TEST(HtmlRunReport, IsSelfContained) {
  const std::string html = render_run_report(sample_input());
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
}

TEST(HtmlRunReport, HasThePlotsTablesAndSummaryFigures) {
  const std::string html = render_run_report(sample_input());
  for (const char* id : {"id=\"top-view\"", "id=\"velocity-time\"", "id=\"velocity-length\"", "id=\"summary\"",
                         "id=\"alarms\"", "id=\"dips\""})
    EXPECT_NE(html.find(id), std::string::npos) << id;
  EXPECT_EQ(html.find("id=\"deviation\""), std::string::npos);  // no reference given
  EXPECT_NE(html.find("id=\"trace-viewer-missing\""), std::string::npos);  // no three.js given
  EXPECT_NE(html.find("12.35 s"), std::string::npos);
  EXPECT_NE(html.find("2.50 s"), std::string::npos);
  EXPECT_NE(html.find("300 mm/min"), std::string::npos);   // lowest feed 5 mm/s
  EXPECT_NE(html.find("1200 mm/min"), std::string::npos);  // highest 20 mm/s
  EXPECT_NE(html.find("12550"), std::string::npos);
  EXPECT_NE(html.find("curvature"), std::string::npos);
  EXPECT_NE(html.find("ended in an alarm"), std::string::npos);
  EXPECT_NE(html.find("class=\"callout\""), std::string::npos);  // the dip is marked
}

TEST(HtmlRunReport, DeviationPlotWhenAReferenceWasUsed) {
  RunReportInput in = sample_input();
  in.plots.has_deviation = true;
  in.plots.max_deviation_mm = 0.0123;
  in.reference = {{1, 0}, {0, 1}, {-1, 0}};
  in.reference_name = "r = 18";
  const std::string html = render_run_report(in);
  EXPECT_NE(html.find("id=\"deviation\""), std::string::npos);
  EXPECT_NE(html.find("0.0123 mm"), std::string::npos);
}

TEST(HtmlRunReport, DipsWorstFirst) {
  motion::PlanSummary s;
  for (double v : {5.0, 1.0, 3.0}) {
    motion::FeedDip d;
    d.v_min_mm_s = v;
    s.dips.push_back(d);
  }
  EXPECT_EQ(dips_worst_first(s), (std::vector<size_t>{1, 2, 0}));
}

TEST(HtmlCompareReport, TableJsonAndOverlay) {
  CompareRow a;
  a.program = "/x/A&B.MPF";
  a.time_s = 10.5;
  a.min_feed_mm_min = 700;
  a.dips = 3;
  a.program_bytes = 1234;
  a.path = {PlotPoint{0, 0, 0, 0, 0, 0}, PlotPoint{1, 1, 0, 0, 0, 0}};
  CompareRow b = a;
  b.program = "/x/C.MPF";
  b.has_deviation = true;
  b.max_deviation_mm = 0.002;
  const std::string html = render_compare_report({a, b}, {}, "");
  EXPECT_NE(html.find("id=\"compare-paths\""), std::string::npos);
  EXPECT_NE(html.find("A&amp;B.MPF"), std::string::npos);
  EXPECT_NE(html.find(program_colour(0)), std::string::npos);
  EXPECT_NE(html.find(program_colour(1)), std::string::npos);
  EXPECT_NE(program_colour(0), program_colour(1));
  EXPECT_EQ(html.find("http"), std::string::npos);
  const std::string text = compare_table_text({a, b});
  EXPECT_NE(text.find("10.50"), std::string::npos);
  EXPECT_NE(text.find("1234"), std::string::npos);
  EXPECT_NE(text.find("0.0020"), std::string::npos);
  const std::string json = compare_json({a, b});
  EXPECT_NE(json.find("\"max_deviation_mm\": null"), std::string::npos);
  EXPECT_NE(json.find("\"program_bytes\": 1234"), std::string::npos);
}

}  // namespace
}  // namespace drycut::report
