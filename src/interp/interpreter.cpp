#include "interp/interpreter.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "interp/geometry/arc_solvers.hpp"
#include "interp/feed_rate.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using parser::AddressWord;
using parser::ValueMode;

namespace {

constexpr double kMmPerInch = 25.4;
// Value ranges of the programming manual; beyond them the control raises an alarm (and drycut
// would otherwise report absurd times or convert out of range).
constexpr double kMinFeed = 0.001;          // F resolution (mm/min, inch/min, mm/rev)
constexpr double kMaxDwellS = 999999.999;   // G4 F range
constexpr double kMaxTurns = 999;           // TURN=0..999
constexpr double kMaxToolNumber = 32000;    // T number
constexpr double kMaxEdgeNumber = 32000;    // D number
constexpr int kUnsupported = 990006;  // catalogued: function not modelled, would change the path
constexpr int kNotModelled = 990002;  // catalogued warning: no effect on the path modelled

int axis_index(std::string_view name) {
  if (name == "X") return 0;
  if (name == "Y") return 1;
  if (name == "Z") return 2;
  return -1;
}

geometry::Plane to_geometry_plane(PlaneSelect plane) {
  switch (plane) {
    case PlaneSelect::G17: return geometry::Plane::G17;
    case PlaneSelect::G18: return geometry::Plane::G18;
    case PlaneSelect::G19: return geometry::Plane::G19;
  }
  return geometry::Plane::G17;
}

geometry::SplineEnd to_spline_end(SplineCondition condition, const Vector3d& tangent) {
  geometry::SplineEnd end;
  switch (condition) {
    case SplineCondition::Natural: end.condition = geometry::EndCondition::Natural; break;
    case SplineCondition::Tangent: end.condition = geometry::EndCondition::Tangent; break;
    case SplineCondition::Auto: end.condition = geometry::EndCondition::Auto; break;
  }
  end.tangent = tangent;
  return end;
}

// The programmable frame instruction a command names (A...: additive), if it is one.
std::optional<FrameInstruction> frame_instruction_kind(std::string_view name) {
  if (name == "TRANS" || name == "ATRANS") return FrameInstruction::Trans;
  if (name == "ROT" || name == "AROT") return FrameInstruction::Rot;
  if (name == "SCALE" || name == "ASCALE") return FrameInstruction::Scale;
  if (name == "MIRROR" || name == "AMIRROR") return FrameInstruction::Mirror;
  return std::nullopt;
}

// Minimum spline end-point blocks per window of 10 (facts §1.2).
int spline_quota(MotionMode mode, int cubic_spline_blocks) {
  switch (mode) {
    case MotionMode::ASpline: return 4;
    case MotionMode::BSpline: return 6;
    default: return std::min(10, cubic_spline_blocks + 1);
  }
}

}  // namespace

// Everything one block asks for, gathered before anything moves (SINUMERIK executes a block's
// words in a fixed order, not in the order they are written).
struct Interpreter::BlockContext {
  explicit BlockContext(const parser::Block& b) : block(b) {}
  // The source of the elements this block makes (the text is copied once per element).
  BlockRef ref() const { return BlockRef{block.file, block.line, block.text}; }
  const std::string& file_name() const {
    static const std::string kNone;
    return block.file ? *block.file : kNone;
  }
  const parser::Block& block;
  bool exact_stop = false;      // G9
  bool suppress_offsets = false;  // G53, G153, SUPA: no frame for this block
  bool dwell = false;           // G4
  bool tool_change = false;     // M6
  std::optional<StopKind> stop;  // M0, M1, M2, M30
  bool preprocessing_stop = false;  // STOPRE
  bool motion_code = false;     // a group-1 code is written in this block
  // TRANS/ROT/SCALE/MIRROR (A...: additive): the axis words are the frame's values, not a target.
  std::optional<FrameInstruction> frame_instruction;
  bool additive_frame = false;
  std::optional<PoleReference> pole;  // G110/G111/G112: the axis or polar words define the pole
  bool compensation_changed = false;
  double lead_change_mm = 0.0;  // F of a G34/G35 block (lead change per revolution)
  uint32_t compensation_column = 0;  // the G41/G42 word
  std::optional<double> block_feed;  // F in this block (not a G4 block)
};

Interpreter::Interpreter(const machine::MachineProfile& profile, ElementSink& sink,
                         Diagnostics& diagnostics, InterpreterOptions options)
    : profile_(profile),
      sink_(sink),
      diagnostics_(diagnostics),
      options_(options),
      state_(reset_state(profile)),
      tools_(profile),
      position_(profile.start_position) {
  for (int i = 0; i < kSettableFrames; ++i) {
    settable_frames_[static_cast<size_t>(i)] = profile_settable_frame(profile, i);
    settable_defined_[static_cast<size_t>(i)] = profile_has_settable_frame(profile, i);
  }
  last_dynamics_.transition = state_.transition;
  last_dynamics_.profile = state_.accel;
}

void Interpreter::raise(const BlockContext& ctx, int number, const std::string& detail,
                        uint32_t column) const {
  throw AlarmError(make_alarm(number, detail, {ctx.file_name(), ctx.block.line, column}, ctx.block.text));
}

void Interpreter::warn_once(const BlockContext& ctx, const std::string& what, uint32_t column) {
  if (!warned_.insert(what).second) return;
  diagnostics_.warn(kNotModelled, what, {ctx.file_name(), ctx.block.line, column}, ctx.block.text);
}

void Interpreter::execute(const parser::Block& block) {
  if (ended_) return;
  BlockContext ctx(block);
  apply_system_writes(block);
  apply_g_words(ctx);
  apply_commands(ctx);
  apply_addresses(ctx);
  apply_m_words(ctx);
  execute_motion(ctx);
}

void Interpreter::apply_g_words(BlockContext& ctx) {
  // G97 after G96 freezes the speed the spindle has now (an S in the block replaces it later).
  const double frozen_speed = state_.constant_cutting_speed && ctx.block.has_g(97) ? spindle_speed(ctx) : -1.0;
  int group1 = -1;
  for (const auto& g : ctx.block.g) {
    const int code = g.code;
    if (code >= 0 && code <= 3) {
      if (group1 >= 0 && group1 != code)
        raise(ctx, 12070, "G" + std::to_string(group1) + " and G" + std::to_string(code), g.column);
      group1 = code;
      ctx.motion_code = true;
      state_.apply_code("G" + std::to_string(code));
      continue;
    }
    switch (code) {
      case 4: ctx.dwell = true; continue;
      case 9: ctx.exact_stop = true; continue;
      case 53: case 153: ctx.suppress_offsets = true; continue;
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
        state_.compensation = code == 41 ? CompensationSide::Left : CompensationSide::Right;
        ctx.compensation_changed = true;
        ctx.compensation_column = g.column;
        continue;
      }
      case 40: state_.compensation = CompensationSide::None; ctx.compensation_changed = true; continue;
      case 500: case 54: case 55: case 56: case 57: select_settable_frame(ctx, code, g.column); continue;
      case 601: case 602: case 603: continue;  // exact-stop window: no effect on the planned set-point
      case 63: continue;  // tapping with compensating chuck: moves with F at a fixed 100 % override, as planned anyway
      case 644: state_.transition = TransitionMode::SmoothTolerance; continue;
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
  if (frozen_speed >= 0 && state_.spindle != SpindleState::Stopped) state_.spindle_rpm = frozen_speed;
}

void Interpreter::apply_commands(BlockContext& ctx) {
  for (const auto& c : ctx.block.commands) {
    const std::string& n = c.name;
    if (n == "ASPLINE" || n == "BSPLINE" || n == "CSPLINE" || n == "CIP" || n == "CT") {
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
    } else if (n == "MSG") {
      // A message on the operator screen: nothing to simulate.
    } else if (!state_.apply_code(n)) {
      warn_once(ctx, n, c.column);
    }
  }
}

void Interpreter::apply_addresses(BlockContext& ctx) {
  // MD22550 = 1: the M function of MD22560 changes the tool; its address extension is a
  // spindle number, and only the master spindle (1) changes tools here (W1 2.2.5).
  if (tools_.change_on_m_code()) {
    for (const auto& m : ctx.block.m) {
      if (m.code != tools_.change_m_code()) continue;
      if (m.extension > 1)
        warn_once(ctx, "M" + std::to_string(m.extension) + "=" + std::to_string(m.code) +
                           ": tool change on another spindle than the master spindle 1", m.column);
      else
        ctx.tool_change = true;
    }
  }
  // T="name" is not an address word: program it before the words so that a D in the same block
  // (`T="BALL_R3" D1`, as posts write it) belongs to the prepared tool, as with `T1 D1`.
  if (ctx.block.tool_name) program_tool(ctx, *ctx.block.tool_name, 0);
  for (const AddressWord& a : ctx.block.addresses) {
    const std::string& n = a.name;
    if (n == "F") {
      if (ctx.dwell) continue;  // G4 F<s>: dwell time, modal feed unchanged
      // F has a resolution of 0.001: a smaller value is zero on the control (and would make
      // absurd times here).
      if (state_.motion == MotionMode::ThreadIncreasing || state_.motion == MotionMode::ThreadDecreasing) {
        // G34/G35: F is the lead change per revolution (0: constant lead).
        if (!(a.value >= 0)) raise(ctx, 12160, "the lead change F must be >= 0", a.column);
        ctx.lead_change_mm = a.value * geometry_unit();
        continue;
      }
      if (a.value < kMinFeed) raise(ctx, 14800, "F" + std::to_string(a.value), a.column);
      state_.feed = a.value;
      state_.feed_unit_mm = feed_unit();  // kept with F: a later G70/G71 does not convert it again
      ctx.block_feed = a.value;
    } else if (n == "S") {
      if (ctx.dwell) continue;  // G4 S<rev>
      if (a.value < 0) raise(ctx, 12160, "S must not be negative", a.column);
      state_.spindle_rpm = a.value;
    } else if (n == "LIMS") {
      if (a.value < 0) raise(ctx, 12160, "LIMS must not be negative", a.column);
      state_.spindle_speed_limit = a.value;
    } else if (n == "SF") {
      // Thread start angle: shifts where the thread starts on the circumference, not its time.
    } else if (n == "OVR") {
      warn_once(ctx, "OVR (drycut plans at 100 % override)", a.column);
    } else if (n == "T") {
      // Checked before the conversion: a double outside long long's range is undefined there.
      if (!(a.value >= 0 && a.value <= kMaxToolNumber) || a.value != std::floor(a.value))
        raise(ctx, 12160, "T number must be a whole number 0..32000", a.column);
      program_tool(ctx, std::to_string(static_cast<long long>(a.value)), a.column);
    } else if (n == "D") {
      // Range first: converting a double outside int's range is undefined behaviour.
      if (!(a.value >= 0 && a.value <= kMaxEdgeNumber) || a.value != std::floor(a.value))
        raise(ctx, 12160, "D must be a whole number >= 0", a.column);
      // In a block that changes the tool the edge belongs to the new tool: taken at the change.
      if (ctx.tool_change) continue;
      std::vector<ToolNotice> notices;
      tools_.select_edge(static_cast<int>(a.value), notices);
      report_tool_notices(ctx, notices, a.column);
    } else if (n == "SD") {
      if (a.value != 2 && a.value != 3) raise(ctx, 12160, "SD must be 2 or 3", a.column);
      state_.bspline_degree = static_cast<int>(a.value);
    } else if (n == "DISC") {
      if (a.value < 0 || a.value > 100) raise(ctx, 12160, "DISC must be 0..100", a.column);
      state_.disc = a.value;
    } else if (n == "A" || n == "B" || n == "C") {
      warn_once(ctx, "rotary axis " + n + " (not simulated)", a.column);
    }
  }
}

void Interpreter::program_tool(BlockContext& ctx, const std::string& id, uint32_t column) {
  std::vector<ToolNotice> notices;
  if (tools_.program_tool(id, notices)) ctx.tool_change = true;  // MD22550 = 0: T changes
  report_tool_notices(ctx, notices, column);
}

void Interpreter::apply_m_words(BlockContext& ctx) {
  for (const auto& m : ctx.block.m) {
    if (m.extension > 0 && m.code >= 3 && m.code <= 5) {
      warn_once(ctx, "spindle " + std::to_string(m.extension) + " (only the master spindle is simulated)", m.column);
    }
    switch (m.code) {
      case 0: ctx.stop = StopKind::ProgramStop; break;
      case 1: if (options_.optional_stop_active) ctx.stop = StopKind::OptionalStop; break;
      case 2: case 30: ctx.stop = StopKind::ProgramEnd; break;
      case 3: state_.spindle = SpindleState::Clockwise; break;
      case 4: state_.spindle = SpindleState::CounterClockwise; break;
      case 5: state_.spindle = SpindleState::Stopped; break;
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
    if (warned_.insert(n.detail).second)
      diagnostics_.warn(n.number, n.detail, {ctx.file_name(), ctx.block.line, column}, ctx.block.text);
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
  tools_.change_tool(d, notices);
  report_tool_notices(ctx, notices, column);
  const std::string tool = tools_.active_tool().value_or("0");
  emit_control(ctx, ElementKind::ToolChange,
               tools_.change_on_m_code() ? "M" + std::to_string(tools_.change_m_code()) + " " + tool : "T " + tool);
}

Vector3d Interpreter::tool_length_vector() const {
  Vector3d length = Vector3d::Zero();
  length[state_.plane_normal_axis()] = tools_.offsets().length_mm;
  return length;
}

const Frame& Interpreter::block_frame(const BlockContext& ctx) const {
  return state_.frames.total(ctx.suppress_offsets);
}

bool Interpreter::is_incremental(const AddressWord& a) const {
  return a.mode == ValueMode::Incremental || (a.mode == ValueMode::Default && !state_.absolute);
}

PolarWords Interpreter::polar_words(const BlockContext& ctx) const {
  PolarWords w;
  if (const AddressWord* ap = ctx.block.find_address("AP")) {
    w.angle_deg = ap->value;
    w.angle_incremental = ap->mode == ValueMode::Incremental;
  }
  if (const AddressWord* rp = ctx.block.find_address("RP")) w.radius_mm = rp->value * (state_.inch ? kMmPerInch : 1.0);
  return w;
}

void Interpreter::select_settable_frame(const BlockContext& ctx, int code, uint32_t column) {
  const int index = settable_frame_index(code);
  state_.work_offset = settable_frame_name(index);
  state_.frames.set_settable(settable_frames_[static_cast<size_t>(index)]);
  if (index != 0 && !settable_defined_[static_cast<size_t>(index)])
    warn_once(ctx, state_.work_offset + " has no offset in the machine profile; zero used", column);
}

void Interpreter::set_settable_frame(int index, const Frame& frame) {
  if (index < 0 || index >= kSettableFrames) return;
  settable_frames_[static_cast<size_t>(index)] = frame;
  settable_defined_[static_cast<size_t>(index)] = true;
}

void Interpreter::set_programmable_frame(const Frame& frame) { state_.frames.set_programmable(frame); }

void Interpreter::apply_frame_instruction(const BlockContext& ctx) {
  // TRANS X.. / ROT RPL=.. / SCALE X.. / MIRROR X0 ...: the words are the frame's values.
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const FrameInstruction kind = *ctx.frame_instruction;
  FrameInstructionWords words;
  for (const AddressWord& a : ctx.block.addresses) {
    if (const int i = axis_index(a.name); i >= 0) {
      words.axes[static_cast<size_t>(i)] = kind == FrameInstruction::Trans ? a.value * unit : a.value;
    } else if (a.name == "RPL") {
      words.rpl = a.value;
    }
  }
  const Frame component = instruction_frame(kind, words, state_.plane_normal_axis());
  // A scale factor 0 (or a product beyond the double range) leaves no way back from the machine
  // to the workpiece system.
  if (!component.invertible() || !state_.frames.programmable().then(component).invertible())
    raise(ctx, kUnsupported, "frame without an inverse (scale factor 0 or out of range)");
  state_.frames.program(component, ctx.additive_frame);
}

void Interpreter::define_pole(const BlockContext& ctx) {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const PlaneIndices axes = state_.plane_indices();
  PoleWords cartesian;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    if (i == axes.first) cartesian.first = a.value * unit;
    if (i == axes.second) cartesian.second = a.value * unit;
  }
  const Vector3d here = block_frame(ctx).to_inner(position_);
  state_.polar.define_pole(*ctx.pole, cartesian, polar_words(ctx), axes, here);
}

bool Interpreter::frame_mirrors_plane(const Frame& frame) const {
  if (frame.is_pure_translation()) return false;
  const PlaneIndices axes = state_.plane_indices();
  const Vector3d n = frame.vector_to_outer(Vector3d::Unit(axes.first)).cross(frame.vector_to_outer(Vector3d::Unit(axes.second)));
  return n[axes.normal] < 0;
}

void Interpreter::tilt_compensation_plane(const BlockContext& ctx, CompensationRequest& request) const {
  const Frame& frame = block_frame(ctx);
  if (request.side == CompensationSide::None || frame.is_pure_translation()) return;
  // A frame that tilts the working plane (ROT about a plane axis, CYCLE800 in 3+2 machining):
  // the control compensates in the tilted plane, 2.5-D as in G17/G18/G19 (PGsl "Tool radius
  // compensation"; Cycles "Swivel - CYCLE800": machining in the swivelled plane).
  const PlaneIndices axes = state_.plane_indices();
  const Vector3d first = frame.vector_to_outer(Vector3d::Unit(axes.first));
  const Vector3d n = first.cross(frame.vector_to_outer(Vector3d::Unit(axes.second)));
  if (std::abs(n[axes.normal]) >= (1 - 1e-9) * n.norm()) return;  // still the machine's plane
  request.tilted = true;
  request.tilted_first = first.normalized();
  // frame_mirrors_plane swapped the side when n points against the machine's normal axis; the
  // swapped side about -n is the programmed side about n.
  request.tilted_normal = (n[axes.normal] < 0 ? -n : n).normalized();
}

Interpreter::Target Interpreter::target_position(BlockContext& ctx) {
  const double unit = geometry_unit();
  const Frame& frame = block_frame(ctx);
  const PolarWords polar = polar_words(ctx);
  const Vector3d length = tool_length_vector();
  Target t;
  t.length_before = length_applied_;
  if (frame.is_pure_translation() && !polar.any()) {
    // Per axis and exact: the position of an axis not written does not move. Tool length: the
    // carrier stands the length above the tip from the first move of that axis on; an
    // incremental move carries only the part of the length not yet applied.
    t.machine = position_;
    t.length_after = length_applied_;
    for (const AddressWord& a : ctx.block.addresses) {
      const int i = axis_index(a.name);
      if (i < 0) continue;
      const bool incremental = is_incremental(a);
      t.machine[i] = incremental ? position_[i] + a.value * unit : a.value * unit + frame.offset()[i];
      t.machine[i] += length[i] - (incremental ? length_applied_[i] : 0.0);
      t.length_after[i] = length[i];
    }
    t.workpiece = frame.to_inner(t.machine - t.length_after);
    return t;
  }
  // Through the workpiece system of the tool tip: axes not written keep their workpiece
  // coordinate; the tool length joins with the first move that writes its axis, as above.
  t.workpiece = frame.to_inner(position_ - length_applied_);
  t.length_after = length_applied_;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    if (i < 0) continue;
    t.workpiece[i] = is_incremental(a) ? t.workpiece[i] + a.value * unit : a.value * unit;
    t.length_after[i] = length[i];
  }
  if (polar.any()) t.workpiece = state_.polar.target(polar, state_.plane_indices(), t.workpiece);
  t.machine = frame.to_outer(t.workpiece) + t.length_after;
  return t;
}

double Interpreter::geometry_unit() const { return state_.inch ? kMmPerInch : 1.0; }

double Interpreter::feed_unit() const {
  // G700/G710: F in the geometry's unit; G70/G71: F stays in the base system (MD10240).
  const bool inch = state_.feed_in_geometry_unit ? state_.inch : profile_.base_unit_inch;
  return inch ? kMmPerInch : 1.0;
}

double Interpreter::spindle_speed(const BlockContext& ctx) {
  if (state_.spindle == SpindleState::Stopped) return 0.0;
  if (!state_.constant_cutting_speed) return state_.spindle_rpm;
  // G96: S is the cutting speed (m/min, ft/min on an inch base) at the tool; the speed follows
  // the diameter 2|X| (work coordinates) at the block start, limited by LIMS and MD35100.
  warn_once(ctx, "G96 constant cutting speed: spindle speed taken at the block start diameter", 0);
  const double speed_mm_min = state_.spindle_rpm * 1000.0 * (profile_.base_unit_inch ? 0.3048 : 1.0);
  const double diameter = 2.0 * std::abs(block_frame(ctx).to_inner(position_ - length_applied_).x());
  double rpm = diameter > 1e-9 ? speed_mm_min / (std::numbers::pi * diameter) : profile_.max_spindle_speed_rpm;
  if (state_.spindle_speed_limit > 0) rpm = std::min(rpm, state_.spindle_speed_limit);
  return std::min(rpm, profile_.max_spindle_speed_rpm);
}

double Interpreter::feed_mm_s(BlockContext& ctx, double length_mm, const Vector3d& chord) {
  const FeedResult feed = path_feed(state_, spindle_speed(ctx), length_mm, chord, ctx.lead_change_mm);
  if (feed.alarm != 0) raise(ctx, feed.alarm, feed.detail);
  return feed.mm_s;
}

PathElement Interpreter::element_template(const BlockContext& ctx, ElementKind kind) const {
  PathElement e;
  e.kind = kind;
  e.source = ctx.ref();
  e.dynamics.transition = state_.transition;
  e.dynamics.profile = state_.accel;
  e.dynamics.exact_stop_this_block = ctx.exact_stop;
  e.compensation.side = state_.compensation;
  // A mirror in the plane swaps the sides: G41 on the programmed contour is right of the mirrored one.
  if (e.compensation.side != CompensationSide::None && frame_mirrors_plane(block_frame(ctx)))
    e.compensation.side = e.compensation.side == CompensationSide::Left ? CompensationSide::Right : CompensationSide::Left;
  e.compensation.radius_mm = tools_.offsets().radius_mm;
  e.compensation.intersection_corners = state_.intersection_corners;
  e.compensation.contour_approach = state_.contour_approach;
  e.compensation.collision_detection = state_.collision_detection;
  e.compensation.disc = state_.disc;
  e.compensation.plane_normal_axis = state_.plane_normal_axis();
  tilt_compensation_plane(ctx, e.compensation);
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
  if (thread_chain_ == state_.motion || profile_.spindle_ramp_time_s <= 0) return;
  PathElement e = element_template(ctx, ElementKind::Dwell);
  e.dwell_s = profile_.spindle_ramp_time_s;
  e.label = "spindle ramp";
  emit(std::move(e));
}

void Interpreter::emit(PathElement element) {
  if (element.is_motion() && element.curve && element.curve->length() > 0) {
    last_tangent_ = element.curve->at(element.curve->length()).tangent;
    has_last_tangent_ = true;
  }
  sink_.consume(std::move(element));
}

void Interpreter::emit_control(BlockContext& ctx, ElementKind kind, std::string label) {
  PathElement e = element_template(ctx, kind);
  e.label = std::move(label);
  emit(std::move(e));
}

void Interpreter::check_limits(const BlockContext& ctx, const Vector3d& target) const {
  for (int i = 0; i < 3; ++i) {
    const auto& axis = profile_.axes[static_cast<size_t>(i)];
    if (target[i] < axis.min_mm - 1e-9 || target[i] > axis.max_mm + 1e-9) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "axis %s at %.3f mm, limits %.3f .. %.3f mm", axis.name.c_str(),
                    target[i], axis.min_mm, axis.max_mm);
      raise(ctx, 10720, buf);
    }
  }
}

void Interpreter::execute_motion(BlockContext& ctx) {
  if (ctx.compensation_changed && state_.compensation != CompensationSide::None &&
      (!tools_.has_tool() || tools_.edge() == 0))
    raise(ctx, 10750, tools_.has_tool() ? "D0 is active" : "no tool is active", ctx.compensation_column);
  // Dynamics changes are told to the planner once, where they happen.
  if (state_.transition != last_dynamics_.transition || state_.accel != last_dynamics_.profile) {
    last_dynamics_.transition = state_.transition;
    last_dynamics_.profile = state_.accel;
    emit_control(ctx, ElementKind::DynamicsChange, "dynamics");
  }

  if (ctx.frame_instruction) {
    apply_frame_instruction(ctx);
    return;
  }
  if (ctx.pole) {
    define_pole(ctx);
    return;
  }

  bool has_axis = false;
  for (const AddressWord& a : ctx.block.addresses)
    if (axis_index(a.name) >= 0 || a.name == "AP" || a.name == "RP") has_axis = true;
  const bool arc_mode = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw;
  // A full circle needs no end point: G2 I10 is a motion block.
  const bool full_circle = arc_mode && !has_axis &&
                           (ctx.block.find_address("I") || ctx.block.find_address("J") ||
                            ctx.block.find_address("K") || ctx.block.find_address("AR"));

  const bool stops = ctx.dwell || ctx.tool_change || ctx.stop || ctx.preprocessing_stop;

  if (has_axis || full_circle) {
    const Target programmed = target_position(ctx);
    const Vector3d& target = programmed.machine;
    length_applied_ = programmed.length_after;
    check_limits(ctx, target);
    const bool run_ends = spline_.active() && !(state_.spline_mode() && state_.motion == spline_.mode());
    if (run_ends && (state_.spline_mode() || state_.motion == MotionMode::ArcTangent)) {
      // A new spline type, or CT (which is tangent to the run's end itself): ETAN takes the chord.
      Vector3d direction = target - position_;
      if (direction.norm() > 1e-12) direction.normalize();
      end_spline_run(direction.norm() > 0 ? &direction : nullptr);
    }
    if (state_.spline_mode()) {
      add_spline_point(ctx, target);
    } else {
      const bool arc = arc_mode || state_.motion == MotionMode::ArcThroughPoint || state_.motion == MotionMode::ArcTangent;
      if (state_.thread_mode()) start_thread_block(ctx);
      PathElement e = arc ? build_arc(ctx, programmed) : build_line(ctx, target);
      if (spline_.active()) {
        // The run ends here; ETAN takes the direction this block starts in.
        Vector3d direction = e.curve->length() > 0 ? e.curve->at(0).tangent : Vector3d::Zero();
        end_spline_run(direction.norm() > 0 ? &direction : nullptr);
      }
      position_ = e.curve->end();
      check_limits(ctx, position_);
      emit(std::move(e));
    }
  } else if (stops && spline_.active()) {
    end_spline_run(nullptr);
  }
  if (has_axis || full_circle) thread_chain_ = state_.thread_mode() ? std::optional(state_.motion) : std::nullopt;
  if (!state_.spline_mode()) quota_.stop();
  if (quota_.active() && !quota_.record(has_axis))
    raise(ctx, 990001, std::to_string(quota_.in_window()) + " of 10, " + std::to_string(quota_.required()) + " required");

  if (ctx.dwell) {
    PathElement e = element_template(ctx, ElementKind::Dwell);
    const AddressWord* f = ctx.block.find_address("F");
    const AddressWord* s = ctx.block.find_address("S");
    if (f) {
      if (f->value < 0 || f->value > kMaxDwellS)
        raise(ctx, 12160, "dwell time must be 0..999999.999 s", f->column);
      e.dwell_s = f->value;
    } else if (s) {
      const double rpm = spindle_speed(ctx);
      if (rpm <= 0) raise(ctx, 12160, "G4 S needs a turning spindle", s->column);
      e.dwell_s = s->value * 60.0 / rpm;
      if (!(e.dwell_s >= 0 && e.dwell_s <= kMaxDwellS))
        raise(ctx, 12160, "dwell time must be 0..999999.999 s", s->column);
    } else {
      raise(ctx, 12080, "G4 needs F<seconds> or S<revolutions>");
    }
    e.label = "G4";
    emit(std::move(e));
  }
  if (ctx.tool_change) change_tool(ctx);
  if (ctx.preprocessing_stop) {
    PathElement e = element_template(ctx, ElementKind::Stop);
    e.stop = StopKind::Preprocessing;
    e.label = "STOPRE";
    emit(std::move(e));
  }
  if (ctx.stop) {
    if (spline_.active()) end_spline_run(nullptr);
    PathElement e = element_template(ctx, ElementKind::Stop);
    e.stop = *ctx.stop;
    e.label = *ctx.stop == StopKind::ProgramStop ? "M0" : *ctx.stop == StopKind::OptionalStop ? "M1" : "M30";
    emit(std::move(e));
    if (*ctx.stop == StopKind::ProgramEnd) ended_ = true;
  }
}

PathElement Interpreter::build_line(BlockContext& ctx, const Vector3d& target) {
  PathElement e = element_template(ctx, ElementKind::Line);
  e.rapid = state_.motion == MotionMode::Rapid;
  e.label = e.rapid ? "G0" : std::string(motion_mode_name(state_.motion));
  e.curve = std::make_shared<geometry::LineCurve>(position_, target);
  if (!e.rapid) e.feed_mm_s = feed_mm_s(ctx, e.curve->length(), target - position_);
  return e;
}

PathElement Interpreter::build_arc(BlockContext& ctx, const Target& target) {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  // The circle is built where the program describes it. With a pure translation that is the
  // machine system shifted (exact, as before frames); otherwise the workpiece system, and the
  // finished circle goes through the frame (a mirror turns G2 into G3 by itself).
  const Frame& frame = block_frame(ctx);
  const bool in_machine = frame.is_pure_translation();
  // Absolute centres and CIP points are tip positions: in the machine system they get the length.
  const Vector3d shift = in_machine ? Vector3d(frame.offset() + target.length_after) : Vector3d::Zero();
  const Vector3d start = in_machine ? position_ : frame.to_inner(position_ - target.length_before);
  const Vector3d end = in_machine ? target.machine : target.workpiece;
  const geometry::Plane plane = to_geometry_plane(state_.plane);
  geometry::ArcTolerance tolerance{profile_.circle_error_const_mm, profile_.circle_error_factor};
  geometry::ArcResult result;
  PathElement e = element_template(ctx, ElementKind::Arc);
  e.label = std::string(motion_mode_name(state_.motion));

  if (state_.motion == MotionMode::ArcThroughPoint) {
    // CIP: intermediate point I1/J1/K1 follows G90/G91 (and AC/IC) like an end point.
    Vector3d mid = start;
    bool any = false;
    const char* names[3] = {"I1", "J1", "K1"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        any = true;
        mid[i] = is_incremental(*a) ? start[i] + a->value * unit : a->value * unit + shift[i];
      }
    }
    if (!any) raise(ctx, 14040, "CIP needs an intermediate point I1/J1/K1");
    result = geometry::arc_through_point(start, mid, end);
  } else if (state_.motion == MotionMode::ArcTangent) {
    if (!has_last_tangent_) raise(ctx, 14040, "CT needs a preceding motion to be tangent to");
    const Vector3d tangent = in_machine ? last_tangent_ : frame.vector_to_inner(last_tangent_).normalized();
    result = geometry::arc_tangent(start, tangent, end, plane);
  } else {
    const bool cw = state_.motion == MotionMode::ArcCw;
    const AddressWord* cr = ctx.block.find_address("CR");
    const AddressWord* ar = ctx.block.find_address("AR");
    const AddressWord* turn = ctx.block.find_address("TURN");
    int turns = 0;
    if (turn) {
      if (turn->value < 0 || turn->value > kMaxTurns || turn->value != std::floor(turn->value))
        raise(ctx, 14048, "TURN=" + std::to_string(turn->value), turn->column);
      turns = static_cast<int>(turn->value);
    }
    bool has_center = false;
    Vector3d center = start;
    const char* names[3] = {"I", "J", "K"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        has_center = true;
        // I/J/K are relative to the start point unless written I=AC(..).
        center[i] = a->mode == ValueMode::Absolute ? a->value * unit + shift[i] : start[i] + a->value * unit;
      }
    }
    if (!has_center && polar_words(ctx).any()) {
      // G2/G3 AP= RP=: a circle about the pole (in the plane; the normal coordinate is the start's).
      const PlaneIndices axes = state_.plane_indices();
      has_center = true;
      center[axes.first] = state_.polar.pole()[axes.first] + shift[axes.first];
      center[axes.second] = state_.polar.pole()[axes.second] + shift[axes.second];
    }
    if (cr) {
      if (cr->value == 0) raise(ctx, 14040, "CR=0", cr->column);
      result = geometry::arc_from_radius(start, end, cr->value * unit, cw, plane);
    } else if (ar && has_center) {
      result = geometry::arc_from_angle_and_center(start, center, ar->value * std::numbers::pi / 180.0, cw, plane);
    } else if (ar) {
      result = geometry::arc_from_angle_and_end(start, end, ar->value * std::numbers::pi / 180.0, cw, plane);
    } else if (has_center) {
      result = geometry::arc_from_center(start, end, center, cw, plane, turns, tolerance);
    } else {
      raise(ctx, 14040, "G2/G3 needs a centre (I/J/K), a radius (CR=) or an angle (AR=)");
    }
  }
  if (result.alarm != 0) raise(ctx, result.alarm, result.detail);
  if (in_machine) {
    e.curve = result.curve;
  } else {
    // Mapped through the frame, then lifted by the tool length to the carrier.
    auto mapped = transform_curve(result.curve, Frame::translation(target.length_after).then(frame));
    if (!mapped) raise(ctx, kUnsupported, "circle under unequal scale factors in its plane (SCALE/ASCALE)");
    e.curve = *mapped;
  }
  e.feed_mm_s = feed_mm_s(ctx, e.curve->length(), target.machine - position_);
  return e;
}

void Interpreter::add_spline_point(BlockContext& ctx, const Vector3d& target) {
  if (!spline_.active()) {
    Vector3d tangent = has_last_tangent_ ? last_tangent_ : Vector3d::Zero();
    SplineCondition begin = state_.spline_begin;
    // BTAN with nothing before it has no direction to take: the start is natural then.
    if (begin == SplineCondition::Tangent && !has_last_tangent_) begin = SplineCondition::Natural;
    spline_.begin(state_.motion, position_, to_spline_end(begin, tangent), state_.bspline_degree,
                  profile_.cubic_spline_global ? 0 : profile_.cubic_spline_blocks);
    quota_.start(spline_quota(state_.motion, profile_.cubic_spline_blocks));
  }
  PathElement e = element_template(ctx, ElementKind::SplineSpan);
  // The span's length is known only when the run is solved: G93 takes the chord here.
  if (state_.feed_mode == FeedMode::InverseTime) warn_once(ctx, "G93 with splines: the block time uses the chord", 0);
  e.feed_mm_s = feed_mm_s(ctx, (target - position_).norm(), target - position_);
  e.label = std::string(motion_mode_name(state_.motion));
  double weight = 1.0, knot_span = 0.0;
  if (const AddressWord* pw = ctx.block.find_address("PW")) {
    if (pw->value < 0 || pw->value > 3) raise(ctx, 12160, "PW must be 0..3", pw->column);
    weight = pw->value;
  }
  if (const AddressWord* pl = ctx.block.find_address("PL")) {
    if (pl->value <= 0) raise(ctx, 12160, "PL must be > 0", pl->column);
    knot_span = pl->value * (state_.inch ? kMmPerInch : 1.0);
  }
  try {
    spline_.add(target, weight, knot_span, std::move(e));
    spline_.drain(sink_);
  } catch (const AlarmError& error) {
    // The geometry knows what is wrong but not where: give the alarm this block's location.
    if (!error.alarm().where.file.empty()) throw;
    Alarm located = error.alarm();
    located.where = {ctx.file_name(), ctx.block.line, 0};
    located.block = ctx.block.text;
    throw AlarmError(std::move(located));
  }
  position_ = target;
  if (spline_.has_last_tangent()) {
    last_tangent_ = spline_.last_tangent();
    has_last_tangent_ = true;
  }
}

void Interpreter::end_spline_run(const Vector3d* next_direction) {
  SplineCondition end = state_.spline_end;
  if (end == SplineCondition::Tangent && !next_direction) end = SplineCondition::Natural;
  spline_.finish(to_spline_end(end, next_direction ? *next_direction : Vector3d::Zero()));
  spline_.drain(sink_);
  if (spline_.has_last_tangent()) {
    last_tangent_ = spline_.last_tangent();
    has_last_tangent_ = true;
  }
  spline_.reset();
  quota_.stop();
}

void Interpreter::finish() {
  if (spline_.active()) end_spline_run(nullptr);
  sink_.finish();
}

}  // namespace drycut::interp
