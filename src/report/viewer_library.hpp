#pragma once
// The JavaScript libraries the report's 3D viewer needs: three.js, its OrbitControls and its
// fat lines (lines of a width in pixels; WebGL draws plain lines one pixel wide), from Debian's
// libjs-three. They are read when a report is written and inlined into the page, so the
// report stays one file that opens offline. Where they are: the folder configured at build time
// (CMake cache variable DRYCUT_THREE_JS_DIR, default /usr/share/javascript/three), or the
// environment variable DRYCUT_THREE_JS_DIR at run time. A missing file never fails the run: the
// report then says why the 3D view is absent and keeps its top view.
#include <array>
#include <string>
#include <vector>

namespace drycut::report {

// In the order they are loaded (each later one extends the THREE object of the first).
inline constexpr std::array<const char*, 5> kViewerLibraryFiles{
    "three.min.js", "examples/js/controls/OrbitControls.js", "examples/js/lines/LineSegmentsGeometry.js",
    "examples/js/lines/LineMaterial.js", "examples/js/lines/LineSegments2.js"};

struct ViewerLibrary {
  std::vector<std::string> scripts;  // the texts of kViewerLibraryFiles, all of them or none
  std::string missing;               // why the viewer cannot be built; empty = every file read

  bool available() const { return missing.empty() && scripts.size() == kViewerLibraryFiles.size(); }
};

// The folder searched: $DRYCUT_THREE_JS_DIR if set, else the build-time default.
std::string viewer_library_dir();

// Reads the files from `dir`; on failure `missing` names the first file that could not be read.
ViewerLibrary load_viewer_library(const std::string& dir = viewer_library_dir());

// Text made safe to sit inside an HTML <script> element: "</script" (any case) would end the
// element and "<!--" changes how it is parsed, so they become "<\/script" and "<\!--", which mean
// the same inside JavaScript strings, regular expressions and comments, the only places they occur.
std::string inline_script_text(const std::string& js);

}  // namespace drycut::report
