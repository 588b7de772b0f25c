// Chamfer and rounding words of a block (Fundamentals, "Contour corners: chamfer, rounding"):
// the interpreter reads them and attaches the request to the block's G0/G1 element; the filter
// in contour_corners.hpp inserts the element between it and the next block.
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

#include "interp/feed_rate.hpp"

namespace drycut::interp {

using parser::AddressWord;
using namespace detail;

bool Interpreter::apply_corner_address(BlockContext& ctx, const AddressWord& a) {
  const std::string_view n = a.name;
  const bool round = n == "RND", chamfer = n == "CHF", leg = n == "CHR";
  if (round || chamfer || leg || n == "RNDM") {
    if (a.value < 0) {
      warn_once(ctx, std::string(n) + " < 0 (ignored)", a.column);
      return true;
    }
    const double size = a.value * geometry_unit();
    if (n == "RNDM") {
      state_.rndm_mm = size;
      return true;
    }
    // A rounding and a chamfer in one block: the rounding is inserted.
    if (ctx.corner == ContourCornerKind::Round && !round) return true;
    ctx.corner = round ? ContourCornerKind::Round : chamfer ? ContourCornerKind::Chamfer : ContourCornerKind::ChamferLeg;
    ctx.corner_size_mm = size;
    ctx.corner_column = a.column;
    if (size == 0) ctx.corner = ContourCornerKind::None;
    return true;
  }
  if (n == "FRC" || n == "FRCM") {
    if (a.value < 0 || (n == "FRC" && a.value == 0)) raise(ctx, 14800, std::string(n) + " must be > 0", a.column);
    (n == "FRC" ? ctx.frc : state_.frcm) = a.value;
    return true;
  }
  return false;
}

Interpreter::CornerWords Interpreter::corner_words(const BlockContext& ctx) {
  return {ctx.corner, ctx.corner_size_mm, ctx.frc, ctx.corner_column};
}

void Interpreter::request_corner(BlockContext& ctx, PathElement& e, const CornerWords& words) {
  ContourCornerRequest r;
  r.program_level = ctx.block.program_level;
  if (words.kind != ContourCornerKind::None) {
    r.kind = words.kind;
    r.size_mm = words.size_mm;
  } else if (state_.rndm_mm > 0) {
    r.kind = ContourCornerKind::Round;
    r.size_mm = state_.rndm_mm;
    r.modal = true;
  }
  ctx.corner_used = true;
  if (r.kind == ContourCornerKind::None) return;
  const bool circle = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw ||
                      state_.motion == MotionMode::ArcThroughPoint || state_.motion == MotionMode::ArcTangent;
  if (state_.motion != MotionMode::Rapid && state_.motion != MotionMode::Linear &&
      !(circle && r.kind == ContourCornerKind::Round)) {
    warn_once(ctx, std::string(corner_word(r)) + " at the end of a " + std::string(motion_mode_name(state_.motion)) +
                       " block (modelled between straight G0/G1 blocks, and RND next to circles: the corner stays sharp)",
              words.column);
    return;
  }
  const double frc = words.frc > 0 ? words.frc : state_.frcm;
  if (frc > 0 && state_.feed_mode == FeedMode::InverseTime) {
    warn_once(ctx, "FRC/FRCM under G93 (the corner takes the next block's feed)", 0);
  } else if (frc > 0) {
    ModalState feed_state = state_;
    feed_state.feed = frc;
    feed_state.feed_unit_mm = feed_unit();
    const FeedResult feed = path_feed(feed_state, spindle_speed(ctx), 1.0, Eigen::Vector3d::UnitX(), 0.0);
    if (feed.alarm != 0) raise(ctx, feed.alarm, feed.detail);
    r.feed_mm_s = feed.mm_s;
  }
  e.corner = r;
}

void Interpreter::warn_unused_corner(BlockContext& ctx) {
  if (ctx.corner == ContourCornerKind::None || ctx.corner_used) return;
  ContourCornerRequest r;
  r.kind = ctx.corner;
  warn_once(ctx, std::string(corner_word(r)) + " in a block without a straight G0/G1 motion (not modelled)", ctx.corner_column);
}

}  // namespace drycut::interp
