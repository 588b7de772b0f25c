#include "interp/modal_state.hpp"

#include <array>
#include <utility>

namespace drycut::interp {
namespace {

// G93/G94/G95: a change of the feed type deletes the tooth feed FZ; selecting the active type
// again keeps it (Fundamentals, "Tooth feedrate (G95 FZ)").
void set_feed_mode(ModalState& s, FeedMode mode) {
  if (s.feed_mode != mode) {
    s.tooth_feed = 0.0;
    s.feed_type_changed = s.feed > 0;  // with no F yet, the first feed block raises 10860 anyway
  }
  s.feed_mode = mode;
}

void set_cutting_speed_mode(ModalState& s, bool constant_cutting_speed, bool lims_acts) {
  s.constant_cutting_speed = constant_cutting_speed;
  s.lims_acts = lims_acts;
}

// Modal codes given by name (reset list and program words alike). G words arrive here as "G64".
using Setter = void (*)(ModalState&);
constexpr std::array<std::pair<std::string_view, Setter>, 76> kCodes{{
    {"G0", [](ModalState& s) { s.motion = MotionMode::Rapid; }},
    {"G1", [](ModalState& s) { s.motion = MotionMode::Linear; }},
    {"G2", [](ModalState& s) { s.motion = MotionMode::ArcCw; }},
    {"G3", [](ModalState& s) { s.motion = MotionMode::ArcCcw; }},
    {"CIP", [](ModalState& s) { s.motion = MotionMode::ArcThroughPoint; }},
    {"CT", [](ModalState& s) { s.motion = MotionMode::ArcTangent; }},
    {"ASPLINE", [](ModalState& s) { s.motion = MotionMode::ASpline; }},
    {"BSPLINE", [](ModalState& s) { s.motion = MotionMode::BSpline; }},
    {"CSPLINE", [](ModalState& s) { s.motion = MotionMode::CSpline; }},
    {"POLY", [](ModalState& s) { s.motion = MotionMode::Polynomial; }},
    {"G17", [](ModalState& s) { s.plane = PlaneSelect::G17; }},
    {"G18", [](ModalState& s) { s.plane = PlaneSelect::G18; }},
    {"G19", [](ModalState& s) { s.plane = PlaneSelect::G19; }},
    {"G90", [](ModalState& s) { s.absolute = true; }},
    {"G91", [](ModalState& s) { s.absolute = false; }},
    {"G70", [](ModalState& s) { s.inch = true; s.feed_in_geometry_unit = false; }},
    {"G71", [](ModalState& s) { s.inch = false; s.feed_in_geometry_unit = false; }},
    {"G700", [](ModalState& s) { s.inch = true; s.feed_in_geometry_unit = true; }},
    {"G710", [](ModalState& s) { s.inch = false; s.feed_in_geometry_unit = true; }},
    // G group 15: a feed type ends G96 (Fundamentals 10.2004, "Constant cutting rate": G96/G961
    // "can also be deactivated with G94 or G95"), and LIMS acts only under G96, G961 and G97
    // (ibid., LIMS). G96 switches feed per revolution on.
    {"G93", [](ModalState& s) { set_feed_mode(s, FeedMode::InverseTime); set_cutting_speed_mode(s, false, false); }},
    {"G94", [](ModalState& s) { set_feed_mode(s, FeedMode::PerMinute); set_cutting_speed_mode(s, false, false); }},
    {"G95", [](ModalState& s) { set_feed_mode(s, FeedMode::PerRevolution); set_cutting_speed_mode(s, false, false); }},
    {"G96", [](ModalState& s) { set_cutting_speed_mode(s, true, true); set_feed_mode(s, FeedMode::PerRevolution); }},
    // G97 is feed per revolution with constant spindle speed ("G97 can be programmed without G96
    // beforehand; it then has the same effect as G95"); G973 the same without LIMS; G961/G971
    // linear feed (as G94); G962/G972 keep the feed type.
    {"G97", [](ModalState& s) { set_cutting_speed_mode(s, false, true); set_feed_mode(s, FeedMode::PerRevolution); }},
    {"G961", [](ModalState& s) { set_cutting_speed_mode(s, true, true); set_feed_mode(s, FeedMode::PerMinute); }},
    {"G962", [](ModalState& s) { set_cutting_speed_mode(s, true, true); }},
    {"G971", [](ModalState& s) { set_cutting_speed_mode(s, false, false); set_feed_mode(s, FeedMode::PerMinute); }},
    {"G972", [](ModalState& s) { set_cutting_speed_mode(s, false, false); }},
    {"G973", [](ModalState& s) { set_cutting_speed_mode(s, false, false); set_feed_mode(s, FeedMode::PerRevolution); }},
    {"G33", [](ModalState& s) { s.motion = MotionMode::Thread; }},
    {"G34", [](ModalState& s) { s.motion = MotionMode::ThreadIncreasing; }},
    {"G35", [](ModalState& s) { s.motion = MotionMode::ThreadDecreasing; }},
    {"G331", [](ModalState& s) { s.motion = MotionMode::Tapping; }},
    {"G332", [](ModalState& s) { s.motion = MotionMode::TappingRetract; }},
    {"G60", [](ModalState& s) { s.transition = TransitionMode::ExactStop; s.smoothing.code = 0; }},
    {"G64", [](ModalState& s) { s.transition = TransitionMode::Continuous; s.smoothing.code = 0; }},
    {"G641", [](ModalState& s) { s.transition = TransitionMode::SmoothDistance; s.smoothing.code = 641; }},
    {"G642", [](ModalState& s) { s.transition = TransitionMode::SmoothTolerance; s.smoothing.code = 642; }},
    {"G643", [](ModalState& s) { s.transition = TransitionMode::SmoothTolerance; s.smoothing.code = 643; }},
    {"G644", [](ModalState& s) { s.transition = TransitionMode::SmoothTolerance; s.smoothing.code = 644; }},
    {"G645", [](ModalState& s) { s.transition = TransitionMode::SmoothTolerance; s.smoothing.code = 645; }},
    {"BRISK", [](ModalState& s) { s.accel = AccelProfile::Brisk; }},
    {"SOFT", [](ModalState& s) { s.accel = AccelProfile::Soft; }},
    {"BNAT", [](ModalState& s) { s.spline_begin = SplineCondition::Natural; }},
    {"BTAN", [](ModalState& s) { s.spline_begin = SplineCondition::Tangent; }},
    {"BAUTO", [](ModalState& s) { s.spline_begin = SplineCondition::Auto; }},
    {"ENAT", [](ModalState& s) { s.spline_end = SplineCondition::Natural; }},
    {"ETAN", [](ModalState& s) { s.spline_end = SplineCondition::Tangent; }},
    {"EAUTO", [](ModalState& s) { s.spline_end = SplineCondition::Auto; }},
    {"G40", [](ModalState& s) { s.compensation = CompensationSide::None; }},
    {"G450", [](ModalState& s) { s.intersection_corners = false; }},
    {"G451", [](ModalState& s) { s.intersection_corners = true; }},
    {"NORM", [](ModalState& s) { s.contour_approach = false; }},
    {"KONT", [](ModalState& s) { s.contour_approach = true; }},
    {"CDON", [](ModalState& s) { s.collision_detection = true; }},
    {"CFC", [](ModalState& s) { s.contour_feed = ContourFeed::Contour; }},
    {"CFTCP", [](ModalState& s) { s.contour_feed = ContourFeed::ToolCentre; }},
    {"CFIN", [](ModalState& s) { s.contour_feed = ContourFeed::InsideOnly; }},
    {"CDOF", [](ModalState& s) { s.collision_detection = false; }},
    {"CDOF2", [](ModalState& s) { s.collision_detection = false; }},
    {"KONTC", [](ModalState& s) { s.contour_approach = true; }},
    {"KONTT", [](ModalState& s) { s.contour_approach = true; }},
    // G group 59: which element of the dynamic machine data applies (machine/dynamic_groups.hpp).
    {"DYNNORM", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::Norm; }},
    {"DYNPOS", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::Pos; }},
    {"DYNROUGH", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::Rough; }},
    {"DYNSEMIFIN", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::SemiFinish; }},
    {"DYNFINISH", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::Finish; }},
    {"DYNPREC", [](ModalState& s) { s.dynamic_group = machine::DynamicGroup::Precision; }},
    {"COMPOF", [](ModalState& s) { s.compressor = Compressor::Off; }},
    {"COMPON", [](ModalState& s) { s.compressor = Compressor::Compon; }},
    {"COMPCURV", [](ModalState& s) { s.compressor = Compressor::Compcurv; }},
    {"COMPCAD", [](ModalState& s) { s.compressor = Compressor::Compcad; }},
    {"COMPSURF", [](ModalState& s) { s.compressor = Compressor::Compsurf; }},
    {"G601", [](ModalState& s) { s.exact_stop_window = 601; }},
    {"G602", [](ModalState& s) { s.exact_stop_window = 602; }},
    {"G603", [](ModalState& s) { s.exact_stop_window = 603; }},
}};

// Modal codes of the reset list that shape nothing drycut plans (feed-forward, FIFO control,
// exact-stop windows ...): accepted so a machine's real MD20150 list can be used as it is.
constexpr std::array<std::string_view, 6> kNoPathEffect{
    "FNORM", "FFWOF", "STARTFIFO", "CUT2D", "SPATH", "G290"};

}  // namespace

bool ModalState::apply_code(std::string_view name) {
  if (const auto mode = channel_diameter_mode(name)) {  // G group 29
    diameter.channel = *mode;
    return true;
  }
  for (const auto& [code, set] : kCodes) {
    if (code == name) {
      set(*this);
      return true;
    }
  }
  for (std::string_view code : kNoPathEffect)
    if (code == name) return true;
  return false;
}

ModalState reset_state(const machine::MachineProfile& profile) {
  ModalState state;
  // MD20100: the transverse axis, which the channel's DIAMON/DIAM90 act on and G96 refers to.
  for (int i = 0; i < 3; ++i)
    if (!profile.diameter_axis.empty() && profile.axes[static_cast<size_t>(i)].name == profile.diameter_axis) {
      state.diameter.transverse_axis = i;
      state.cutting_speed_axis = i;
    }
  for (const auto& code : profile.reset_gcodes) {
    if (code.size() > 1 && code[0] == 'G' && code.find_first_not_of("0123456789", 1) == std::string::npos &&
        code.size() <= 4) {
      if (const int index = settable_frame_index(std::stoi(code.substr(1))); index >= 0) {
        state.work_offset = code;
        state.frames.set_settable(profile_settable_frame(profile, index));
        continue;
      }
    }
    if (!state.apply_code(code))
      throw machine::ProfileError("reset_gcodes: '" + code + "' is not a modal code drycut knows");
  }
  return state;
}

std::string_view motion_mode_name(MotionMode mode) {
  switch (mode) {
    case MotionMode::Rapid: return "G0";
    case MotionMode::Linear: return "G1";
    case MotionMode::ArcCw: return "G2";
    case MotionMode::ArcCcw: return "G3";
    case MotionMode::ArcThroughPoint: return "CIP";
    case MotionMode::ArcTangent: return "CT";
    case MotionMode::ASpline: return "ASPLINE";
    case MotionMode::BSpline: return "BSPLINE";
    case MotionMode::CSpline: return "CSPLINE";
    case MotionMode::Polynomial: return "POLY";
    case MotionMode::Thread: return "G33";
    case MotionMode::ThreadIncreasing: return "G34";
    case MotionMode::ThreadDecreasing: return "G35";
    case MotionMode::Tapping: return "G331";
    case MotionMode::TappingRetract: return "G332";
  }
  return "?";
}

}  // namespace drycut::interp
