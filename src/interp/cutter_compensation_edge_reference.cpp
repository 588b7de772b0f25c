#include "interp/cutter_compensation_edge_reference.hpp"

#include <memory>

#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/translated_curve.hpp"

namespace drycut::interp {

void EdgeReferenceShift::apply(PathElement& element) {
  if (!element.is_motion() || !element.curve) return;
  const geometry::Vec3 target =
      element.compensation.side == CompensationSide::None ? geometry::Vec3::Zero() : element.compensation.reference_shift;
  if (target.isZero() && current_.isZero()) return;
  if (target == current_ || element.kind != ElementKind::Line) {
    // A curve cannot take up a change of the shift: it is moved whole (the compensation joins
    // the step as it joins a change of the radius).
    element.curve = geometry::translate_curve(element.curve, target);
  } else {
    element.curve = std::make_shared<geometry::LineCurve>(element.curve->start() + current_, element.curve->end() + target);
  }
  current_ = target;
}

}  // namespace drycut::interp
