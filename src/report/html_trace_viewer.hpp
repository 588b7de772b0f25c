#pragma once
// The report's interactive 3D view of the tool-centre trace: three.js (inlined from Debian's
// libjs-three), the trace as compact JSON, and the viewer script (src/report/trace_viewer.js,
// embedded at build time). Orbit/pan/zoom, path coloured by velocity on the top view's scale,
// rapids dashed, the worst dips marked, a playback bar that moves the tool along the trace and
// shows the block, file:line, time and feed.
//
// Data in the page (<script type="application/json" id="trace-data">), all numbers rounded:
//   { "p": [x, y, z, t, v, block, rapid, ...]   7 numbers per point: mm, s, mm/min, index, 0/1
//     "blocks": [[file, line, text, F], ...]   file indexes "files"; F in mm/min, 0 for rapids
//     "files": [name, ...], "dips": [[t, rank, tooltip], ...], "scale": mm/min at the top colour,
//     "colours": ["#rrggbb", ...] the top view's velocity bins, "samples": IPO samples before decimation }
// Without the libraries, or without motion, the section is a note and the page has no script.
#include <string>
#include <vector>

#include "report/trace_3d_collector.hpp"
#include "report/viewer_library.hpp"

namespace drycut::report {

struct TraceDipMark {
  double t = 0;  // s, where the dip's lowest velocity is
  size_t rank = 0;
  std::string tooltip;
};

struct TraceViewerInput {
  const Trace3d* trace = nullptr;
  const ViewerLibrary* library = nullptr;
  double scale_mm_s = 0;  // velocity at the top colour
  std::vector<TraceDipMark> dips;
};

// The JSON object described above, safe inside a <script> element ('<' written as \u003c).
std::string trace_viewer_json(const TraceViewerInput& input);

// The "3D view" section: heading, viewer markup and scripts, or a note why it is absent.
std::string trace_viewer_section(const TraceViewerInput& input);

}  // namespace drycut::report
