// Spline construction while streaming points: the per-block cost of ASPLINE / CSPLINE / BSPLINE
// (builder, span polynomial and its arc-length table).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "interp/geometry/spline_builder.hpp"

namespace {

using namespace drycut::geometry;

// Points on a circle of radius 50 mm, 0.3 mm apart: a CAM-like fine spline.
Vec3 circle_point(size_t i) {
  const double angle = static_cast<double>(i) * 0.3 / 50.0;
  return {50.0 * std::cos(angle), 50.0 * std::sin(angle), 0.0};
}

template <class MakeBuilder>
void run_spline(benchmark::State& state, MakeBuilder make) {
  const size_t points = static_cast<size_t>(state.range(0));
  for (auto _ : state) {
    std::unique_ptr<SplineBuilder> builder = make();
    SplineSpan span;
    double length = 0;
    for (size_t i = 0; i < points; ++i) {
      builder->add_point(circle_point(i), 1.0, 0.0);
      while (builder->pop_span(span)) length += span.curve->length();
    }
    builder->finish(SplineEnd{});
    while (builder->pop_span(span)) length += span.curve->length();
    benchmark::DoNotOptimize(length);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_AkimaSplinePerPoint(benchmark::State& state) {
  run_spline(state, [] { return make_akima_builder(SplineEnd{}); });
}
BENCHMARK(BM_AkimaSplinePerPoint)->Arg(1000);

void BM_WindowedCubicSplinePerPoint(benchmark::State& state) {
  run_spline(state, [] { return make_cubic_builder(SplineEnd{}, 8); });
}
BENCHMARK(BM_WindowedCubicSplinePerPoint)->Arg(1000);

void BM_NurbsSplinePerPoint(benchmark::State& state) {
  run_spline(state, [] { return make_nurbs_builder(3); });
}
BENCHMARK(BM_NurbsSplinePerPoint)->Arg(1000);

}  // namespace
