#pragma once
// A self-contained SVG x-y chart: frame, ticks with labels, axis titles with units, a legend,
// lines (NaN breaks a line), lines coloured by a value, markers and numbered callouts. Output
// is plain inline SVG: no scripts, fonts or links, so the report opens offline.
#include <string>
#include <vector>

namespace drycut::report {

struct XY {
  double x = 0, y = 0;
};

struct ChartOptions {
  std::string id;       // the <svg> element's id
  std::string title;
  std::string x_label;  // with unit, e.g. "time [s]"
  std::string y_label;
  int width = 1100;
  int height = 420;
  bool equal_aspect = false;  // one mm is as long in x as in y (top views)
  bool y_from_zero = false;   // include 0 in the y range (velocities)
  double y_max = 0;           // > 0: fixed top of the y range (data above is clipped)
};

class SvgChart {
 public:
  explicit SvgChart(ChartOptions options);

  void add_line(std::vector<XY> points, std::string colour, double stroke_width, std::string legend,
                bool dashed = false);
  // A line whose segments take the colour of `fractions[i]` (0..1 on the colour scale).
  void add_coloured_line(std::vector<XY> points, std::vector<double> fractions, double stroke_width,
                         std::string legend);
  void add_markers(std::vector<XY> points, std::string colour, double radius, std::string legend);
  // A numbered callout (dips): a ring at the point and its label; `tooltip` shows on hover.
  void add_callout(XY at, std::string label, std::string tooltip);
  // A vertical colour bar right of the plot for add_coloured_line (values lo..hi, unit label).
  void set_colour_bar(double lo, double hi, std::string label);

  // Show this data range instead of fitting all data (what lies outside is clipped).
  void set_view(double x0, double x1, double y0, double y1) {
    view_ = true;
    view_bounds_ = {x0, x1, y0, y1};
  }

  bool empty() const { return lines_.empty() && coloured_.empty() && markers_.empty(); }
  std::string render() const;

 private:
  struct Line {
    std::vector<XY> points;
    std::string colour;
    double width;
    std::string legend;
    bool dashed;
  };
  struct ColouredLine {
    std::vector<XY> points;
    std::vector<double> fractions;
    double width;
    std::string legend;
  };
  struct Markers {
    std::vector<XY> points;
    std::string colour;
    double radius;
    std::string legend;
  };
  struct Callout {
    XY at;
    std::string label, tooltip;
  };
  struct Bounds {
    double x0, x1, y0, y1;
  };
  struct Frame;        // data-to-pixel mapping (svg_chart.cpp)
  struct LegendEntry;  // a swatch and its text (svg_chart.cpp)
  Bounds data_bounds() const;

  // render(), piece by piece in the order of the SVG.
  std::vector<LegendEntry> legend_entries() const;
  static std::vector<XY> legend_positions(const std::vector<LegendEntry>& legend, double width);
  Frame plot_frame(double top) const;
  void render_head(std::string& o, const Frame& f, const std::string& id) const;
  void render_axes(std::string& o, const Frame& f) const;
  void render_data(std::string& o, const Frame& f, const std::string& id) const;
  static void render_coloured_line(std::string& o, const Frame& f, const ColouredLine& c);
  void render_callouts(std::string& o, const Frame& f) const;
  static void render_legend(std::string& o, const std::vector<LegendEntry>& legend,
                            const std::vector<XY>& legend_at);
  void render_colour_bar(std::string& o, const Frame& f, const std::string& id) const;
  static std::vector<std::string> polylines(const Frame& f, const std::vector<XY>& pts);

  ChartOptions options_;
  bool view_ = false;
  Bounds view_bounds_{0, 1, 0, 1};
  std::vector<Line> lines_;
  std::vector<ColouredLine> coloured_;
  std::vector<Markers> markers_;
  std::vector<Callout> callouts_;
  bool colour_bar_ = false;
  double bar_lo_ = 0, bar_hi_ = 1;
  std::string bar_label_;
};

}  // namespace drycut::report
