// The 3D view section: the data JSON (compact, parseable, safe inside <script>), the libraries
// inlined in order, the note when they are missing, and the loader.
#include "report/html_trace_viewer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "report/svg_colour_map.hpp"
#include "report_test_support.hpp"

namespace drycut::report {
namespace {

using namespace drycut::report::test;

Trace3d two_point_trace() {
  Trace3d t;
  t.samples = 7;
  TracePoint a;
  a.x = 1.23456, a.y = -0.0001, a.z = 5, a.t = 0.00004, a.v = 10, a.rapid = true;
  TracePoint b;
  b.x = 2, b.y = 3, b.z = 4, b.t = 1.5, b.v = 2.5, b.block = 1;
  t.points = {a, b};
  TraceBlock r;
  r.file = intern_file_name("/some/dir/MAIN.MPF");
  r.line = 4, r.text = "N40 G0 Z5", r.rapid = true;
  TraceBlock c;
  c.file = r.file;
  c.line = 5, c.text = "N50 G1 X2 ; </script><!-- & <b>", c.feed_mm_s = 20;
  t.blocks = {r, c};
  return t;
}

TEST(TraceViewerJson, CompactRoundedAndParseable) {
  const Trace3d trace = two_point_trace();
  TraceViewerInput in;
  in.trace = &trace;
  in.scale_mm_s = 25;
  in.dips = {{1.25, 1, "dip 1: </script>"}};
  const std::string text = trace_viewer_json(in);
  EXPECT_EQ(text.find('<'), std::string::npos);  // nothing can end the <script> element
  const auto j = nlohmann::json::parse(text);
  // 7 numbers per point: mm to 3 decimals, s to 4, mm/min whole; y = -0.0001 rounds to 0.
  EXPECT_EQ(j["p"], nlohmann::json::parse("[1.235,0,5,0,600,0,1, 2,3,4,1.5,150,1,0]"));
  EXPECT_EQ(text.find("1.235,0,5,0,600,0,1"), text.find("\"p\":[") + 5);  // no trailing zeros, no "-0"
  ASSERT_EQ(j["blocks"].size(), 2u);
  EXPECT_EQ(j["files"], nlohmann::json::parse("[\"MAIN.MPF\"]"));  // the name, not the path
  EXPECT_EQ(j["blocks"][1][0], 0);
  EXPECT_EQ(j["blocks"][1][1], 5);
  EXPECT_EQ(j["blocks"][1][2], "N50 G1 X2 ; </script><!-- & <b>");
  EXPECT_EQ(j["blocks"][1][3], 1200);  // F 20 mm/s
  EXPECT_EQ(j["scale"], 1500);
  EXPECT_EQ(j["dips"][0][2], "dip 1: </script>");
  EXPECT_EQ(j["colours"].size(), static_cast<size_t>(kColourBins));
  EXPECT_EQ(j["samples"], 7);
}

TEST(TraceViewerSection, NoteInsteadOfScriptsWhenTheLibraryIsMissing) {
  const Trace3d trace = two_point_trace();
  ViewerLibrary lib;
  lib.missing = "/x/three.min.js could not be read";
  TraceViewerInput in;
  in.trace = &trace;
  in.library = &lib;
  const std::string html = trace_viewer_section(in);
  EXPECT_NE(html.find("id=\"trace-viewer-missing\""), std::string::npos);
  EXPECT_NE(html.find("/x/three.min.js could not be read"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  in.library = nullptr;
  EXPECT_EQ(trace_viewer_section(in).find("<script"), std::string::npos);
}

TEST(TraceViewerSection, LibrariesInOrderThenDataThenViewer) {
  const Trace3d trace = two_point_trace();
  ViewerLibrary lib;
  for (size_t i = 0; i < kViewerLibraryFiles.size(); ++i) lib.scripts.push_back("var lib" + std::to_string(i) + " = '</script>';");
  TraceViewerInput in;
  in.trace = &trace;
  in.library = &lib;
  const std::string html = trace_viewer_section(in);
  EXPECT_NE(html.find("<canvas id=\"trace-canvas\""), std::string::npos);
  EXPECT_NE(html.find("id=\"trace-slider\" type=\"range\" min=\"0\" max=\"1\""), std::string::npos);
  size_t at = 0;
  for (size_t i = 0; i < kViewerLibraryFiles.size(); ++i) {
    const size_t next = html.find("var lib" + std::to_string(i) + " = '<\\/script>';");
    ASSERT_NE(next, std::string::npos) << i;
    EXPECT_GT(next, at);
    at = next;
  }
  const size_t data = html.find("id=\"trace-data\"");
  EXPECT_GT(data, at);
  // Every "</script" in the page closes one of the page's own script elements: 5 + data + viewer.
  size_t opens = 0, closes = 0;
  for (size_t p = html.find("<script"); p != std::string::npos; p = html.find("<script", p + 1)) ++opens;
  for (size_t p = html.find("</script"); p != std::string::npos; p = html.find("</script", p + 1)) ++closes;
  EXPECT_EQ(opens, kViewerLibraryFiles.size() + 2);
  EXPECT_EQ(closes, opens);
}

TEST(TraceViewerSection, NoMotionNoViewer) {
  Trace3d empty;
  ViewerLibrary lib;
  lib.scripts.assign(kViewerLibraryFiles.size(), "var x;");
  TraceViewerInput in;
  in.trace = &empty;
  in.library = &lib;
  const std::string html = trace_viewer_section(in);
  EXPECT_NE(html.find("no motion"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(InlineScriptText, EscapesOnlyWhatEndsOrConfusesTheElement) {
  EXPECT_EQ(inline_script_text("a='</script>';b='</SCRIPT >';c='<!--';d='</div>';e=1<2"),
            "a='<\\/script>';b='<\\/SCRIPT >';c='<\\!--';d='</div>';e=1<2");
  EXPECT_EQ(inline_script_text("x<"), "x<");
  EXPECT_EQ(inline_script_text(""), "");
}

TEST(ViewerLibrary, LoadsEveryFileOrSaysWhichIsMissing) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("drycut_viewer_lib_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  for (const char* f : kViewerLibraryFiles) {
    fs::create_directories((dir / f).parent_path());
    std::ofstream(dir / f) << "// " << f << "\n";
  }
  const ViewerLibrary ok = load_viewer_library(dir.string());
  EXPECT_TRUE(ok.available()) << ok.missing;
  ASSERT_EQ(ok.scripts.size(), kViewerLibraryFiles.size());
  EXPECT_EQ(ok.scripts[1], "// examples/js/controls/OrbitControls.js\n");
  fs::remove(dir / "examples/js/lines/LineMaterial.js");
  const ViewerLibrary partial = load_viewer_library(dir.string());
  EXPECT_FALSE(partial.available());
  EXPECT_TRUE(partial.scripts.empty());
  EXPECT_NE(partial.missing.find("LineMaterial.js"), std::string::npos);
  fs::remove_all(dir);
  EXPECT_NE(load_viewer_library(dir.string()).missing.find("three.min.js"), std::string::npos);
}

}  // namespace
}  // namespace drycut::report
