// DRYCUT_CONTOUR_BEGIN / DRYCUT_CONTOUR_END: the contour recording of drycut's own contour
// cycles (interp/contour_recording.hpp; docs/cycles.md, "Contour cycles").
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using namespace detail;

void Interpreter::record_contour(const BlockContext& ctx, bool begin, uint32_t column) {
  // The control's alarm for contour preparation started twice or ended unstarted (CONTPRON).
  constexpr int kWrongStart = 15800;
  if (begin == recorder_.active())
    raise(ctx, kWrongStart, begin ? "DRYCUT_CONTOUR_BEGIN while a contour is being recorded" : "DRYCUT_CONTOUR_END without BEGIN",
          column);
  // A spline run still open belongs to the side of the switch it was programmed on.
  if (spline_.active()) end_spline_run(nullptr);
  if (begin) {
    recording_start_ = RecordingStart{position_,     length_applied_, last_tangent_,
                                      has_last_tangent_, nominal_time_s_, cutting_time_s_, last_dynamics_,
                                      held_angle_deg_, held_corner_,    thread_chain_,
                                      block_between_compressible_,      compensation_selection_pending_,
                                      tools_,        extra_axes_};
    recorder_.start([this](const geometry::Vec3& machine) {
      return geometry::Vec3(state_.frames.total(false).to_inner(machine - length_applied_) / geometry_unit());
    });
    corners_.redirect(recorder_);
    return;
  }
  stop_recording();
}

void Interpreter::stop_recording() {
  if (!recorder_.active()) return;
  corners_.redirect(downstream_);
  recorder_.stop();
  RecordingStart& r = *recording_start_;
  position_ = r.position;
  length_applied_ = r.length_applied;
  last_tangent_ = r.last_tangent;
  has_last_tangent_ = r.has_last_tangent;
  nominal_time_s_ = r.nominal_time_s;
  cutting_time_s_ = r.cutting_time_s;
  last_dynamics_ = r.last_dynamics;  // the next real motion reports its dynamics downstream again
  held_angle_deg_ = r.held_angle_deg;
  held_corner_ = r.held_corner;
  thread_chain_ = r.thread_chain;
  block_between_compressible_ = r.block_between_compressible;
  compensation_selection_pending_ = r.compensation_selection_pending;
  tools_ = std::move(r.tools);
  extra_axes_ = std::move(r.extra_axes);
  recording_start_.reset();
}

}  // namespace drycut::interp
