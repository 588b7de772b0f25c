#include "interp/geometry/translated_curve.hpp"

#include <memory>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {

TranslatedCurve::TranslatedCurve(CurvePtr base, Vec3 shift) : base_(std::move(base)), shift_(std::move(shift)) {}

CurvePoint TranslatedCurve::at(double s) const {
  CurvePoint p = base_->at(s);
  p.position += shift_;
  return p;
}

CurvePtr translate_curve(const CurvePtr& curve, const Vec3& shift) {
  if (shift.isZero()) return curve;
  if (dynamic_cast<const LineCurve*>(curve.get())) return std::make_shared<LineCurve>(curve->start() + shift, curve->end() + shift);
  if (const auto* arc = dynamic_cast<const ArcCurve*>(curve.get()))
    return std::make_shared<ArcCurve>(arc->centre() + shift, arc->radius(), arc->first_axis(), arc->second_axis(),
                                      arc->start_angle(), arc->sweep(), arc->axial_travel());
  return std::make_shared<TranslatedCurve>(curve, shift);
}

}  // namespace drycut::geometry
