#pragma once
// Points along a curve every ds of arc length, both ends included (for path listings and tests).
#include <vector>

#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// ds <= 0 or non-finite returns just the two end points. The last step may be shorter than ds.
std::vector<Vec3> sample_curve(const Curve& curve, double ds);

}  // namespace drycut::geometry
