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
    recording_start_ = {position_, length_applied_, last_tangent_, has_last_tangent_, nominal_time_s_};
    recorder_.start([this](const geometry::Vec3& machine) {
      return geometry::Vec3(state_.frames.total(false).to_inner(machine - length_applied_) / geometry_unit());
    });
    corners_.redirect(recorder_);
    return;
  }
  corners_.redirect(downstream_);
  recorder_.stop();
  position_ = recording_start_.position;
  length_applied_ = recording_start_.length_applied;
  last_tangent_ = recording_start_.last_tangent;
  has_last_tangent_ = recording_start_.has_last_tangent;
  nominal_time_s_ = recording_start_.nominal_time_s;
}

}  // namespace drycut::interp
