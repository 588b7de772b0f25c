#include "interp/geometry/trimmed_curve.hpp"

#include <algorithm>
#include <memory>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {

TrimmedCurve::TrimmedCurve(CurvePtr base, double s0, double s1)
    : base_(std::move(base)), s0_(s0), s1_(s1), start_(base_->at(s0).position), end_(base_->at(s1).position) {}

CurvePoint TrimmedCurve::at(double s) const { return base_->at(s0_ + std::clamp(s, 0.0, s1_ - s0_)); }

CurvePtr trim_curve(const CurvePtr& curve, double s0, double s1) {
  if (dynamic_cast<const LineCurve*>(curve.get()))
    return std::make_shared<LineCurve>(curve->at(s0).position, curve->at(s1).position);
  if (const auto* arc = dynamic_cast<const ArcCurve*>(curve.get()); arc && arc->sweep() != 0.0) {
    // P(phi) = centre + r (cos phi e1 + sin phi e2) + axial (phi - start) / sweep n: the piece
    // starts at the share f0 of the sweep and of the axial travel.
    const double length = arc->length();
    const double f0 = length > 0 ? s0 / length : 0.0, f1 = length > 0 ? s1 / length : 1.0;
    return std::make_shared<ArcCurve>(arc->centre() + f0 * arc->axial_travel() * arc->normal(), arc->radius(),
                                      arc->first_axis(), arc->second_axis(), arc->start_angle() + f0 * arc->sweep(),
                                      (f1 - f0) * arc->sweep(), (f1 - f0) * arc->axial_travel());
  }
  if (const auto* piece = dynamic_cast<const TrimmedCurve*>(curve.get()))
    return std::make_shared<TrimmedCurve>(piece->base(), piece->base_start() + s0, piece->base_start() + s1);
  return std::make_shared<TrimmedCurve>(curve, s0, s1);
}

}  // namespace drycut::geometry
