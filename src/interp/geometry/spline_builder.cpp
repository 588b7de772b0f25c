#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry {

SplineBuilder::~SplineBuilder() = default;

}  // namespace drycut::geometry
