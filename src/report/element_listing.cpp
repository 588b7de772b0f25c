#include "report/element_listing.hpp"

#include <filesystem>
#include <string>

namespace drycut::report {
namespace {

const char* kind_name(interp::ElementKind kind) {
  switch (kind) {
    case interp::ElementKind::Line: return "LINE";
    case interp::ElementKind::Arc: return "ARC";
    case interp::ElementKind::SplineSpan: return "SPLINE";
    case interp::ElementKind::Dwell: return "DWELL";
    case interp::ElementKind::Stop: return "STOP";
    case interp::ElementKind::ToolChange: return "TOOL";
    case interp::ElementKind::DynamicsChange: return "DYNAMICS";
    case interp::ElementKind::Positioning: return "POSITION";
    case interp::ElementKind::AxisWait: return "WAIT";
  }
  return "?";
}

const char* transition_name(interp::TransitionMode mode) {
  switch (mode) {
    case interp::TransitionMode::ExactStop: return "G60";
    case interp::TransitionMode::Continuous: return "G64";
    case interp::TransitionMode::SmoothDistance: return "G641";
    case interp::TransitionMode::SmoothTolerance: return "G642";
  }
  return "?";
}

// -0.000 prints as 0.000 so listings are stable across platforms.
double clean(double v) { return std::abs(v) < 5e-7 ? 0.0 : v; }

}  // namespace

void ElementListingWriter::consume(interp::PathElement&& e) {
  // File names without folders keep the listings independent of where the tests run.
  const std::string file = std::filesystem::path(e.source.file_name()).filename().string();
  std::fprintf(out_, "%-8s %-8s", kind_name(e.kind), e.label.c_str());
  if (e.is_motion() && e.curve) {
    const auto a = e.curve->start(), b = e.curve->end();
    std::fprintf(out_, " (%.3f %.3f %.3f) -> (%.3f %.3f %.3f) L=%.4f", clean(a.x()), clean(a.y()), clean(a.z()),
                 clean(b.x()), clean(b.y()), clean(b.z()), e.curve->length());
    if (e.rapid) std::fputs(" RAPID", out_);
    else std::fprintf(out_, " F=%.3f", e.feed_mm_s * 60.0);
    if (e.compensation.side != interp::CompensationSide::None)
      std::fprintf(out_, " %s r=%.3f", e.compensation.side == interp::CompensationSide::Left ? "G41" : "G42",
                   e.compensation.radius_mm);
    for (const auto& m : e.extra_axes) std::fprintf(out_, " %s %.3f%+.3f", m.name.c_str(), clean(m.start), clean(m.travel));
  } else if (e.kind == interp::ElementKind::Dwell) {
    std::fprintf(out_, " %.3f s", e.dwell_s);
  } else if (e.kind == interp::ElementKind::Positioning) {
    for (const auto& m : e.positioning) std::fprintf(out_, " %s %.3f", m.axis.c_str(), m.travel);
  } else if (e.kind == interp::ElementKind::DynamicsChange) {
    std::fprintf(out_, " %s %s", transition_name(e.dynamics.transition),
                 e.dynamics.profile == interp::AccelProfile::Soft ? "SOFT" : "BRISK");
  }
  if (e.dynamics.exact_stop_this_block) std::fputs(" G9", out_);
  std::fprintf(out_, " | %s:%u\n", file.c_str(), e.source.line);
}

}  // namespace drycut::report
