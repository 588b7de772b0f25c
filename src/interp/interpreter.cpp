#include "interp/interpreter.hpp"

#include "interp/interpreter_block.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <optional>
#include <typeinfo>

#include "interp/geometry/arc_solvers.hpp"
#include "interp/feed_rate.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using parser::AddressWord;
using parser::ValueMode;
using namespace detail;

Interpreter::Interpreter(const machine::MachineProfile& profile, ElementSink& sink,
                         Diagnostics& diagnostics, InterpreterOptions options)
    : profile_(profile),
      downstream_(sink),
      corners_(sink, diagnostics),
      sink_(corners_),
      diagnostics_(diagnostics),
      options_(options),
      state_(reset_state(profile)),
      tools_(profile),
      position_(profile.start_position),
      g96_speed_position_(profile.start_position),
      extra_axes_(profile),
      master_spindle_(profile.master_spindle) {
  for (int i = 0; i < kSettableFrames; ++i) {
    settable_components_[static_cast<size_t>(i)] = profile_frame_components(profile, i);
    settable_frames_[static_cast<size_t>(i)] = settable_components_[static_cast<size_t>(i)].frame();
    settable_defined_[static_cast<size_t>(i)] = profile_has_settable_frame(profile, i);
  }
  if (state_.work_offset.size() > 1)  // the frame selected at reset ($P_IFRAME's components)
    if (const int index = settable_frame_index(std::atoi(state_.work_offset.c_str() + 1)); index >= 0)
      active_settable_components_ = settable_components_[static_cast<size_t>(index)];
  last_dynamics_.transition = state_.transition;
  last_dynamics_.profile = state_.accel;
  last_dynamics_.group = state_.dynamic_group;
  last_dynamics_.limits = state_.axis_limits;
  for (size_t i = 0; i < geometry_positioning_feed_.size() && i < profile.axes.size(); ++i)
    geometry_positioning_feed_[i] = profile.axes[i].pos_velocity_mm_s;
}

void Interpreter::raise(const BlockContext& ctx, int number, const std::string& detail,
                        uint32_t column) const {
  throw AlarmError(make_alarm(number, detail, {ctx.file_name(), ctx.block.line, column}, ctx.block.text));
}

void Interpreter::warn_once(const BlockContext& ctx, const std::string& what, uint32_t column) {
  warn_once(ctx, kNotModelled, what, column);
}

void Interpreter::warn_once(const BlockContext& ctx, int number, const std::string& what, uint32_t column) {
  if (!warned_.insert(what).second) return;
  diagnostics_.warn(number, what, {ctx.file_name(), ctx.block.line, column}, ctx.block.text);
}

void Interpreter::execute(const parser::Block& block) {
  if (ended_) return;
  if (block.modal_save != parser::ModalSave::None) {
    apply_modal_save(block.modal_save);
    return;
  }
  GeometryPositioning mode = GeometryPositioning::None;
  // Only POS/POSA words can make one (most blocks have none: no std::optional<Block> for them).
  if (!block.axis_words.empty()) {
    if (auto moved = geometry_positioning_block(block, mode)) {
      execute_block(*moved, mode);
      return;
    }
  }
  execute_block(block, GeometryPositioning::None);
}

void Interpreter::execute_block(const parser::Block& block, GeometryPositioning geometry_positioning) {
  corners_.begin_block();
  BlockContext ctx(block);
  ctx.geometry_positioning = geometry_positioning;
  if (geometry_positioning == GeometryPositioning::WithPath)
    warn_once(ctx, "POS/POSA of a geometry axis in a block with path axes (it moves with the path, at the path feed)", 0);
  if (geometry_positioning == GeometryPositioning::AloneAsync)
    warn_once(ctx, "POSA of a geometry axis (planned as POS: the program waits for the axis instead of running on)", 0);
  // Only a compressor asks (a block that selects one is no simple block itself), and the test
  // runs on every block.
  ctx.simple = state_.compressor != Compressor::Off && is_simple_block(block, extra_axes_);
  ctx.compensation_before = state_.compensation;
  if (clock_wait_s_ > 0) emit_clock_wait(ctx);
  if (block.main_run_read) {
    // The stop comes after everything before the read, a spline run's pending spans included.
    if (spline_.active()) end_spline_run(nullptr);
    emit_preprocessing_stop(ctx, "STOPRE (implicit: main-run variable read)");
  }
  // The passes over words a block may not have are skipped here: each is a loop over its words,
  // and the call alone costs a CAM block more than the test.
  if (!block.system_writes.empty()) apply_system_writes(block);
  apply_g_words(ctx);
  if (!block.commands.empty()) apply_commands(ctx);
  ctx.feed_before = state_.feed;
  apply_addresses(ctx);
  if (!block.axis_words.empty()) apply_axis_words(ctx);
  if (!block.m.empty()) apply_m_words(ctx);
  if (spindle_left_to_changer_) note_spindle_programmed(block);
  note_spindle_change();
  // G63 (tapping with a compensating chuck; Fundamentals, "Tapping with compensating chuck
  // (G63)") is non-modal: its block runs linear at F (at a fixed 100 % override, as drycut plans
  // anyway), and the motion command in force before it (often the G0 of the approach) applies
  // again from the next block.
  const MotionMode modal_motion = state_.motion;
  // A SAR block (G147 ... G348, non-modal) runs its own contour, whatever group 1 says.
  if (ctx.tapping_chuck || ctx.smooth_approach) state_.motion = MotionMode::Linear;
  execute_motion(ctx, modal_motion);
  if (ctx.tapping_chuck || ctx.smooth_approach) state_.motion = modal_motion;
  if (ctx.stop == StopKind::ProgramStop || ctx.stop == StopKind::OptionalStop) settle_spindles_at_stop();
  warn_unused_corner(ctx);
  if (!ctx.simple) block_between_compressible_ = true;
}

void Interpreter::apply_modal_save(parser::ModalSave what) {
  // SAVE gives back the modal G functions and frames of the call (PGA Job Planning "SAVE"); the
  // feed, the spindle and the tool are not modal G functions and stay as the subprogram left them.
  if (what == parser::ModalSave::Save) {
    saved_states_.push_back(state_);
    return;
  }
  if (saved_states_.empty()) return;
  ModalState restored = std::move(saved_states_.back());
  saved_states_.pop_back();
  restored.feed = state_.feed;
  restored.feed_unit_mm = state_.feed_unit_mm;
  restored.tooth_feed = state_.tooth_feed;  // like F
  restored.tooth_feed_unit_mm = state_.tooth_feed_unit_mm;
  restored.spindle_rpm = state_.spindle_rpm;
  restored.cutting_speed = state_.cutting_speed;
  restored.spindle_speed_limit = state_.spindle_speed_limit;  // LIMS writes a setting datum, no G code
  restored.spindle = state_.spindle;
  // The caller's G97 (or G94/G95) coming back over the subprogram's G96 ends it as a G97 would:
  // the spindle keeps the speed it has (drycut's reading [I]; docs/controller-state.md).
  if (state_.constant_cutting_speed && !restored.constant_cutting_speed && state_.spindle != SpindleState::Stopped)
    restored.spindle_rpm = std::abs(actual_spindle_speed(0));
  restored.thread_lead_mm = state_.thread_lead_mm;
  restored.thread_lead_axis = state_.thread_lead_axis;
  state_ = std::move(restored);
}

void Interpreter::apply_g_words(BlockContext& ctx) {
  // G97 (G971, G972, G973) or a feed type G93/G94/G95 after G96 freezes the speed the spindle has
  // at the block start (an S in the block replaces it later).
  const bool was_g96 = state_.constant_cutting_speed;
  const FeedMode feed_before = state_.feed_mode;
  const bool ends_g96 = ends_constant_cutting_speed(ctx.block);
  const double frozen_speed = was_g96 && ends_g96 ? spindle_speed(ctx) : -1.0;
  int group1 = -1;
  for (const auto& g : ctx.block.g) {
    const int code = g.code;
    if (code >= 0 && code <= 3) {
      if (group1 >= 0 && group1 != code)
        raise(ctx, 12070, "G" + std::to_string(group1) + " and G" + std::to_string(code), g.column);
      group1 = code;
      ctx.motion_code = true;
      // What apply_code("G0".."G3") sets (kCodes, modal_state.cpp), without building the name
      // and searching the code table by it on every motion block.
      static constexpr MotionMode kGroup1[] = {MotionMode::Rapid, MotionMode::Linear, MotionMode::ArcCw,
                                               MotionMode::ArcCcw};
      state_.motion = kGroup1[code];
      continue;
    }
    switch (code) {
      case 4: ctx.dwell = true; continue;
      case 25: case 26: ctx.speed_limit = code; continue;
      case 9: ctx.exact_stop = true; continue;
      case 53: case 153: ctx.suppress_offsets = true; continue;
      case 74: case 75: ctx.home_move = code; continue;
      case 147: case 148: case 247: case 248: case 347: case 348: ctx.smooth_approach = code; continue;
      case 140: case 141: case 142: case 143: state_.sar_side_rule = code; continue;
      case 340: case 341: state_.sar_in_plane = code == 341; continue;
      case 58: case 59: ctx.axial_offset = code; continue;
      case 110: ctx.pole = PoleReference::LastPosition; continue;
      case 111: ctx.pole = PoleReference::WorkpieceZero; continue;
      case 112: ctx.pole = PoleReference::LastPole; continue;
      case 17: case 18: case 19: {
        const PlaneSelect before = state_.plane;
        state_.apply_code("G" + std::to_string(code));
        if (state_.plane != before && state_.compensation != CompensationSide::None)
          raise(ctx, 10757, "", g.column);
        if (state_.plane != before) state_.polar.plane_changed();
        continue;
      }
      case 41: case 42: {
        // Checked in execute_motion: a D in the same block counts (the control applies D first).
        if (state_.compensation == CompensationSide::None) compensation_selection_pending_ = true;
        state_.compensation = code == 41 ? CompensationSide::Left : CompensationSide::Right;
        ctx.compensation_changed = true;
        ctx.compensation_column = g.column;
        continue;
      }
      case 40:
        compensation_selection_pending_ = false;
        state_.compensation = CompensationSide::None;
        ctx.compensation_changed = true;
        ctx.compensation_column = g.column;
        continue;
      case 500: case 54: case 55: case 56: case 57: select_settable_frame(ctx, code, g.column); continue;
      case 601: case 602: case 603:  // exact-stop window: no effect on the planned set-point
        state_.exact_stop_window = code;
        continue;
      case 63: ctx.tapping_chuck = true; continue;
      case 291:
        // ISO dialect mode (an option of the control): G, M and addresses mean other things there
        // (G70 cycle, M98 call, R radius, #100 variables); read as Siemens code they would give a
        // wrong path without a word. drycut reads Siemens mode only, so it stops here.
        raise(ctx, kUnsupported, "G291 (ISO dialect mode): drycut reads only the Siemens language (G290)", g.column);
      case 644:
        // Rounding with the axes' largest dynamics: no rounding element modelled, planned as G64.
        state_.apply_code("G644");
        warn_once(ctx, "G644 (smoothing with maximum dynamics: planned as G64)", g.column);
        continue;
      default:
        if (settable_frame_index(code) >= 0) {
          select_settable_frame(ctx, code, g.column);
          continue;
        }
        break;
    }
    if (state_.apply_code("G" + std::to_string(code))) continue;
    warn_once(ctx, "G" + std::to_string(code), g.column);
  }
  if (ends_g96) combine_feed_type_and_speed_mode(ctx);
  if (frozen_speed >= 0 && !state_.constant_cutting_speed && state_.spindle != SpindleState::Stopped)
    state_.spindle_rpm = frozen_speed;
  if (ends_g96) note_group15_change(ctx, was_g96, feed_before, frozen_speed);
}

void Interpreter::apply_commands(BlockContext& ctx) {
  for (const auto& c : ctx.block.commands) {
    const std::string& n = c.name;
    if (n == "ASPLINE" || n == "BSPLINE" || n == "CSPLINE" || n == "CIP" || n == "CT" || n == "POLY") {
      ctx.motion_code = true;
      state_.apply_code(n);
    } else if (auto kind = frame_instruction_kind(n)) {
      ctx.frame_instruction = kind;
      ctx.additive_frame = n[0] == 'A';
    } else if (n == "SUPA") {
      ctx.suppress_offsets = true;
    } else if (n == "STOPRE") {
      ctx.preprocessing_stop = true;
    } else if (n == "SPLINEPATH") {
      // Only spline group 1 over X, Y, Z is modelled; other axis sets would change the path.
      for (size_t i = 1; i < c.args.size(); ++i) {
        const auto* axis = std::get_if<std::string>(&c.args[i]);
        if (!axis || axis_index(*axis) < 0)
          raise(ctx, kUnsupported, "SPLINEPATH with axes other than X, Y, Z", c.column);
      }
    } else if (n == "SETMS") {
      set_master_spindle(ctx, c);
    } else if (n == "TCA") {
      change_tool_regardless_of_status(ctx, c);
    } else if (n == "DRYCUT_CONTOUR_BEGIN" || n == "DRYCUT_CONTOUR_END") {
      record_contour(ctx, n == "DRYCUT_CONTOUR_BEGIN", c.column);
    } else if (n == "MSG") {
      // A message on the operator screen: nothing to simulate.
    } else if (n == "RET") {
      // The return itself is the loader's (it leaves the subprogram after this block).
    } else if (n == "TCOABS" || n == "TCOFR" || n == "TCOFRX" || n == "TCOFRY" || n == "TCOFRZ") {
      orient_tool(ctx, n, c.column);
    } else if (n == "KONTC" || n == "KONTT") {
      state_.apply_code(n);
      warn_once(ctx, n + " (approach/retract on a polynomial: planned as KONT)", c.column);
    } else if (apply_axis_command(ctx, c)) {
      // FGROUP, WAITP, WAITS (interpreter_axes.cpp)
    } else if (apply_transformation_command(c)) {
      // TRANSMIT, TRACYL, TRAANG, TRAORI, TRAFOOF (transformation_limits.cpp)
    } else if (apply_turning_command(ctx, c)) {
      // diameter programming, SCC (interpreter_turning.cpp)
    } else if (!state_.apply_code(n)) {
      warn_once(ctx, n, c.column);
    }
  }
}

void Interpreter::apply_addresses(BlockContext& ctx) {
  if (!ctx.block.m.empty()) note_tool_change_m_words(ctx);  // (a pass over the M words)
  // T="name" is not an address word: program it before the words so that a D in the same block
  // (`T="BALL_R3" D1`, as posts write it) belongs to the prepared tool, as with `T1 D1`.
  if (ctx.block.tool_name) {
    if (const int n = ctx.block.tool_name_spindle; n > 0 && n != master_spindle())
      warn_once(ctx, "T" + std::to_string(n) + "= (a tool for spindle " + std::to_string(n) +
                         ", not the master spindle: not simulated)", 0);
    else
      program_tool(ctx, *ctx.block.tool_name, 0);
  }
  for (const AddressWord& a : ctx.block.addresses) {
    const std::string_view n = a.name;  // compared with literals inline, without strlen
    // X, Y, Z in a linear value mode (most words of a CAM program) are target_position's alone:
    // no rule below takes them, unless an extra axis bears the name.
    if (axis_index(n) >= 0 && parser::is_linear_value_mode(a.mode) && extra_axes_.index(n) < 0) continue;
    if (apply_smoothing_address(ctx, a)) continue;
    if (apply_corner_address(ctx, a)) continue;
    if (apply_smooth_approach_address(ctx, a)) continue;
    if (n == "F") {
      apply_feed_address(ctx, a);
    } else if (n == "FZ") {
      apply_tooth_feed(ctx, a);
    } else if (n == "ANG") {
      // The contour angle: target_position uses it (interpreter_coordinates.cpp).
    } else if (n == "SVC") {
      apply_cutting_speed(ctx, a);
    } else if (n == "FB") {
      // Non-modal feed (Fundamentals, "Non-modal feedrate (FB)"): this block's feed, in the
      // active feed type; the modal F applies again in the next block.
      if (a.value < kMinFeed) raise(ctx, 14800, "FB=" + std::to_string(a.value), a.column);
      ctx.nonmodal_feed = a.value;
    } else if (n == "S" || numbered_spindle(n) > 0) {
      apply_spindle_speed(ctx, a);
    } else if (n.starts_with("LIMS")) {
      apply_speed_limit_lims(ctx, a);
    } else if (n == "SF") {
      // Thread start angle: shifts where the thread starts on the circumference, not its time.
    } else if (n == "OVR") {
      if (a.value != 100.0) warn_once(ctx, "OVR (drycut plans at 100 % override)", a.column);
    } else if (n[0] == 'T' && n.find_first_not_of("0123456789", 1) == std::string::npos) {
      apply_tool_address(ctx, a);
    } else if (n == "D") {
      apply_edge_address(ctx, a);
    } else if (n == "SD") {
      if (a.value != 2 && a.value != 3) raise(ctx, 12160, "SD must be 2 or 3", a.column);
      state_.bspline_degree = static_cast<int>(a.value);
    } else if (n == "OFFN") {
      // Programmed contour offset (Fundamentals, "Tool radius compensation, OFFN"): the offset
      // path lies OFFN further out, as with a tool that much larger.
      state_.offn_mm = a.value * geometry_unit();
    } else if (n == "DISC") {
      if (a.value < 0 || a.value > 100) raise(ctx, 12160, "DISC must be 0..100", a.column);
      state_.disc = a.value;
      // DISC > 0 lets the G450 transition circle deviate towards the intersection (Fundamentals,
      // "Corner behavior G450/G451, DISC"); drycut keeps the plain circle (cutter_compensation.hpp).
      if (a.value > 0) warn_once(ctx, "DISC>0 (the G450 transition stays the plain circle, as DISC=0)", a.column);
    } else if (!parser::is_linear_value_mode(a.mode) && extra_axes_.index(n) < 0 && !is_axis_letter_name(n)) {
      // DC/ACP/ACN choose the way of a rotary axis: on X, Y, Z and non-axis words the control
      // refuses them (an extra axis the profile lacks is a warning below; a linear one: 168xx).
      const int number = a.mode == ValueMode::Direct ? 16800 : a.mode == ValueMode::AbsolutePositive ? 16810 : 16820;
      raise(ctx, number, a.name + " is not a rotary axis", a.column);
    } else {
      note_extra_axis_word(ctx, a);
    }
  }
}

// ADIS=, ADISPOS= (G641 and MD20480 digit 4), CTOL=, ATOL[ax]= (G642..G645 and the compressor):
// modal; a negative tolerance restores the machine/setting data value (PGA "CTOL, OTOL, ATOL").
bool Interpreter::apply_smoothing_address(BlockContext& ctx, const AddressWord& a) {
  const std::string_view n = a.name;
  SmoothingRequest& s = state_.smoothing;
  if (n == "ADIS" || n == "ADISPOS") {
    double v = a.value * geometry_unit();
    if (v < 0) {
      warn_once(ctx, std::string(n) + " < 0 (taken as 0)", a.column);
      v = 0;
    }
    (n == "ADIS" ? s.adis_mm : s.adispos_mm) = v;
    return true;
  }
  if (n == "CTOL") {
    s.ctol_mm = a.value < 0 ? -1.0 : a.value * geometry_unit();
    return true;
  }
  if (!n.starts_with("ATOL[")) return false;
  const std::string axis(n.substr(5, n.size() - 6));
  const int i = axis_index(axis);
  if (i < 0) {
    warn_once(ctx, "ATOL[" + axis + "] (tolerance of an axis drycut does not smooth)", a.column);
    return true;
  }
  s.atol_mm[i] = a.value < 0 ? -1.0 : a.value * geometry_unit();
  return true;
}

void Interpreter::program_tool(BlockContext& ctx, const std::string& id, uint32_t column) {
  std::vector<ToolNotice> notices;
  if (tools_.program_tool(id, notices)) ctx.tool_change = true;  // MD22550 = 0: T changes
  report_tool_notices(ctx, notices, column);
}

void Interpreter::apply_m_words(BlockContext& ctx) {
  for (const auto& m : ctx.block.m) {
    // M<n>=3/4/5/19/70: spindle n. Another spindle than the master keeps its direction (G4
    // S<n>=, SETMS); its positioning (M<n>=19, M<n>=70) is not simulated.
    const bool spindle_function = (m.code >= 3 && m.code <= 5) || m.code == 19 || m.code == 70;
    if (m.extension > 0 && m.extension != master_spindle_ && spindle_function) {
      if (m.code >= 3 && m.code <= 5)
        other_spindles_[m.extension].state = m.code == 3   ? SpindleState::Clockwise
                                             : m.code == 4 ? SpindleState::CounterClockwise
                                                           : SpindleState::Stopped;
      else
        warn_once(ctx, "M" + std::to_string(m.extension) + "=" + std::to_string(m.code) +
                           " (positioning of a spindle other than the master is not simulated)", m.column);
      continue;
    }
    switch (m.code) {
      case 0: ctx.stop = StopKind::ProgramStop; break;
      case 1: if (options_.optional_stop_active) ctx.stop = StopKind::OptionalStop; break;
      case 2: case 30: ctx.stop = StopKind::ProgramEnd; break;
      case 3: state_.spindle = SpindleState::Clockwise; break;
      case 4: state_.spindle = SpindleState::CounterClockwise; break;
      case 70:  // the master spindle to axis mode (Function Manual S1, "Spindle modes")
        warn_once(ctx, "M70 (the master spindle's change to axis mode: braked as by M5, the switch-over itself is not timed)",
                  m.column);
        [[fallthrough]];
      case 5:
        // M5 does not wait for the spindle: it brakes (MD35200) while the program goes on; an
        // SPOS/M19 before it stands finds it still turning (add_spindle_positioning).
        if (const double rpm = std::abs(actual_spindle_speed(0)); rpm > 0) master_braking_ = {nominal_time_s_, rpm};
        state_.spindle = SpindleState::Stopped;
        break;
      case 19: {
        // M19: the master spindle goes to SD43240 M19_SPOS (default 0°) in the mode of SD43250
        // (default DC, the shortest way), as SPOS would (Function Manual S1, "Spindle positioning
        // with M19"); another mode of SD43250 is not modelled.
        parser::AxisWord w;
        w.kind = parser::AxisWordKind::SPos;
        w.mode = ValueMode::Direct;
        w.column = m.column;
        if (auto it = profile_.machine_data.find("$SA_M19_SPOS"); it != profile_.machine_data.end()) w.value = it->second;
        add_spindle_positioning(ctx, w);
        break;
      }
      default: break;  // M17 is the loader's; coolant and PLC functions take no path time
    }
    // MD22560: the M function that changes the tool when MD22550 = 1.
    // (MD22560, the change M function, is seen by apply_addresses: a D beside it is the new tool's.)
  }
}

void Interpreter::report_tool_notices(const BlockContext& ctx, const std::vector<ToolNotice>& notices,
                                      uint32_t column) {
  for (const ToolNotice& n : notices) {
    if (n.alarm) raise(ctx, n.number, n.detail, column);
    warn_once(ctx, n.number, n.detail, column);
  }
}

void Interpreter::change_tool(BlockContext& ctx) {
  std::optional<int> d;
  uint32_t column = 0;
  if (const AddressWord* word = ctx.block.find_address("D")) {
    d = static_cast<int>(word->value);  // range checked with the addresses
    column = word->column;
  }
  std::vector<ToolNotice> notices;
  const std::optional<std::string> before = tools_.active_tool();
  tools_.change_tool(d, notices);
  report_tool_notices(ctx, notices, column);
  speed_from_cutting_speed(ctx, column);  // SVC: the new tool's radius
  const std::string tool = tools_.active_tool().value_or("0");
  const std::string label =
      tools_.change_on_m_code() ? "M" + std::to_string(tools_.change_m_code()) + " " + tool : "T " + tool;
  // The tool in the spindle (turret) already: nothing is changed, no change time (CAM posts
  // repeat T1 M6 for the next operation with the same tool, or name it T="..." once and T1 once);
  // the motion stops as at a change.
  if (before && tools_.active_tool() && tools_.same_tool(*before, *tools_.active_tool())) {
    emit_control(ctx, ElementKind::Dwell, label + " (in the spindle already)");
    return;
  }
  emit_control(ctx, ElementKind::ToolChange, label);
}

double Interpreter::geometry_unit() const { return state_.inch ? kMmPerInch : 1.0; }

double Interpreter::feed_unit() const {
  // G700/G710: F in the geometry's unit; G70/G71: F stays in the base system (MD10240).
  const bool inch = state_.feed_in_geometry_unit ? state_.inch : profile_.base_unit_inch;
  return inch ? kMmPerInch : 1.0;
}

PathElement Interpreter::element_template(const BlockContext& ctx, ElementKind kind) {
  PathElement e;
  e.kind = kind;
  e.source = std::move(spare_source_);  // its text buffer takes the block text (emit)
  e.source.file = ctx.block.file;
  e.source.line = ctx.block.line;
  e.source.text.assign(ctx.block.text);
  e.dynamics.transition = state_.transition;
  e.smoothing = state_.smoothing;
  e.dynamics.profile = state_.accel;
  e.dynamics.group = state_.dynamic_group;
  e.dynamics.limits = state_.axis_limits;
  e.dynamics.exact_stop_this_block = ctx.exact_stop;
  e.geometry_feed_axes = extra_axes_.geometry_feed_axes();
  e.corner.program_level = ctx.block.program_level;
  e.compensation.side = state_.compensation;
  // A mirror in the plane swaps the sides: G41 on the programmed contour is right of the mirrored one.
  if (e.compensation.side != CompensationSide::None && frame_mirrors_plane(block_frame(ctx)))
    e.compensation.side = e.compensation.side == CompensationSide::Left ? CompensationSide::Right : CompensationSide::Left;
  e.compensation.radius_mm = tools_.offsets().radius_mm + state_.offn_mm;
  e.compensation.intersection_corners = state_.intersection_corners;
  e.compensation.contour_approach = state_.contour_approach;
  e.compensation.collision_detection = state_.collision_detection;
  e.compensation.contour_feed = state_.contour_feed;
  e.compensation.disc = state_.disc;
  e.compensation.plane_normal_axis = state_.plane_normal_axis();
  tilt_compensation_plane(ctx, e.compensation);
  if (e.compensation.side != CompensationSide::None) e.compensation.reference_shift = edge_reference_shift(e.compensation);
  return e;
}

void Interpreter::start_thread_block(BlockContext& ctx) {
  // The lead: I (X), J (Y) or K (Z) of this block, else the last one (chained threads).
  const char* names[3] = {"I", "J", "K"};
  for (int i = 0; i < 3; ++i) {
    if (const AddressWord* a = ctx.block.find_address(names[i])) {
      state_.thread_lead_mm = std::abs(a->value) * geometry_unit();  // G331: the sign is the direction
      state_.thread_lead_axis = i;
    }
  }
  // A chain of thread blocks of one kind runs on without a new run-up; G331 -> G332 reverses.
  if (thread_chain_ == state_.motion) return;
  // Rigid tapping (G331/G332): the axis follows the spindle's ramps in position control
  // (MD35210, planned as the lead axis's acceleration: limit_tapping_acceleration), the reversal
  // at the depth included; nothing waits. The run-up dwell is for threads cut with the spindle
  // in speed control (G33, G34, G35).
  if (state_.motion == MotionMode::Tapping || state_.motion == MotionMode::TappingRetract) return;
  if (profile_.spindle_ramp_time_s <= 0) return;
  PathElement e = element_template(ctx, ElementKind::Dwell);
  e.dwell_s = profile_.spindle_ramp_time_s;
  e.label = "spindle ramp";
  emit(std::move(e));
}

void Interpreter::emit(PathElement&& element) {
  if (sar_pending_ && !sar_releasing_ && hold_for_smooth_approach(element)) return;
  if (run_up_.pending && element.is_motion() && !element.rapid) wait_for_spindle_speed(element);
  if (run_up_mark_ != 0) element.run_up_start = std::exchange(run_up_mark_, 0);
  if (compensation_selection_pending_ && element.is_motion() && element.curve) defer_compensation_selection(element);
  add_nominal_time(element);
  if (element.kind == ElementKind::ToolChange) note_tool_change_stops_spindle();
  if (element.is_motion() && element.curve && element.curve->length() > 0) {
    last_tangent_ = element.curve->at(element.curve->length()).tangent;
    has_last_tangent_ = true;
  }
  if (element.is_motion() && element.curve) note_compensated_end(element);
  if (state_.constant_cutting_speed && element.is_motion() && !element.rapid && element.curve)
    g96_speed_position_ = element.curve->end();
  sink_.consume(std::move(element));
  spare_source_ = std::move(element.source);
  if (element.curve) spare_curve_ = std::move(element.curve);
}

geometry::CurvePtr Interpreter::line_curve(const Vector3d& a, const Vector3d& b) {
  // Only a spare held by nobody else may change (use_count 1: the worker that handed it back
  // released its references before the batch came back, under the pipeline's lock).
  if (spare_curve_ && spare_curve_.use_count() == 1 && typeid(*spare_curve_) == typeid(geometry::LineCurve)) {
    // Built by make_shared<LineCurve> (not const), so it may be written through a const_cast.
    *const_cast<geometry::LineCurve*>(static_cast<const geometry::LineCurve*>(spare_curve_.get())) =
        geometry::LineCurve(a, b);
    return std::move(spare_curve_);
  }
  return std::make_shared<geometry::LineCurve>(a, b);
}

void Interpreter::defer_compensation_selection(PathElement& element) {
  // W1 "Tool radius compensation": a selection block that programs no axis of the working plane
  // (G41 G1 Z-3) selects nothing; the compensation starts with the next block that does, which
  // becomes the approach. One that names them where the tool stands selects: its approach has
  // no length and ends beside the next element's start. (Under a tilting frame the plane is the
  // tilted one: not deferred.)
  if (element.compensation.side == CompensationSide::None || element.compensation.tilted ||
      element.kind != ElementKind::Line) {
    compensation_selection_pending_ = false;
    return;
  }
  const PlaneIndices plane = state_.plane_indices();
  const Eigen::Vector3d d = element.curve->end() - element.curve->start();
  if (block_names_plane_axis_ || std::hypot(d[plane.first], d[plane.second]) > 1e-9) {
    compensation_selection_pending_ = false;
    return;
  }
  element.compensation.side = CompensationSide::None;
}

void Interpreter::emit_control(BlockContext& ctx, ElementKind kind, std::string label) {
  PathElement e = element_template(ctx, kind);
  e.label = std::move(label);
  emit(std::move(e));
}

void Interpreter::check_limits(const BlockContext& ctx, const Vector3d& target) {
  if (!limits_checked(ctx)) return;
  if (const auto violation = limit_violation(target)) raise(ctx, 10720, *violation);
}

std::optional<std::string> Interpreter::limit_violation(const Vector3d& p) const {
  for (int i = 0; i < 3; ++i) {
    const auto& axis = profile_.axes[static_cast<size_t>(i)];
    if (p[i] < axis.min_mm - 1e-9 || p[i] > axis.max_mm + 1e-9) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "axis %s at %.3f mm, limits %.3f .. %.3f mm", axis.name.c_str(), p[i],
                    axis.min_mm, axis.max_mm);
      return std::string(buf);
    }
  }
  return std::nullopt;
}

void Interpreter::refuse_compensation_change_on_curve(const BlockContext& ctx, bool moves) const {
  // G41/G42 are selected and G40 deselected in a straight block only (Function Manual W1, "Tool
  // radius compensation": selection with G0 or G1): in a circle, spline or polynomial block the
  // control stops with 10753 / 10754 (the compensation has no start or end point to go from).
  const bool curve = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw ||
                     state_.motion == MotionMode::ArcThroughPoint || state_.motion == MotionMode::ArcTangent ||
                     state_.motion == MotionMode::ASpline || state_.motion == MotionMode::BSpline ||
                     state_.motion == MotionMode::CSpline || state_.motion == MotionMode::Polynomial;
  // Selected in a block that programs no axis of the plane (G41 G1 Z-2), the compensation starts with
  // the next block that does: that block is the selection block, so a circle there is
  // refused as in the G41 block itself (drycut's reading of the rule; it ran the circle as a
  // straight approach, or a full circle uncompensated, silently).
  if (compensation_selection_pending_ && !ctx.compensation_changed && moves && curve &&
      state_.compensation != CompensationSide::None)
    raise(ctx, 10753, "the first block that moves in the plane after G41/G42 is not G0/G1", 0);
  if (!ctx.compensation_changed || !moves || !curve) return;
  const bool was_on = ctx.compensation_before != CompensationSide::None;
  const bool is_on = state_.compensation != CompensationSide::None;
  if (!was_on && is_on) raise(ctx, 10753, "G41/G42 in a block that is not G0/G1", ctx.compensation_column);
  if (was_on && !is_on) raise(ctx, 10754, "G40 in a block that is not G0/G1", ctx.compensation_column);
}

// Dynamics changes are told to the planner once, where they happen.
void Interpreter::emit_dynamics_change(BlockContext& ctx) {
  if (state_.transition != last_dynamics_.transition || state_.accel != last_dynamics_.profile ||
      state_.dynamic_group != last_dynamics_.group || state_.axis_limits != last_dynamics_.limits) {
    last_dynamics_.transition = state_.transition;
    last_dynamics_.profile = state_.accel;
    last_dynamics_.group = state_.dynamic_group;
    last_dynamics_.limits = state_.axis_limits;
    emit_control(ctx, ElementKind::DynamicsChange, "dynamics");
  }
}

bool Interpreter::execute_axis_instruction(BlockContext& ctx) {
  if (ctx.frame_instruction) {
    apply_frame_instruction(ctx);
    return true;
  }
  if (ctx.axial_offset) {
    apply_axial_offset(ctx);
    return true;
  }
  if (ctx.speed_limit) {
    warn_working_area(ctx);
    return true;
  }
  if (ctx.pole) {
    define_pole(ctx);
    return true;
  }
  if (ctx.home_move) {
    move_to_fixed_point(ctx);
    return true;
  }
  return false;
}

void Interpreter::execute_motion(BlockContext& ctx, MotionMode modal_motion) {
  if (ctx.compensation_changed && state_.compensation != CompensationSide::None && !tools_.has_tool())
    raise(ctx, 10750, "no tool is active", ctx.compensation_column);
  emit_dynamics_change(ctx);
  block_names_plane_axis_ = false;
  if (execute_axis_instruction(ctx)) return;
  if (const AddressWord* fp = ctx.find_named("FP"))
    warn_once(ctx, "FP= without G75 (it selects the fixed point of G75 only)", fp->column);
  bool has_axis = false, has_plane_axis = false;  // the latter: an axis of the plane, or a polar word
  const PlaneIndices plane = state_.plane_indices();
  for (const AddressWord& a : ctx.block.addresses) {
    const std::string_view n = a.name;  // compared with literals by length first, not a memcmp each
    const int i = axis_index(n);
    const bool polar = n == "AP" || n == "RP";
    has_axis = has_axis || i >= 0 || polar;
    has_plane_axis = has_plane_axis || i == plane.first || i == plane.second || polar;
  }
  if (hold_contour_angle(ctx, has_axis)) return;
  if (held_angle_deg_ && has_axis) run_to_contour_corner(ctx);
  const bool arc_mode = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw;
  // A full circle needs no end point: G2 I10 is a motion block.
  const bool full_circle = arc_mode && !has_axis &&
                           (ctx.block.find_address("I") || ctx.block.find_address("J") ||
                            ctx.block.find_address("K") || ctx.block.find_address("AR"));
  block_names_plane_axis_ = has_plane_axis;
  refuse_compensation_change_on_curve(ctx, has_axis || full_circle);

  const bool stops = ctx.dwell || ctx.tool_change || ctx.stop || ctx.preprocessing_stop;
  // The dwell's words are checked before the block moves: a refused block adds nothing. (On
  // the heap: an empty std::optional<PathElement> still clears its storage on every block.)
  std::unique_ptr<PathElement> dwell;
  if (ctx.dwell) dwell = std::make_unique<PathElement>(dwell_element(ctx));
  if (!ctx.waits.empty()) emit_axis_waits(ctx);  // (tested here: most blocks wait for no axis)
  std::vector<ExtraAxisMove> extra;
  if (!ctx.extra_words.empty()) extra = take_extra_axis_moves(ctx);

  if (ctx.geometry_positioning == GeometryPositioning::Alone || ctx.geometry_positioning == GeometryPositioning::AloneAsync) {
    position_geometry_axes(ctx, std::move(extra));
  } else if (ctx.smooth_approach && (has_axis || ctx.smooth_approach % 10 == 7)) {
    if (!extra.empty()) warn_once(ctx, "extra axes in a smooth approach/retraction block (they move without time)", 0);
    execute_smooth_approach(ctx, modal_motion);
  } else if (has_axis || full_circle) {
    move_to_target(ctx, std::move(extra));
  } else if (!extra.empty() && state_.spline_mode()) {
    warn_once(ctx, "extra axes in spline blocks (they move without time)", 0);
  } else if (!extra.empty()) {
    // Only extra axes: a straight move of them alone (in G2/G3 too: no circle without a geometry end point).
    if (spline_.active()) end_spline_run(nullptr);
    PathElement e = build_line(ctx, position_);
    if (e.label != "G0") e.label = "G1";
    attach_extra_axes(ctx, e, std::move(extra));
    emit(std::move(e));
  } else if (stops && spline_.active()) {
    end_spline_run(nullptr);
  }
  if (!ctx.positioning.empty()) emit_positioning(ctx);
  if (has_axis || full_circle) thread_chain_ = state_.thread_mode() ? std::optional(state_.motion) : std::nullopt;
  if (!state_.spline_mode()) quota_.stop();
  if (quota_.active() && !quota_.record(has_axis))
    raise(ctx, 990001, std::to_string(quota_.in_window()) + " of 10, " + std::to_string(quota_.required()) + " required");

  if (dwell) emit(std::move(*dwell));
  emit_block_end(ctx);
}

void Interpreter::emit_preprocessing_stop(BlockContext& ctx, const char* label) {
  // The path comes to rest: the blocks before it run to their end before preparation goes on.
  PathElement e = element_template(ctx, ElementKind::Stop);
  e.stop = StopKind::Preprocessing;
  e.label = label;
  emit(std::move(e));
}

void Interpreter::emit_block_end(BlockContext& ctx) {
  // What a block does after its motion: tool change, STOPRE, M0/M1/M2/M30.
  if (ctx.tool_change) {
    change_tool(ctx);
    if (spindle_left_to_changer_) note_spindle_programmed(ctx.block);  // T1 M6 S1000 M3
  }
  if (ctx.preprocessing_stop) emit_preprocessing_stop(ctx, "STOPRE");
  if (ctx.stop) {
    if (spline_.active()) end_spline_run(nullptr);
    PathElement e = element_template(ctx, ElementKind::Stop);
    e.stop = *ctx.stop;
    e.label = *ctx.stop == StopKind::ProgramStop ? "M0" : *ctx.stop == StopKind::OptionalStop ? "M1" : "M30";
    if (*ctx.stop == StopKind::ProgramEnd && recorder_.active())
      raise(ctx, 15800, "program end while a contour is being recorded (DRYCUT_CONTOUR_END missing)");
    emit(std::move(e));
    if (*ctx.stop == StopKind::ProgramEnd) ended_ = true;
  }
}

void Interpreter::finish() {
  if (sar_pending_) release_smooth_approach(nullptr);
  if (spline_.active()) end_spline_run(nullptr);
  // A run stopped by an alarm inside a recorded contour: what came before goes on downstream.
  stop_recording();
  if (clock_wait_s_ > 0 && !ended_) {  // the program ran out while waiting for the clock
    const parser::Block none;
    emit_clock_wait(BlockContext(none));
  }
  sink_.finish();
}

}  // namespace drycut::interp
