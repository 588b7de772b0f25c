#pragma once
// The one stylesheet of the HTML pages (inline, system fonts only: the page opens offline).
#include <string_view>

namespace drycut::report {

inline constexpr std::string_view kHtmlPageStyle = R"css(
body { font-family: system-ui, "DejaVu Sans", Arial, sans-serif; margin: 24px; color: #222; max-width: 1160px; }
h1 { font-size: 22px; margin: 0 0 4px 0; }
h2 { font-size: 17px; margin: 28px 0 8px 0; border-bottom: 1px solid #ccc; padding-bottom: 3px; }
p.meta { color: #555; margin: 0 0 12px 0; }
table { border-collapse: collapse; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
code, td.block { font-family: "DejaVu Sans Mono", monospace; font-size: 12px; white-space: pre-wrap; }
.status-ok { color: #1a7f37; font-weight: bold; }
.status-alarm { color: #b2182b; font-weight: bold; }
p.incomplete { background: #fdecec; border: 2px solid #b2182b; color: #7a0f1d; font-weight: bold; padding: 8px 12px; margin: 8px 0 12px 0; }
tr.incomplete td { background: #fdecec; }
tr.alarm td { background: #fdecec; }
tr.warning td { background: #fff8e1; }
svg.chart { display: block; margin: 8px 0 4px 0; background: #fff; }
svg.chart text { font-size: 12px; fill: #333; }
svg.chart text.title { font-size: 14px; font-weight: bold; }
svg.chart text.axis { font-size: 13px; }
svg.chart .grid line { stroke: #e6e6e6; stroke-width: 1; }
svg.chart rect.frame { fill: none; stroke: #888; }
svg.chart .callout circle { fill: none; stroke: #000; stroke-width: 2; }
svg.chart .callout text { font-weight: bold; fill: #000; paint-order: stroke; stroke: #fff; stroke-width: 3px; }
svg.chart circle.callout-swatch { fill: none; stroke: #000; stroke-width: 2; }
p.note { color: #555; font-size: 12px; margin: 2px 0 10px 0; }
div.viewer { border: 1px solid #ccc; padding: 6px; outline: none; }
div.viewer:focus { border-color: #2166ac; }
div.viewer-stage { position: relative; width: 1100px; height: 640px; overflow: hidden; }
div.viewer-stage canvas { display: block; cursor: grab; }
#trace-labels span { position: absolute; transform: translate(-50%, -130%); font: bold 12px sans-serif; color: #000; paint-order: stroke; -webkit-text-stroke: 3px #fff; pointer-events: none; }
#trace-labels span.tool { display: none; }
div.viewer-bar { display: flex; gap: 6px; align-items: center; margin: 6px 0; }
div.viewer-bar input[type=range] { flex: 1; }
#trace-readout { width: 100%; margin-top: 4px; }
#trace-readout th { width: 70px; }
#trace-legend { font-size: 12px; color: #333; margin-top: 6px; }
#trace-legend .ramp { display: inline-block; width: 240px; height: 10px; vertical-align: middle; margin: 0 6px; border: 1px solid #999; }
)css";

}  // namespace drycut::report
