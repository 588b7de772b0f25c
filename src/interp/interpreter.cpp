#include "interp/interpreter.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "interp/geometry/arc_solvers.hpp"
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
  bool suppress_offsets = false;  // G53
  bool dwell = false;           // G4
  bool tool_change = false;     // M6
  std::optional<StopKind> stop;  // M0, M1, M2, M30
  bool preprocessing_stop = false;  // STOPRE
  bool motion_code = false;     // a group-1 code is written in this block
  bool translation = false;     // TRANS/ATRANS: the axis words are the offset, not a target
  bool additive_translation = false;
  bool compensation_changed = false;
  std::optional<double> block_feed;  // F in this block (not a G4 block)
};

Interpreter::Interpreter(const machine::MachineProfile& profile, ElementSink& sink,
                         Diagnostics& diagnostics, InterpreterOptions options)
    : profile_(profile),
      sink_(sink),
      diagnostics_(diagnostics),
      options_(options),
      state_(reset_state(profile)),
      position_(profile.start_position) {
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
  apply_g_words(ctx);
  apply_commands(ctx);
  apply_addresses(ctx);
  apply_m_words(ctx);
  execute_motion(ctx);
}

void Interpreter::apply_g_words(BlockContext& ctx) {
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
      case 53: ctx.suppress_offsets = true; continue;
      case 17: case 18: case 19: {
        const PlaneSelect before = state_.plane;
        state_.apply_code("G" + std::to_string(code));
        if (state_.plane != before && state_.compensation != CompensationSide::None)
          raise(ctx, 10757, "", g.column);
        continue;
      }
      case 41: case 42: {
        if (!state_.active_tool || state_.edge == 0)
          raise(ctx, 10750, state_.active_tool ? "D0 is active" : "no tool is active", g.column);
        state_.compensation = code == 41 ? CompensationSide::Left : CompensationSide::Right;
        ctx.compensation_changed = true;
        continue;
      }
      case 40: state_.compensation = CompensationSide::None; ctx.compensation_changed = true; continue;
      case 500: case 54: case 55: case 56: case 57: {
        const std::string name = "G" + std::to_string(code);
        state_.work_offset = name;
        auto it = profile_.work_offsets.find(name);
        if (it == profile_.work_offsets.end()) {
          state_.work_offset_mm = Vector3d::Zero();
          if (code != 500) warn_once(ctx, name + " has no offset in the machine profile; zero used", g.column);
        } else {
          state_.work_offset_mm = it->second;
        }
        continue;
      }
      case 601: case 602: case 603: continue;  // exact-stop window: no effect on the planned set-point
      case 644: state_.transition = TransitionMode::SmoothTolerance; continue;
      default: break;
    }
    if (state_.apply_code("G" + std::to_string(code))) continue;
    warn_once(ctx, "G" + std::to_string(code), g.column);
  }
}

void Interpreter::apply_commands(BlockContext& ctx) {
  for (const auto& c : ctx.block.commands) {
    const std::string& n = c.name;
    if (n == "ASPLINE" || n == "BSPLINE" || n == "CSPLINE" || n == "CIP" || n == "CT") {
      ctx.motion_code = true;
      state_.apply_code(n);
    } else if (n == "TRANS" || n == "ATRANS") {
      ctx.translation = true;
      ctx.additive_translation = n == "ATRANS";
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
  for (const AddressWord& a : ctx.block.addresses) {
    const std::string& n = a.name;
    if (n == "F") {
      if (ctx.dwell) continue;  // G4 F<s>: dwell time, modal feed unchanged
      // F has a resolution of 0.001: a smaller value is zero on the control (and would make
      // absurd times here).
      if (a.value < kMinFeed) raise(ctx, 14800, "F" + std::to_string(a.value), a.column);
      state_.feed = a.value;
      ctx.block_feed = a.value;
    } else if (n == "S") {
      if (ctx.dwell) continue;  // G4 S<rev>
      if (a.value < 0) raise(ctx, 12160, "S must not be negative", a.column);
      state_.spindle_rpm = a.value;
    } else if (n == "T") {
      // Checked before the conversion: a double outside long long's range is undefined there.
      if (!(a.value >= 0 && a.value <= kMaxToolNumber))
        raise(ctx, 12160, "T number must be 0..32000", a.column);
      state_.prepared_tool = std::to_string(static_cast<long long>(a.value));
    } else if (n == "D") {
      // Range first: converting a double outside int's range is undefined behaviour.
      if (!(a.value >= 0 && a.value <= kMaxEdgeNumber) || a.value != std::floor(a.value))
        raise(ctx, 12160, "D must be a whole number >= 0", a.column);
      // With M6 in the same block the edge belongs to the new tool: selected after the change.
      if (ctx.block.has_m(6)) continue;
      select_edge(ctx, static_cast<int>(a.value), a.column);
    } else if (n == "SD") {
      if (a.value != 2 && a.value != 3) raise(ctx, 12160, "SD must be 2 or 3", a.column);
      state_.bspline_degree = static_cast<int>(a.value);
    } else if (n == "DISC") {
      if (a.value < 0 || a.value > 100) raise(ctx, 12160, "DISC must be 0..100", a.column);
      state_.disc = a.value;
    } else if (n == "AP" || n == "RP") {
      raise(ctx, kUnsupported, "polar coordinates " + n + "=", a.column);
    } else if (n == "A" || n == "B" || n == "C") {
      warn_once(ctx, "rotary axis " + n + " (not simulated)", a.column);
    }
  }
  if (ctx.block.tool_name) state_.prepared_tool = *ctx.block.tool_name;
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
      case 6: ctx.tool_change = true; break;
      default: break;  // M17 is the loader's; coolant and PLC functions take no path time
    }
  }
}

const machine::Tool* Interpreter::find_tool(const std::string& id) const {
  // T="name" selects by name; T<n> by number (kept as its decimal text).
  if (const machine::Tool* tool = profile_.find_tool(id)) return tool;
  char* end = nullptr;
  const long number = std::strtol(id.c_str(), &end, 10);
  return end && *end == '\0' && !id.empty() ? profile_.find_tool(static_cast<int>(number)) : nullptr;
}

void Interpreter::select_edge(const BlockContext& ctx, int d, uint32_t column) {
  if (d != 0 && !state_.active_tool) raise(ctx, 12160, "D" + std::to_string(d) + " without an active tool", column);
  state_.edge = d;
  state_.tool_radius_mm = 0;
  if (d == 0) return;
  const machine::Tool* tool = find_tool(*state_.active_tool);
  const machine::ToolEdge* edge = nullptr;
  if (tool)
    for (const auto& e : tool->edges)
      if (e.d == d) edge = &e;
  if (!edge) raise(ctx, 12160, "tool " + *state_.active_tool + " has no edge D" + std::to_string(d), column);
  state_.tool_radius_mm = edge->radius_mm;
}

Vector3d Interpreter::frame_offset(const BlockContext& ctx) const {
  if (ctx.suppress_offsets) return Vector3d::Zero();
  return state_.work_offset_mm + state_.translation_mm;
}

Vector3d Interpreter::target_position(BlockContext& ctx) const {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const Vector3d frame = frame_offset(ctx);
  Vector3d target = position_;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    if (i < 0) continue;
    const bool incremental = a.mode == ValueMode::Incremental || (a.mode == ValueMode::Default && !state_.absolute);
    target[i] = incremental ? position_[i] + a.value * unit : a.value * unit + frame[i];
  }
  return target;
}

double Interpreter::feed_mm_s(const BlockContext& ctx) const {
  if (state_.feed <= 0) raise(ctx, 10860, "no F programmed for " + std::string(motion_mode_name(state_.motion)));
  if (state_.feed_per_rev) {
    // S below its 0.001 resolution is a standing spindle (and would give absurd times).
    if (state_.spindle_rpm < kMinFeed || state_.spindle == SpindleState::Stopped)
      raise(ctx, 10860, "G95 feed per revolution needs a turning spindle (S and M3/M4)");
    return state_.feed * state_.spindle_rpm / 60.0;  // mm/rev * rev/min -> mm/s
  }
  const double unit = state_.inch_feed ? kMmPerInch : 1.0;
  return state_.feed * unit / 60.0;
}

PathElement Interpreter::element_template(const BlockContext& ctx, ElementKind kind) const {
  PathElement e;
  e.kind = kind;
  e.source = ctx.ref();
  e.dynamics.transition = state_.transition;
  e.dynamics.profile = state_.accel;
  e.dynamics.exact_stop_this_block = ctx.exact_stop;
  e.compensation.side = state_.compensation;
  e.compensation.radius_mm = state_.tool_radius_mm;
  e.compensation.intersection_corners = state_.intersection_corners;
  e.compensation.contour_approach = state_.contour_approach;
  e.compensation.collision_detection = state_.collision_detection;
  e.compensation.disc = state_.disc;
  e.compensation.plane_normal_axis = state_.plane_normal_axis();
  return e;
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
  // Dynamics changes are told to the planner once, where they happen.
  if (state_.transition != last_dynamics_.transition || state_.accel != last_dynamics_.profile) {
    last_dynamics_.transition = state_.transition;
    last_dynamics_.profile = state_.accel;
    emit_control(ctx, ElementKind::DynamicsChange, "dynamics");
  }

  if (ctx.translation) {
    // TRANS X.. Y.. Z..: the axis words set (ATRANS: add) the programmable translation.
    const double unit = state_.inch ? kMmPerInch : 1.0;
    if (!ctx.additive_translation) state_.translation_mm.setZero();
    for (const AddressWord& a : ctx.block.addresses)
      if (int i = axis_index(a.name); i >= 0) state_.translation_mm[i] += a.value * unit;
    return;
  }

  bool has_axis = false;
  for (const AddressWord& a : ctx.block.addresses)
    if (axis_index(a.name) >= 0) has_axis = true;
  const bool arc_mode = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw;
  // A full circle needs no end point: G2 I10 is a motion block.
  const bool full_circle = arc_mode && !has_axis &&
                           (ctx.block.find_address("I") || ctx.block.find_address("J") ||
                            ctx.block.find_address("K") || ctx.block.find_address("AR"));

  const bool stops = ctx.dwell || ctx.tool_change || ctx.stop || ctx.preprocessing_stop;

  if (has_axis || full_circle) {
    const Vector3d target = target_position(ctx);
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
      PathElement e = arc ? build_arc(ctx, target) : build_line(ctx, target);
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
      if (state_.spindle_rpm <= 0 || state_.spindle == SpindleState::Stopped)
        raise(ctx, 12160, "G4 S needs a turning spindle", s->column);
      e.dwell_s = s->value * 60.0 / state_.spindle_rpm;
      if (!(e.dwell_s >= 0 && e.dwell_s <= kMaxDwellS))
        raise(ctx, 12160, "dwell time must be 0..999999.999 s", s->column);
    } else {
      raise(ctx, 12080, "G4 needs F<seconds> or S<revolutions>");
    }
    e.label = "G4";
    emit(std::move(e));
  }
  if (ctx.tool_change) {
    if (!state_.prepared_tool) raise(ctx, 12160, "M6 without a tool selected by T");
    const machine::Tool* tool = find_tool(*state_.prepared_tool);
    if (!tool) raise(ctx, 12160, "tool '" + *state_.prepared_tool + "' is not in the machine profile's tool table");
    state_.active_tool = state_.prepared_tool;
    if (const AddressWord* d = ctx.block.find_address("D")) {
      select_edge(ctx, static_cast<int>(d->value), d->column);
    } else {
      // MD20270 CUTTING_EDGE_DEFAULT = 1: after a change without D the first edge is active.
      state_.edge = 1;
      state_.tool_radius_mm = tool->edges.empty() ? 0.0 : tool->edges.front().radius_mm;
    }
    emit_control(ctx, ElementKind::ToolChange, "M6 " + *state_.active_tool);
  }
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

PathElement Interpreter::build_line(BlockContext& ctx, const Vector3d& target) const {
  PathElement e = element_template(ctx, ElementKind::Line);
  e.rapid = state_.motion == MotionMode::Rapid;
  if (!e.rapid) e.feed_mm_s = feed_mm_s(ctx);
  e.label = e.rapid ? "G0" : "G1";
  e.curve = std::make_shared<geometry::LineCurve>(position_, target);
  return e;
}

PathElement Interpreter::build_arc(BlockContext& ctx, const Vector3d& target) const {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const Vector3d frame = frame_offset(ctx);
  const geometry::Plane plane = to_geometry_plane(state_.plane);
  geometry::ArcTolerance tolerance{profile_.circle_error_const_mm, profile_.circle_error_factor};
  geometry::ArcResult result;
  PathElement e = element_template(ctx, ElementKind::Arc);
  e.feed_mm_s = feed_mm_s(ctx);
  e.label = std::string(motion_mode_name(state_.motion));

  if (state_.motion == MotionMode::ArcThroughPoint) {
    // CIP: intermediate point I1/J1/K1 follows G90/G91 (and AC/IC) like an end point.
    Vector3d mid = position_;
    bool any = false;
    const char* names[3] = {"I1", "J1", "K1"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        any = true;
        const bool inc = a->mode == ValueMode::Incremental || (a->mode == ValueMode::Default && !state_.absolute);
        mid[i] = inc ? position_[i] + a->value * unit : a->value * unit + frame[i];
      }
    }
    if (!any) raise(ctx, 14040, "CIP needs an intermediate point I1/J1/K1");
    result = geometry::arc_through_point(position_, mid, target);
  } else if (state_.motion == MotionMode::ArcTangent) {
    if (!has_last_tangent_) raise(ctx, 14040, "CT needs a preceding motion to be tangent to");
    result = geometry::arc_tangent(position_, last_tangent_, target, plane);
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
    Vector3d center = position_;
    const char* names[3] = {"I", "J", "K"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        has_center = true;
        // I/J/K are relative to the start point unless written I=AC(..).
        center[i] = a->mode == ValueMode::Absolute ? a->value * unit + frame[i] : position_[i] + a->value * unit;
      }
    }
    if (cr) {
      if (cr->value == 0) raise(ctx, 14040, "CR=0", cr->column);
      result = geometry::arc_from_radius(position_, target, cr->value * unit, cw, plane);
    } else if (ar && has_center) {
      result = geometry::arc_from_angle_and_center(position_, center, ar->value * std::numbers::pi / 180.0, cw, plane);
    } else if (ar) {
      result = geometry::arc_from_angle_and_end(position_, target, ar->value * std::numbers::pi / 180.0, cw, plane);
    } else if (has_center) {
      result = geometry::arc_from_center(position_, target, center, cw, plane, turns, tolerance);
    } else {
      raise(ctx, 14040, "G2/G3 needs a centre (I/J/K), a radius (CR=) or an angle (AR=)");
    }
  }
  if (result.alarm != 0) raise(ctx, result.alarm, result.detail);
  e.curve = result.curve;
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
  e.feed_mm_s = feed_mm_s(ctx);
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
