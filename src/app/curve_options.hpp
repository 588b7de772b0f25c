#pragma once
// The curve options shared by generate, deviation and sweep: --polar, --parametric, --points, or
// the reference experiment's contour when none is given.
#include <string>

#include <CLI/CLI.hpp>

#include "workload/curve_source.hpp"

namespace drycut::app {

struct CurveOptions {
  std::string polar;       // r(T), T the polar angle in degrees
  std::string parametric;  // "x(T);y(T)[;z(T)]", T in degrees over [0, 360)
  std::string points_csv;  // measured points x,y[,z], one per line: a closed polyline
};

void add_curve_options(CLI::App& cmd, CurveOptions& options);

// Builds the curve (the thesis contour r = 18 + 4 cos 6θ cos 2θ when no option is given).
// Throws UsageError for an unreadable file, AlarmError for a bad expression.
workload::CurveSource make_curve(const CurveOptions& options);

}  // namespace drycut::app
