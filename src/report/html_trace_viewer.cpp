#include "report/html_trace_viewer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>
#include <nlohmann/json.hpp>

#include "report/html_escape.hpp"
#include "report/svg_colour_map.hpp"
#include "trace_viewer_js.hpp"

namespace drycut::report {
namespace {

constexpr double kMinPerS = 60.0;

// A number with at most `decimals` decimals, trailing zeros dropped: the data stays small.
void append_number(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) v = 0;
  char buf[48];
  int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  if (n <= 0 || n >= static_cast<int>(sizeof buf)) {
    out += '0';
    return;
  }
  if (decimals > 0) {
    while (n > 0 && buf[n - 1] == '0') --n;
    if (n > 0 && buf[n - 1] == '.') --n;
  }
  std::string_view s(buf, static_cast<size_t>(n));
  if (s == "-0") s = "0";
  out.append(s);
}

// JSON text for a <script> element: '<' only occurs inside strings, where \u003c means the same.
std::string script_safe(const std::string& json_text) {
  std::string out;
  out.reserve(json_text.size());
  for (char c : json_text) c == '<' ? out.append("\\u003c") : out.append(1, c);
  return out;
}

std::string dump(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

std::string points_json(const Trace3d& trace) {
  std::string o = "[";
  o.reserve(trace.points.size() * 40);
  bool first = true;
  for (const auto& p : trace.points) {
    if (!first) o += ',';
    first = false;
    append_number(o, p.x, 3), o += ',';
    append_number(o, p.y, 3), o += ',';
    append_number(o, p.z, 3), o += ',';
    append_number(o, p.t, 4), o += ',';
    append_number(o, p.v * kMinPerS, 0), o += ',';
    o += std::to_string(p.block);
    o += p.rapid ? ",1" : ",0";
  }
  return o + "]";
}

}  // namespace

std::string trace_viewer_json(const TraceViewerInput& in) {
  using nlohmann::json;
  static const Trace3d kEmpty;
  const Trace3d& trace = in.trace ? *in.trace : kEmpty;
  std::map<std::string, size_t> file_index;
  json files = json::array(), blocks = json::array();
  for (const auto& b : trace.blocks) {
    const std::string name = b.file ? std::filesystem::path(*b.file).filename().string() : std::string();
    auto [it, fresh] = file_index.emplace(name, files.size());
    if (fresh) files.push_back(name);
    blocks.push_back(json::array({it->second, b.line, b.text, std::round(b.feed_mm_s * kMinPerS)}));
  }
  json dips = json::array();
  for (const auto& d : in.dips) dips.push_back(json::array({d.t, d.rank, d.tooltip}));
  json colours = json::array();
  for (int bin = 0; bin < kColourBins; ++bin) colours.push_back(bin_colour(bin));
  std::string o = "{\"p\":" + points_json(trace) + ",\n\"blocks\":" + dump(blocks) + ",\n\"files\":" + dump(files) +
                  ",\n\"dips\":" + dump(dips) + ",\n\"scale\":";
  append_number(o, in.scale_mm_s * kMinPerS, 0);
  o += ",\n\"colours\":" + dump(colours) + ",\n\"samples\":" + std::to_string(trace.samples) + "}";
  return script_safe(o);
}

std::string trace_viewer_section(const TraceViewerInput& in) {
  std::string o = "<h2>3D view</h2>\n";
  if (!in.library || !in.library->available()) {
    const std::string why = in.library ? in.library->missing : std::string("three.js was not loaded");
    return o + "<p id=\"trace-viewer-missing\" class=\"note\">The interactive 3D view is not in this report: " +
           html_escape(why) + ". The top view below shows the path.</p>\n";
  }
  if (!in.trace || in.trace->points.size() < 2)
    return o + "<p id=\"trace-viewer-missing\" class=\"note\">The run has no motion to show in 3D.</p>\n";
  o += R"html(<div id="trace-viewer" class="viewer" tabindex="0">
<div class="viewer-stage"><canvas id="trace-canvas" width="1100" height="640"></canvas><div id="trace-labels"></div></div>
<div class="viewer-bar"><button id="trace-play" type="button" title="play / pause (space)">&#9654;</button>
<input id="trace-slider" type="range" min="0" max=")html" +
       std::to_string(in.trace->points.size() - 1) + R"html(" value="0" step="1" aria-label="playback position">
<select id="trace-speed" title="playback speed (times real time)"></select>
<button id="trace-view-iso" type="button">3D</button><button id="trace-view-top" type="button">top</button><button id="trace-view-front" type="button">front</button></div>
<table id="trace-readout"><tr><th>block</th><td id="trace-block" class="block"></td></tr>
<tr><th>where</th><td id="trace-where"></td></tr>
<tr><th>time</th><td id="trace-time" class="num"></td></tr>
<tr><th>feed</th><td id="trace-feed" class="num"></td></tr></table>
<div id="trace-legend"></div>
<p id="trace-status" class="note"></p>
</div>
<p class="note">Drag to turn the view, right-drag (or shift-drag) to pan, wheel to zoom; double-click the path to move the tool there.
Keys (click the view first): space plays and pauses, &larr; &rarr; step one sample, shift + arrows one block, Home / End.
Colour: path velocity of the tool centre on the top view's scale; dashed grey: rapids; red balls: the worst feed dips, numbered as in the table below.
The trace is decimated like the plots (lowest and highest velocity of each stretch kept).</p>
)html";
  o += "<!-- three.js (MIT licence), its OrbitControls and fat lines, from Debian's libjs-three -->\n";
  for (const auto& script : in.library->scripts) o += "<script>\n" + inline_script_text(script) + "\n</script>\n";
  o += "<script type=\"application/json\" id=\"trace-data\">" + trace_viewer_json(in) + "</script>\n";
  o += "<script>\n" + inline_script_text(kTraceViewerJs) + "\n</script>\n";
  return o;
}

}  // namespace drycut::report
