// Tooth feed G95 FZ (Programming Manual Fundamentals, "Tooth feedrate (G95 FZ)";
// docs/controller-state.md "Feeds"): under G95 the feed per revolution is
// F = FZ · $TC_DPNT, the number of teeth of the active cutting edge. FZ is modal, survives tool
// changes and D selections (the new edge's teeth count from then on), is deleted by a change
// between G93/G94/G95 and has no effect under G93/G94. An F replaces it; F and FZ in one block:
// FZ (warned). Unknown teeth (0 or no edge): drycut assumes 1 tooth, F = FZ, warning 990002.
// Here too the path feed of a block (feed_mm_s) and its check that a thread's lead at the
// spindle speed does not ask an axis for more than its MAX_AX_VELO.
#include <cstdio>

#include "interp/feed_rate.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using namespace detail;

void Interpreter::apply_tooth_feed(BlockContext& ctx, const parser::AddressWord& a) {
  // The path velocity is FZ times the teeth: zero or less is the F word's alarm.
  if (a.value < kMinFeed) raise(ctx, 14800, "FZ" + std::to_string(a.value), a.column);
  state_.tooth_feed = a.value;
  state_.tooth_feed_unit_mm = feed_unit();
}

void Interpreter::apply_f_after_tooth_feed(BlockContext& ctx, const parser::AddressWord& f) {
  // An F switches back from the tooth feed to the feed per revolution. The manual does not say
  // which wins when both stand in one block: drycut keeps FZ (no alarm) and says so.
  if (!ctx.block.find_address("FZ")) {
    state_.tooth_feed = 0.0;
    return;
  }
  warn_once(ctx, "F and FZ in one block: the tooth feed FZ is taken", f.column);
}

const ModalState& Interpreter::feed_state(const BlockContext& ctx, ModalState& scratch) {
  if (ctx.nonmodal_feed) {  // FB=: this block's feed, whatever F or FZ say
    scratch = state_;
    scratch.feed = *ctx.nonmodal_feed;
    scratch.feed_unit_mm = feed_unit();
    return scratch;
  }
  if (state_.tooth_feed <= 0 || state_.feed_mode != FeedMode::PerRevolution || state_.thread_mode()) return state_;
  int teeth = tools_.offsets().teeth;
  if (teeth <= 0) {
    warn_once(ctx, "FZ: number of teeth $TC_DPNT of the active cutting edge not known, 1 tooth assumed (F = FZ)", 0);
    teeth = 1;
  }
  scratch = state_;
  scratch.feed = state_.tooth_feed * teeth;
  scratch.feed_unit_mm = state_.tooth_feed_unit_mm;
  return scratch;
}

double Interpreter::feed_mm_s(BlockContext& ctx, double length_mm, const Eigen::Vector3d& chord) {
  if (state_.feed_type_changed && !state_.thread_mode()) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "F%g taken as %s", state_.feed,
                  state_.feed_mode == FeedMode::InverseTime     ? "1/min (G93)"
                  : state_.feed_mode == FeedMode::PerRevolution ? "per revolution (G95, G96, G97 or G973)"
                                                                : "per minute (G94)");
    warn_once(ctx, 990016, buf, 0);
    state_.feed_type_changed = false;
  }
  ModalState& scratch = feed_scratch_;
  const FeedResult feed = path_feed(feed_state(ctx, scratch), spindle_speed(ctx, &chord), length_mm, chord,
                                     ctx.lead_change_mm);
  if (feed.alarm != 0) {
    // A recorded contour is not run: it needs no feed, as on the control's contour preparation.
    if (recorder_.active()) return 1.0;
    raise(ctx, feed.alarm, feed.detail);
  }
  if (state_.thread_mode() && length_mm > 0) warn_thread_beyond_axis_velocity(ctx, feed.mm_s, length_mm, chord);
  return feed.mm_s;
}

void Interpreter::warn_thread_beyond_axis_velocity(BlockContext& ctx, double feed_mm_s, double length_mm,
                                                   const Eigen::Vector3d& chord) {
  // G33/G34/G35 couple the axes to the spindle: an axis that would have to run faster than its
  // MAX_AX_VELO (MD32000) cannot follow, so the lead is not cut as programmed; the planner limits
  // the velocity (the time shown is that of the slower, wrong thread).
  for (int i = 0; i < 3; ++i) {
    const double axis_velocity = feed_mm_s * std::abs(chord[i]) / length_mm;
    const double limit = profile_.axes[static_cast<size_t>(i)].max_velocity_mm_s;
    if (limit > 0 && axis_velocity > limit * (1 + 1e-9)) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "%s: axis %s would need %.0f mm/min for the lead at this speed, more than its %.0f (MD32000): "
                    "the thread is not cut as programmed",
                    std::string(motion_mode_name(state_.motion)).c_str(), profile_.axes[static_cast<size_t>(i)].name.c_str(),
                    axis_velocity * 60, limit * 60);
      warn_once(ctx, 990013, buf, 0);
    }
  }
}

}  // namespace drycut::interp
