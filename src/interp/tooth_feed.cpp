// Tooth feed G95 FZ (Programming Manual Fundamentals, "Tooth feedrate (G95 FZ)";
// docs/controller-state.md "Feeds"): under G95 the feed per revolution is
// F = FZ · $TC_DPNT, the number of teeth of the active cutting edge. FZ is modal, survives tool
// changes and D selections (the new edge's teeth count from then on), is deleted by a change
// between G93/G94/G95 and has no effect under G93/G94. An F replaces it; F and FZ in one block:
// FZ (warned). Unknown teeth (0 or no edge): drycut assumes 1 tooth, F = FZ, warning 990002.
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
  ModalState scratch;
  const FeedResult feed = path_feed(feed_state(ctx, scratch), spindle_speed(ctx, &chord), length_mm, chord,
                                     ctx.lead_change_mm);
  if (feed.alarm != 0) raise(ctx, feed.alarm, feed.detail);
  return feed.mm_s;
}

}  // namespace drycut::interp
