// Where a block goes: tool length, the frame chain (settable and programmable frames), polar
// coordinates, and the target of a block in workpiece and machine coordinates.
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using parser::AddressWord;
using parser::ValueMode;
using namespace detail;

Vector3d Interpreter::tool_length_vector() const {
  // The three lengths on the plane's axes by tool type (Function Manual W1, "Tool length
  // compensation"; docs/controller-state.md): a turning or grinding tool (types 400 to 599) has
  // length 1 along the ordinate, length 2 along the abscissa and length 3 along the normal (G18:
  // X, Z, Y); every other tool (milling, drilling) length 1 along the normal, length 2 along the
  // ordinate and length 3 along the abscissa (G17: Z, Y, X).
  // SD42940 TOOL_LENGTH_CONST fixes the assignment to one plane's, SD42950 TOOL_LENGTH_TYPE
  // assigns every tool as a milling (1) or turning (2) tool (Function Manual W1, "Tool length
  // and plane change").
  const ToolOffsets& o = tools_.offsets();
  const PlaneSelect fixed =
      tool_length_const_ == 18 ? PlaneSelect::G18 : tool_length_const_ == 19 ? PlaneSelect::G19 : PlaneSelect::G17;
  const PlaneIndices plane = tool_length_const_ != 0 ? ModalState::indices_of(fixed) : state_.plane_indices();
  Vector3d length = Vector3d::Zero();
  const bool turning_tool = tool_length_type_ == 2 || (tool_length_type_ == 0 && o.type >= 400 && o.type <= 599);
  if (turning_tool) {
    length[plane.second] = o.length_mm;
    length[plane.first] = o.length2_mm;
    length[plane.normal] = o.length3_mm;
    return length;
  }
  length[plane.normal] = o.length_mm;
  length[plane.second] = o.length2_mm;
  length[plane.first] = o.length3_mm;
  // No swivel (nearly every block): the exact identity is answered without isIdentity's
  // tolerance test of nine coefficients.
  if (tool_orientation_ == Eigen::Matrix3d::Identity() || tool_orientation_.isIdentity()) return length;
  // A swivel head (TCOABS/TCOFR): each length along its swivelled axis.
  Vector3d swivelled = Vector3d::Zero();
  for (int i = 0; i < 3; ++i)
    if (length[i] != 0.0) swivelled += (tool_orientation_ * Vector3d::Unit(i)).normalized() * length[i];
  return swivelled;
}

void Interpreter::orient_tool(const BlockContext& ctx, const std::string& command, uint32_t column) {
  // TCOABS/TCOFR take the tool orientation from the swivel (drycut's CYCLE800 keeps the swivel in
  // the frame, so both take the frame's rotation). Only a head turns the tool.
  if (profile_.swivel_kinematics == "head") {
    tool_orientation_ = block_frame(ctx).linear();
    return;
  }
  // Only a rotation that tilts the working plane (its normal) is a swivel of the part; ROT about
  // the tool axis is an ordinary frame the linear axes follow.
  const Vector3d normal = Vector3d::Unit(state_.plane_normal_axis());
  part_swivelled_ = (block_frame(ctx).linear() * normal - normal).norm() > 1e-9;
  if (profile_.swivel_kinematics == "none" && !block_frame(ctx).is_pure_translation())
    warn_once(ctx, command + " (no swivel kinematics in the machine profile: the tool length stays on the machine axis)",
              column);
}

Vector3d Interpreter::workpiece_position(bool actual) const {
  Vector3d w = state_.frames.total(false).to_inner((actual ? actual_position() : position_) - length_applied_);
  const double unit = geometry_unit();
  for (int i = 0; i < 3; ++i) w[i] /= unit * state_.diameter.position_factor(i, false);
  return w;
}

const Frame& Interpreter::block_frame(const BlockContext& ctx) const {
  return state_.frames.total(ctx.suppress_offsets);
}

bool Interpreter::is_incremental(const AddressWord& a) const {
  return parser::is_incremental_mode(a.mode) || (a.mode == ValueMode::Default && !state_.absolute);
}

PolarWords Interpreter::polar_words(const BlockContext& ctx) const {
  PolarWords w;
  if (const AddressWord* ap = ctx.find_named("AP")) {
    w.angle_deg = ap->value;
    w.angle_incremental = ap->mode == ValueMode::Incremental;
  }
  if (const AddressWord* rp = ctx.find_named("RP")) w.radius_mm = rp->value * (state_.inch ? kMmPerInch : 1.0);
  return w;
}

void Interpreter::select_settable_frame(const BlockContext& ctx, int code, uint32_t column) {
  const int index = settable_frame_index(code);
  state_.work_offset = settable_frame_name(index);
  state_.frames.set_settable(settable_frames_[static_cast<size_t>(index)]);
  active_settable_components_ = settable_components_[static_cast<size_t>(index)];
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
    } else if (extra_axes_.index(a.name) >= 0 || is_axis_letter_name(a.name)) {
      warn_frame_of_extra_axis(ctx, a);
    }
  }
  const Frame component = instruction_frame(kind, words, state_.plane_normal_axis());
  // A scale factor 0 (or a product beyond the double range) leaves no way back from the machine
  // to the workpiece system.
  if (!component.invertible() || !state_.frames.programmable().then(component).invertible())
    raise(ctx, kUnsupported, "frame without an inverse (scale factor 0 or out of range)");
  state_.frames.program(component, ctx.additive_frame);
}

void Interpreter::warn_frame_of_extra_axis(const BlockContext& ctx, const AddressWord& a) {
  // Frames hold X, Y, Z here; the control's frame has a component for every channel axis
  // (docs/axes.md): the rotary or extra axis then runs on its programmed values, unshifted.
  warn_once(ctx, "frame component of axis " + a.name + " (offsets, rotations and scales of axes beyond X/Y/Z are not modelled: " +
                     a.name + " runs without it)",
            a.column);
}

void Interpreter::apply_axial_offset(const BlockContext& ctx) {
  // G58 X.. / G59 X..: the axis words are offsets, not a target (frame_chain.hpp).
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const bool additive = ctx.axial_offset == 59;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    if (i < 0) {
      if (extra_axes_.index(a.name) >= 0 || is_axis_letter_name(a.name)) warn_frame_of_extra_axis(ctx, a);
      continue;
    }
    if (!state_.frames.axial_offset(i, a.value * unit, additive))
      warn_once(ctx, std::string(additive ? "G59" : "G58") +
                         " with a programmable frame that rotates, scales or mirrors (offset not applied)",
                a.column);
  }
}

void Interpreter::define_pole(const BlockContext& ctx) {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  const PlaneIndices axes = state_.plane_indices();
  PoleWords cartesian;
  // G111 gives the pole absolutely, G110/G112 relative to a point: diameter values as positions.
  const bool relative = *ctx.pole != PoleReference::WorkpieceZero;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    const double value = a.value * unit * state_.diameter.value_factor(i, a.mode, relative);
    if (i == axes.first) cartesian.first = value;
    if (i == axes.second) cartesian.second = value;
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

void Interpreter::apply_contour_angle(const BlockContext& ctx, const Frame& frame, Target& t) {
  // One straight line by an end coordinate and its angle (Fundamentals, "Contour definitions:
  // one straight line"): ANG is the angle to the abscissa of the plane, counter-clockwise
  // positive; the other plane coordinate of the end point follows from the start point.
  const AddressWord* ang = ctx.find_named("ANG");
  if (!ang || ctx.contour_corner_done) return;
  const PlaneIndices plane = state_.plane_indices();
  const bool first = ctx.block.find_address(profile_.axes[static_cast<size_t>(plane.first)].name) != nullptr;
  const bool second = ctx.block.find_address(profile_.axes[static_cast<size_t>(plane.second)].name) != nullptr;
  const double a = ang->value * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  // A line along the written axis leaves the other coordinate open: not determined.
  const bool determined = first ? std::abs(c) > 1e-12 : std::abs(s) > 1e-12;
  if (first == second || !state_.straight_mode() || polar_words(ctx).any() || !determined) {
    warn_once(ctx, "ANG= (a contour of two or three straight lines, ANG on a circle, or an angle that leaves the "
                   "end point open: the block runs to its programmed end point)", ang->column);
    return;
  }
  const Vector3d start = frame.to_inner(position_ - length_applied_);
  if (first)
    t.workpiece[plane.second] = start[plane.second] + (t.workpiece[plane.first] - start[plane.first]) * s / c;
  else
    t.workpiece[plane.first] = start[plane.first] + (t.workpiece[plane.second] - start[plane.second]) * c / s;
  t.machine = frame.to_outer(t.workpiece) + t.length_after;
}

bool Interpreter::hold_contour_angle(BlockContext& ctx, bool has_axis) {
  // Two straight lines (Fundamentals, "Contour definitions: two straight lines"): a G0/G1 block
  // with ANG= and no end point gives the first line's direction; the next block gives the end
  // point and the second line's angle, and the corner is where the two lines meet.
  const AddressWord* ang = ctx.find_named("ANG");
  if (!ang || has_axis || !state_.straight_mode()) return false;
  held_angle_deg_ = ang->value;
  // A rounding or chamfer written here belongs to the corner of the two lines (Fundamentals,
  // "Contour definitions": ANG=α1 RND=r, then X.. Y.. ANG=α2); it is requested there.
  held_corner_ = corner_words(ctx);
  ctx.corner_used = true;
  return true;
}

void Interpreter::run_to_contour_corner(BlockContext& ctx) {
  const double first_deg = *std::exchange(held_angle_deg_, std::nullopt);
  const AddressWord* ang = ctx.find_named("ANG");
  const PlaneIndices plane = state_.plane_indices();
  const auto written = [&](int i) { return ctx.block.find_address(profile_.axes[static_cast<size_t>(i)].name); };
  const AddressWord* a1 = written(plane.first);
  const AddressWord* a2 = written(plane.second);
  const bool absolute = a1 && a2 && !is_incremental(*a1) && !is_incremental(*a2);
  if (!ang || !state_.straight_mode() || !absolute || polar_words(ctx).any()) {
    warn_once(ctx, "ANG= contour of two straight lines whose second block is not a G0/G1 with both absolute end "
                   "coordinates and ANG= (the first angle is dropped)", ang ? ang->column : 0);
    return;
  }
  ctx.contour_corner_done = true;  // this block's ANG= is the second line's: no other meaning
  const Frame& frame = block_frame(ctx);
  const Vector3d start = frame.to_inner(position_ - length_applied_);
  const Vector3d end = target_position(ctx).workpiece;
  const double t1 = first_deg * std::numbers::pi / 180.0, t2 = ang->value * std::numbers::pi / 180.0;
  const double d1x = std::cos(t1), d1y = std::sin(t1), d2x = std::cos(t2), d2y = std::sin(t2);
  const double ex = end[plane.first] - start[plane.first], ey = end[plane.second] - start[plane.second];
  const double denominator = d1x * d2y - d1y * d2x;
  if (std::abs(denominator) < 1e-12) {
    warn_once(ctx, "ANG= contour of two parallel straight lines (no corner: the block runs to its end point)", ang->column);
    return;
  }
  const double along = (ex * d2y - ey * d2x) / denominator;  // S + along * d1 = E + u * d2
  Vector3d corner = start;
  corner[plane.first] += along * d1x;
  corner[plane.second] += along * d1y;
  corner[plane.normal] = end[plane.normal];  // the infeed axis moves with the first line
  PathElement e = build_line(ctx, frame.to_outer(corner) + length_applied_);
  // The first block's word, requested on the first line as if this block had written it.
  const CornerWords held = std::exchange(held_corner_, CornerWords{});
  if (held.kind != ContourCornerKind::None) request_corner(ctx, e, held);
  position_ = e.curve->end();
  check_limits(ctx, position_);
  emit(std::move(e));
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
      const double value = a.value * unit * state_.diameter.value_factor(i, a.mode, incremental);
      t.machine[i] = incremental ? position_[i] + value : value + frame.offset()[i];
      t.machine[i] += length[i] - (incremental ? length_applied_[i] : 0.0);
      t.length_after[i] = length[i];
    }
    t.workpiece = frame.to_inner(t.machine - t.length_after);
    apply_contour_angle(ctx, frame, t);
    return t;
  }
  // Through the workpiece system of the tool tip: axes not written keep their workpiece
  // coordinate; the tool length joins with the first move that writes its axis, as above.
  t.workpiece = frame.to_inner(position_ - length_applied_);
  t.length_after = length_applied_;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = axis_index(a.name);
    if (i < 0) continue;
    const bool incremental = is_incremental(a);
    const double value = a.value * unit * state_.diameter.value_factor(i, a.mode, incremental);
    t.workpiece[i] = incremental ? t.workpiece[i] + value : value;
    t.length_after[i] = length[i];
  }
  if (polar.any()) t.workpiece = state_.polar.target(polar, state_.plane_indices(), t.workpiece);
  t.machine = frame.to_outer(t.workpiece) + t.length_after;
  apply_contour_angle(ctx, frame, t);
  return t;
}

}  // namespace drycut::interp
