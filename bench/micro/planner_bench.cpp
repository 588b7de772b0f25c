// Motion planner cost per element: short G1 lines in G64 (the CAM case) and arcs (discretised
// into many segments). The elements are built before the timed loop.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "machine/machine_profile.hpp"
#include "motion/planner.hpp"

namespace {

using namespace drycut;
using geometry::Vec3;

interp::PathElement cutting_element(geometry::CurvePtr curve, double feed_mm_min) {
  interp::PathElement e;
  e.kind = interp::ElementKind::Line;
  e.curve = std::move(curve);
  e.feed_mm_s = feed_mm_min / 60.0;
  e.dynamics.transition = interp::TransitionMode::Continuous;
  e.dynamics.profile = interp::AccelProfile::Soft;
  e.label = "G1";
  e.source.file = intern_file_name("BENCH.MPF");
  return e;
}

// A spiral polyline of 0.05..0.5 mm steps, as the scale benchmark's programs.
std::vector<interp::PathElement> spiral_lines(size_t count) {
  std::vector<interp::PathElement> v;
  double theta = 0, r = 20;
  Vec3 p(r, 0, 0);
  for (size_t i = 0; i < count; ++i) {
    const double ds = 0.05 + 0.45 * std::fmod(static_cast<double>(i) * 0.6180339887, 1.0);
    theta += ds / r;
    r = 20 + theta * 0.1 / (2 * M_PI);
    const Vec3 q(r * std::cos(theta), r * std::sin(theta), 0);
    v.push_back(cutting_element(std::make_shared<geometry::LineCurve>(p, q), 1500 + 500 * (i / 1000 % 4)));
    p = q;
  }
  return v;
}

void BM_PlannerShortLines(benchmark::State& state) {
  const size_t count = static_cast<size_t>(state.range(0));
  const std::vector<interp::PathElement> elements = spiral_lines(count);
  const machine::MachineProfile profile = machine::default_profile();
  for (auto _ : state) {
    motion::PlanObserver observer;
    motion::Planner planner(profile, observer);
    for (const auto& e : elements) planner.consume(e);
    planner.finish();
    benchmark::DoNotOptimize(planner.summary().time_s);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_PlannerShortLines)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_PlannerArcs(benchmark::State& state) {
  // Quarter circles of radius 5 mm (7.9 mm each): discretised into many segments per element.
  const size_t count = static_cast<size_t>(state.range(0));
  std::vector<interp::PathElement> elements;
  for (size_t i = 0; i < count; ++i) {
    auto arc = std::make_shared<geometry::ArcCurve>(Vec3(0, 0, 0), 5.0, Vec3::UnitX(), Vec3::UnitY(),
                                                    static_cast<double>(i) * M_PI / 2, M_PI / 2, 0.0);
    interp::PathElement e = cutting_element(arc, 3000);
    e.kind = interp::ElementKind::Arc;
    elements.push_back(std::move(e));
  }
  const machine::MachineProfile profile = machine::default_profile();
  for (auto _ : state) {
    motion::PlanObserver observer;
    motion::Planner planner(profile, observer);
    for (const auto& e : elements) planner.consume(e);
    planner.finish();
    benchmark::DoNotOptimize(planner.summary().time_s);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_PlannerArcs)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
