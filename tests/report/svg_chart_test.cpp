#include "report/svg_chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <sstream>

namespace drycut::report {
namespace {

// The pixel coordinates of every polyline in the SVG, in order.
std::vector<std::vector<XY>> polylines(const std::string& svg) {
  std::vector<std::vector<XY>> out;
  const std::regex re("<polyline[^>]* points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it) {
    std::vector<XY> pts;
    std::istringstream in((*it)[1].str());
    std::string pair;
    while (in >> pair) {
      const auto comma = pair.find(',');
      pts.push_back({std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))});
    }
    out.push_back(pts);
  }
  return out;
}

TEST(SvgChart, EqualAspectDrawsASquareAsASquare) {
  SvgChart c({"top", "square", "X [mm]", "Y [mm]", 1000, 400, true, false, 0});
  c.add_line({{0, 0}, {40, 0}, {40, 10}, {0, 10}, {0, 0}}, "#000", 1, "rect");  // 4:1 rectangle
  const auto lines = polylines(c.render());
  ASSERT_EQ(lines.size(), 1u);
  const auto& p = lines[0];
  const double w = std::abs(p[1].x - p[0].x), h = std::abs(p[2].y - p[1].y);
  EXPECT_NEAR(w / h, 4.0, 0.05);  // pixels rounded to 0.1
  EXPECT_LT(p[2].y, p[1].y);      // y grows upwards on the page
}

TEST(SvgChart, WithoutEqualAspectTheDataFillsTheFrame) {
  // A nearly square frame: equal aspect would draw the 4:1 data 4:1, filling draws it ~1:1.
  SvgChart c({"v", "t", "x", "y", 400, 400, false, false, 0});
  c.add_line({{0, 0}, {40, 0}, {40, 10}}, "#000", 1, "");
  const auto p = polylines(c.render())[0];
  const double w = std::abs(p[1].x - p[0].x), h = std::abs(p[2].y - p[1].y);
  EXPECT_GT(h / w, 0.6);
}

TEST(SvgChart, NanBreaksALine) {
  SvgChart c({"v", "t", "x", "y", 600, 300, false, false, 0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.add_line({{0, 0}, {1, 1}, {2, nan}, {3, 1}, {4, 0}}, "#000", 1, "");
  EXPECT_EQ(polylines(c.render()).size(), 2u);
}

TEST(SvgChart, HasIdAxisLabelsTicksAndLegend) {
  SvgChart c({"velocity-time", "Velocity <&>", "time [s]", "path velocity [mm/min]", 600, 300, false, true, 0});
  c.add_line({{0, 0}, {10, 1000}}, "#123456", 1, "path velocity");
  const std::string svg = c.render();
  EXPECT_NE(svg.find("<svg id=\"velocity-time\""), std::string::npos);
  EXPECT_NE(svg.find("time [s]"), std::string::npos);
  EXPECT_NE(svg.find("path velocity [mm/min]"), std::string::npos);
  EXPECT_NE(svg.find("Velocity &lt;&amp;&gt;"), std::string::npos);
  EXPECT_NE(svg.find(">1000<"), std::string::npos);  // a y tick label
  EXPECT_NE(svg.find(">10<"), std::string::npos);    // an x tick label
  EXPECT_NE(svg.find(">path velocity<"), std::string::npos);  // legend entry
  EXPECT_EQ(svg.find("http"), std::string::npos);
}

TEST(SvgChart, ColouredLineUsesSeveralColoursAndABar) {
  SvgChart c({"top", "t", "x", "y", 600, 300, true, false, 0});
  std::vector<XY> pts;
  std::vector<double> f;
  for (int i = 0; i <= 100; ++i) {
    pts.push_back({i * 1.0, 0});
    f.push_back(i / 100.0);
  }
  c.add_coloured_line(pts, f, 2, "tool");
  c.set_colour_bar(0, 3000, "mm/min");
  const std::string svg = c.render();
  const auto lines = polylines(svg);
  EXPECT_GE(lines.size(), 20u);  // one polyline per colour bin
  EXPECT_LE(lines.size(), 30u);
  EXPECT_NE(svg.find("linearGradient"), std::string::npos);
  EXPECT_NE(svg.find(">3000<"), std::string::npos);
}

}  // namespace
}  // namespace drycut::report
