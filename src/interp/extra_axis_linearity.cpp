#include "interp/extra_axis_linearity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drycut::interp {

double ExtraAxisLinearity::tolerance(size_t axis) const {
  // MD33100 of the axis (degrees for a rotary axis); an axis the profile does not list keeps the
  // machine data's default.
  return axis < profile_.extra_axes.size() ? profile_.extra_axes[axis].compress_pos_tol_mm
                                           : machine::AxisData{}.compress_pos_tol_mm;
}

void ExtraAxisLinearity::restart() {
  length_ = 0.0;
  doors_.clear();
}

bool ExtraAxisLinearity::extend(const PathElement& e, double length) {
  if (e.extra_axes.empty() && doors_.empty()) {
    length_ += length;  // no further axis moved in the stretch: nothing to hold
    return true;
  }
  size_t axes = doors_.size();
  for (const ExtraAxisMove& m : e.extra_axes) axes = std::max(axes, static_cast<size_t>(m.axis) + 1);
  travel_.assign(axes, 0.0);
  for (const ExtraAxisMove& m : e.extra_axes) travel_[static_cast<size_t>(m.axis)] += m.travel;
  const double s = length_ + length;
  while (doors_.size() < axes) {
    // An axis that stood still so far: its points so far lie at travel 0, the tightest of their
    // intervals being the last one's.
    Door d;
    if (length_ > 0.0) {
      const double tol = tolerance(doors_.size());
      d = Door{0.0, -tol / length_, tol / length_, true};
    }
    doors_.push_back(d);
  }
  for (size_t a = 0; a < axes; ++a) {
    const Door& d = doors_[a];
    const double v = d.travel + travel_[a];
    if (s <= 0.0) {
      if (std::abs(v) > tolerance(a)) return false;
      continue;
    }
    const double r = v / s;
    if (d.open && (r < d.lo || r > d.hi)) return false;
  }
  if (s <= 0.0) {
    for (size_t a = 0; a < axes; ++a) doors_[a].travel += travel_[a];
    return true;
  }
  for (size_t a = 0; a < axes; ++a) {
    Door& d = doors_[a];
    d.travel += travel_[a];
    const double tol = tolerance(a);
    const double lo = (d.travel - tol) / s, hi = (d.travel + tol) / s;
    d.lo = d.open ? std::max(d.lo, lo) : lo;
    d.hi = d.open ? std::min(d.hi, hi) : hi;
    d.open = true;
  }
  length_ = s;
  return true;
}

}  // namespace drycut::interp
