#include "report/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "report/html_escape.hpp"
#include "report/svg_axis_ticks.hpp"
#include "report/svg_colour_map.hpp"

namespace drycut::report {
namespace {

constexpr double kLeft = 78, kRight = 24, kTop = 58, kBottom = 52, kBarSpace = 96;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

bool finite(const XY& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

// Maps data to pixels.
struct SvgChart::Frame {
  double x0, x1, y0, y1;     // data range shown
  double px0, px1, py0, py1; // pixel box (py0 = bottom)
  double X(double x) const { return px0 + (x - x0) / (x1 - x0) * (px1 - px0); }
  double Y(double y) const { return py0 - (y - y0) / (y1 - y0) * (py0 - py1); }
};

// Legend entries: a swatch drawn at (x, y) and a text; they flow in rows across the top margin.
struct SvgChart::LegendEntry {
  std::function<std::string(double, double)> swatch;
  std::string text;
};

// Polylines for a line, split where a point is not finite.
std::vector<std::string> SvgChart::polylines(const Frame& f, const std::vector<XY>& pts) {
  std::vector<std::string> out;
  std::string cur;
  size_t n = 0;
  auto close = [&] {
    if (n >= 2) out.push_back(cur);
    cur.clear();
    n = 0;
  };
  for (const XY& p : pts) {
    if (!finite(p)) {
      close();
      continue;
    }
    if (n) cur += ' ';
    cur += num(f.X(p.x)) + ',' + num(f.Y(p.y));
    ++n;
  }
  close();
  return out;
}

SvgChart::SvgChart(ChartOptions options) : options_(std::move(options)) {}

void SvgChart::add_line(std::vector<XY> points, std::string colour, double stroke_width, std::string legend,
                        bool dashed) {
  lines_.push_back({std::move(points), std::move(colour), stroke_width, std::move(legend), dashed});
}

void SvgChart::add_coloured_line(std::vector<XY> points, std::vector<double> fractions, double stroke_width,
                                 std::string legend) {
  fractions.resize(points.size(), 0.0);
  coloured_.push_back({std::move(points), std::move(fractions), stroke_width, std::move(legend)});
}

void SvgChart::add_markers(std::vector<XY> points, std::string colour, double radius, std::string legend) {
  markers_.push_back({std::move(points), std::move(colour), radius, std::move(legend)});
}

void SvgChart::add_callout(XY at, std::string label, std::string tooltip) {
  callouts_.push_back({at, std::move(label), std::move(tooltip)});
}

void SvgChart::set_colour_bar(double lo, double hi, std::string label) {
  colour_bar_ = true;
  bar_lo_ = lo;
  bar_hi_ = hi;
  bar_label_ = std::move(label);
}

SvgChart::Bounds SvgChart::data_bounds() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (view_) return view_bounds_;
  Bounds b{inf, -inf, inf, -inf};
  auto take = [&](const std::vector<XY>& pts) {
    for (const XY& p : pts)
      if (finite(p)) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
      }
  };
  for (const auto& l : lines_) take(l.points);
  for (const auto& l : coloured_) take(l.points);
  for (const auto& m : markers_) take(m.points);
  if (!(b.x0 <= b.x1)) b = {0, 1, 0, 1};
  if (options_.y_from_zero) b.y0 = std::min(b.y0, 0.0), b.y1 = std::max(b.y1, 0.0);
  // A flat series still needs a visible range.
  if (b.x1 - b.x0 < 1e-9) b.x0 -= 0.5, b.x1 += 0.5;
  if (b.y1 - b.y0 < 1e-9) b.y0 -= 0.5, b.y1 += 0.5;
  return b;
}

std::vector<SvgChart::LegendEntry> SvgChart::legend_entries() const {
  std::vector<LegendEntry> legend;
  for (const auto& l : lines_)
    if (!l.legend.empty())
      legend.push_back({[&l](double x, double y) {
                          return "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x + 20) +
                                 "\" y2=\"" + num(y) + "\" stroke=\"" + l.colour + "\" stroke-width=\"" +
                                 num(std::max(2.0, l.width)) + "\"" +
                                 (l.dashed ? " stroke-dasharray=\"6 4\"" : "") + "/>";
                        },
                        l.legend});
  for (const auto& c : coloured_)
    if (!c.legend.empty())
      legend.push_back({[](double x, double y) {
                          return "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x + 10) +
                                 "\" y2=\"" + num(y) + "\" stroke=\"" + bin_colour(2) +
                                 "\" stroke-width=\"3\"/><line x1=\"" + num(x + 10) + "\" y1=\"" + num(y) +
                                 "\" x2=\"" + num(x + 20) + "\" y2=\"" + num(y) + "\" stroke=\"" +
                                 bin_colour(kColourBins - 2) + "\" stroke-width=\"3\"/>";
                        },
                        c.legend});
  for (const auto& m : markers_)
    if (!m.legend.empty())
      legend.push_back({[&m](double x, double y) {
                          return "<circle cx=\"" + num(x + 10) + "\" cy=\"" + num(y) + "\" r=\"" +
                                 num(std::max(2.5, m.radius)) + "\" fill=\"" + m.colour + "\"/>";
                        },
                        m.legend});
  if (!callouts_.empty())
    legend.push_back({[](double x, double y) {
                        return "<circle class=\"callout-swatch\" cx=\"" + num(x + 10) + "\" cy=\"" + num(y) +
                               "\" r=\"6\"/>";
                      },
                      "feed dip (number = rank, see table)"});
  return legend;
}

// The swatch position per legend entry: left to right, a new row when the next one would not fit.
std::vector<XY> SvgChart::legend_positions(const std::vector<LegendEntry>& legend, double width) {
  std::vector<XY> legend_at;
  double lx = kLeft, ly = 42;
  for (const auto& e : legend) {
    const double w = 26 + 7.0 * static_cast<double>(e.text.size()) + 18;
    if (lx > kLeft && lx + w > width - kRight) lx = kLeft, ly += 18;
    legend_at.push_back({lx, ly});
    lx += w;
  }
  return legend_at;
}

// The plot box below the legend rows and the data range it shows.
SvgChart::Frame SvgChart::plot_frame(double top) const {
  const double W = options_.width, H = options_.height;
  Frame f{};
  f.px0 = kLeft;
  f.px1 = W - kRight - (colour_bar_ ? kBarSpace : 0);
  f.py0 = H - kBottom;
  f.py1 = top;
  Bounds b = data_bounds();
  // A little air around the data; velocity axes keep 0 at the frame.
  const double padx = 0.03 * (b.x1 - b.x0), pady = 0.05 * (b.y1 - b.y0);
  f.x0 = b.x0 - (options_.equal_aspect ? padx : 0);
  f.x1 = b.x1 + (options_.equal_aspect ? padx : 0);
  f.y0 = options_.y_from_zero && b.y0 >= 0 ? b.y0 : b.y0 - pady;
  f.y1 = b.y1 + pady;
  if (options_.y_max > 0 && options_.y_max > f.y0) f.y1 = options_.y_max;
  if (options_.equal_aspect) {
    // Same mm per pixel on both axes: widen the range that is too short for its side.
    const double sx = (f.px1 - f.px0) / (f.x1 - f.x0), sy = (f.py0 - f.py1) / (f.y1 - f.y0);
    const double s = std::min(sx, sy);
    const double cx = 0.5 * (f.x0 + f.x1), cy = 0.5 * (f.y0 + f.y1);
    const double hx = 0.5 * (f.px1 - f.px0) / s, hy = 0.5 * (f.py0 - f.py1) / s;
    f.x0 = cx - hx, f.x1 = cx + hx, f.y0 = cy - hy, f.y1 = cy + hy;
  }
  return f;
}

// The <svg> element, the clip path of the plot box and the title.
void SvgChart::render_head(std::string& o, const Frame& f, const std::string& id) const {
  const double W = options_.width, H = options_.height;
  // Inline SVG in HTML5 needs no xmlns (and the page must hold no URL at all).
  o += "<svg id=\"" + id + "\" class=\"chart\" viewBox=\"0 0 " + num(W) + " " + num(H) + "\" width=\"" +
       num(W) + "\" height=\"" + num(H) + "\" role=\"img\" aria-label=\"" + html_escape(options_.title) +
       "\">\n";
  o += "<defs><clipPath id=\"" + id + "-clip\"><rect x=\"" + num(f.px0) + "\" y=\"" + num(f.py1) +
       "\" width=\"" + num(f.px1 - f.px0) + "\" height=\"" + num(f.py0 - f.py1) + "\"/></clipPath></defs>\n";
  o += "<text class=\"title\" x=\"" + num(kLeft) + "\" y=\"22\">" + html_escape(options_.title) + "</text>\n";
}

void SvgChart::render_axes(std::string& o, const Frame& f) const {
  const double H = options_.height;
  // Grid and ticks.
  const double xstep = nice_tick_step(f.x0, f.x1, 8), ystep = nice_tick_step(f.y0, f.y1, 6);
  o += "<g class=\"grid\">";
  for (double x : nice_ticks(f.x0, f.x1, 8))
    o += "<line x1=\"" + num(f.X(x)) + "\" y1=\"" + num(f.py0) + "\" x2=\"" + num(f.X(x)) + "\" y2=\"" +
         num(f.py1) + "\"/>";
  for (double y : nice_ticks(f.y0, f.y1, 6))
    o += "<line x1=\"" + num(f.px0) + "\" y1=\"" + num(f.Y(y)) + "\" x2=\"" + num(f.px1) + "\" y2=\"" +
         num(f.Y(y)) + "\"/>";
  o += "</g>\n<g class=\"ticks\">";
  for (double x : nice_ticks(f.x0, f.x1, 8))
    o += "<text x=\"" + num(f.X(x)) + "\" y=\"" + num(f.py0 + 17) + "\" text-anchor=\"middle\">" +
         format_tick(x, xstep) + "</text>";
  for (double y : nice_ticks(f.y0, f.y1, 6))
    o += "<text x=\"" + num(f.px0 - 6) + "\" y=\"" + num(f.Y(y) + 4) + "\" text-anchor=\"end\">" +
         format_tick(y, ystep) + "</text>";
  o += "</g>\n";
  o += "<text class=\"axis\" x=\"" + num(0.5 * (f.px0 + f.px1)) + "\" y=\"" + num(H - 12) +
       "\" text-anchor=\"middle\">" + html_escape(options_.x_label) + "</text>\n";
  o += "<text class=\"axis\" transform=\"translate(16," + num(0.5 * (f.py0 + f.py1)) +
       ") rotate(-90)\" text-anchor=\"middle\">" + html_escape(options_.y_label) + "</text>\n";
}

// Lines, coloured lines and markers.
void SvgChart::render_data(std::string& o, const Frame& f, const std::string& id) const {
  // Data, clipped to the frame.
  o += "<g clip-path=\"url(#" + id +
       "-clip)\" fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (const auto& l : lines_)
    for (const auto& pl : polylines(f, l.points))
      o += "<polyline class=\"series\" stroke=\"" + l.colour + "\" stroke-width=\"" + num(l.width) + "\"" +
           (l.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"" + pl + "\"/>\n";
  for (const auto& c : coloured_) render_coloured_line(o, f, c);
  for (const auto& m : markers_) {
    o += "<g class=\"markers\" fill=\"" + m.colour + "\" stroke=\"none\">";
    for (const XY& p : m.points)
      if (finite(p))
        o += "<circle cx=\"" + num(f.X(p.x)) + "\" cy=\"" + num(f.Y(p.y)) + "\" r=\"" + num(m.radius) +
             "\"/>";
    o += "</g>\n";
  }
  o += "</g>\n";
}

void SvgChart::render_coloured_line(std::string& o, const Frame& f, const ColouredLine& c) {
  // Runs of segments in one colour bin become one polyline.
  size_t i = 0;
  while (i + 1 < c.points.size()) {
    if (!finite(c.points[i]) || !finite(c.points[i + 1])) {
      ++i;
      continue;
    }
    const int bin = colour_bin(0.5 * (c.fractions[i] + c.fractions[i + 1]));
    std::string pts = num(f.X(c.points[i].x)) + ',' + num(f.Y(c.points[i].y));
    size_t j = i;
    while (j + 1 < c.points.size() && finite(c.points[j + 1]) &&
           colour_bin(0.5 * (c.fractions[j] + c.fractions[j + 1])) == bin) {
      ++j;
      pts += ' ' + num(f.X(c.points[j].x)) + ',' + num(f.Y(c.points[j].y));
    }
    o += "<polyline class=\"series\" stroke=\"" + bin_colour(bin) + "\" stroke-width=\"" + num(c.width) +
         "\" points=\"" + pts + "\"/>\n";
    i = j;
  }
}

// Callouts are drawn unclipped, over the data.
void SvgChart::render_callouts(std::string& o, const Frame& f) const {
  for (const auto& c : callouts_) {
    if (!finite(c.at)) continue;
    const double x = f.X(c.at.x), y = f.Y(c.at.y);
    o += "<g class=\"callout\"><title>" + html_escape(c.tooltip) + "</title><circle cx=\"" + num(x) +
         "\" cy=\"" + num(y) + "\" r=\"7\"/><text x=\"" + num(x + 9) + "\" y=\"" + num(y - 8) + "\">" +
         html_escape(c.label) + "</text></g>\n";
  }
}

void SvgChart::render_legend(std::string& o, const std::vector<LegendEntry>& legend,
                             const std::vector<XY>& legend_at) {
  for (size_t k = 0; k < legend.size(); ++k)
    o += "<g class=\"legend\">" + legend[k].swatch(legend_at[k].x, legend_at[k].y) + "<text x=\"" +
         num(legend_at[k].x + 26) + "\" y=\"" + num(legend_at[k].y + 4) + "\">" +
         html_escape(legend[k].text) + "</text></g>";
  o += "\n";
}

void SvgChart::render_colour_bar(std::string& o, const Frame& f, const std::string& id) const {
  const double W = options_.width;
  // Gradient bar with its own ticks: the velocity colours of the coloured line.
  const double bx = W - kRight - kBarSpace + 26, bw = 16, by1 = f.py1, by0 = f.py0;
  o += "<defs><linearGradient id=\"" + id + "-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int k = 0; k <= 8; ++k)
    o += "<stop offset=\"" + num(k / 8.0) + "\" stop-color=\"" + scale_colour(k / 8.0) + "\"/>";
  o += "</linearGradient></defs>\n";
  o += "<g class=\"colour-bar\"><rect x=\"" + num(bx) + "\" y=\"" + num(by1) + "\" width=\"" + num(bw) +
       "\" height=\"" + num(by0 - by1) + "\" fill=\"url(#" + id + "-bar)\" stroke=\"#444\"/>";
  const double lo = bar_lo_, hi = bar_hi_ > bar_lo_ ? bar_hi_ : bar_lo_ + 1;
  const double step = nice_tick_step(lo, hi, 6);
  for (double v : nice_ticks(lo, hi, 6)) {
    const double y = by0 - (v - lo) / (hi - lo) * (by0 - by1);
    o += "<line x1=\"" + num(bx + bw) + "\" y1=\"" + num(y) + "\" x2=\"" + num(bx + bw + 4) + "\" y2=\"" +
         num(y) + "\" stroke=\"#444\"/><text x=\"" + num(bx + bw + 7) + "\" y=\"" + num(y + 4) + "\">" +
         format_tick(v, step) + "</text>";
  }
  o += "<text class=\"axis\" x=\"" + num(bx + bw / 2) + "\" y=\"" + num(by1 - 10) +
       "\" text-anchor=\"middle\">" + html_escape(bar_label_) + "</text></g>\n";
}

std::string SvgChart::render() const {
  const std::vector<LegendEntry> legend = legend_entries();
  const std::vector<XY> legend_at = legend_positions(legend, options_.width);
  const double top = kTop + (legend_at.empty() ? 0 : legend_at.back().y - 42);
  const Frame f = plot_frame(top);

  const std::string id = html_escape(options_.id);
  std::string o;
  render_head(o, f, id);
  render_axes(o, f);
  render_data(o, f, id);
  render_callouts(o, f);
  o += "<rect class=\"frame\" x=\"" + num(f.px0) + "\" y=\"" + num(f.py1) + "\" width=\"" +
       num(f.px1 - f.px0) + "\" height=\"" + num(f.py0 - f.py1) + "\"/>\n";
  render_legend(o, legend, legend_at);
  if (colour_bar_) render_colour_bar(o, f, id);
  o += "</svg>\n";
  return o;
}

}  // namespace drycut::report
