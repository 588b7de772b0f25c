#include "workload/deviation_passes.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace drycut::workload {
namespace {

Vec2 xy(const Vec3& p) { return {p.x(), p.y()}; }

using BlockKey = std::pair<std::string, uint32_t>;

// Appends the element's samples, leaving out its start when it repeats the previous end (the
// junction would otherwise count twice and bias the mean towards the knots).
void append_samples(std::vector<Vec3>& to, const SampledElement& e) {
  auto first = e.points.begin();
  if (!to.empty() && (to.back() - *first).norm() < 1e-9) ++first;
  to.insert(to.end(), first, e.points.end());
}
BlockKey key_of(const SampledElement& e) { return {e.source.file_name(), e.source.line}; }

// Unwrapped parameter fraction along the samples, the first one shifted by whole turns to lie
// nearest `start_near`.
std::vector<double> unwrap(const std::vector<Vec3>& points, const ReferenceContour& reference, double start_near) {
  std::vector<double> u;
  u.reserve(points.size());
  for (const Vec3& p : points) {
    const double raw = reference.nearest(xy(p)).u;
    if (u.empty()) {
      u.push_back(raw + std::round(start_near - raw));
      continue;
    }
    double du = raw - (u.back() - std::floor(u.back()));
    du -= std::round(du);  // into [-0.5, 0.5]: a step never covers half the curve
    u.push_back(u.back() + du);
  }
  return u;
}

// The samples of the contour's elements (feed moves with both ends within `capture_mm` of the
// curve); counts them, notes their blocks and the largest compensation radius in `split`.
std::vector<Vec3> contour_samples(const SampledProgram& program, const ReferenceContour& reference,
                                  double capture_mm, ContourSplit& split,
                                  std::set<BlockKey>& contour_blocks) {
  std::vector<Vec3> programmed;
  for (const SampledElement& e : program.programmed) {
    if (e.rapid) continue;
    if (reference.nearest(xy(e.start())).distance > capture_mm ||
        reference.nearest(xy(e.end())).distance > capture_mm)
      continue;
    ++split.contour_elements;
    contour_blocks.insert(key_of(e));
    if (e.compensation.side != interp::CompensationSide::None)
      split.tool_radius_mm = std::max(split.tool_radius_mm, e.compensation.radius_mm);
    append_samples(programmed, e);
  }
  return programmed;
}

// Pass index: whole turns from the first sample; a sample exactly on the seam goes with the
// pass that follows (the small bias), and slivers of a few samples are merged below.
std::vector<ContourPass> passes_by_turn(const std::vector<Vec3>& programmed, const std::vector<double>& u,
                                        double direction) {
  auto turn = [&](double value) { return std::floor(direction * value + 1e-4); };
  const double first_turn = turn(u.front());
  std::vector<ContourPass> passes;
  double current = -1;
  for (size_t i = 0; i < programmed.size(); ++i) {
    const double t = turn(u[i]) - first_turn;
    if (passes.empty() || t != current) {
      passes.emplace_back();
      passes.back().u_low = passes.back().u_high = u[i];
      current = t;
    }
    ContourPass& p = passes.back();
    p.programmed.push_back(programmed[i]);
    p.u_low = std::min(p.u_low, u[i]);
    p.u_high = std::max(p.u_high, u[i]);
  }
  return passes;
}

// Merge slivers (a sample or two on the seam) into a neighbour.
void merge_slivers(std::vector<ContourPass>& passes) {
  for (size_t i = 0; i < passes.size() && passes.size() > 1;) {
    if (passes[i].u_high - passes[i].u_low >= 2e-3) {
      ++i;
      continue;
    }
    ContourPass& into = i > 0 ? passes[i - 1] : passes[i + 1];
    const std::vector<Vec3>& sliver = passes[i].programmed;
    if (i > 0) into.programmed.insert(into.programmed.end(), sliver.begin(), sliver.end());
    else into.programmed.insert(into.programmed.begin(), sliver.begin(), sliver.end());
    into.u_low = std::min(into.u_low, passes[i].u_low);
    into.u_high = std::max(into.u_high, passes[i].u_high);
    passes.erase(passes.begin() + static_cast<std::ptrdiff_t>(i));
  }
}

// Tool-centre samples (unwrapped fractions `tu`) follow the passes in travel order.
void assign_tool_centre(std::vector<ContourPass>& passes, const std::vector<Vec3>& tool,
                        const std::vector<double>& tu, double direction) {
  size_t p = 0;
  for (size_t i = 0; i < tool.size(); ++i) {
    while (p + 1 < passes.size() &&
           (direction > 0 ? tu[i] > passes[p].u_high + 1e-4 : tu[i] < passes[p].u_low - 1e-4))
      ++p;
    passes[p].tool_centre.push_back(tool[i]);
  }
}

// The first and the last full loop; passes.size() for both when there is none.
struct FullLoops {
  size_t first, last;
};

// Marks the full loops and gives each pass its mean Z.
FullLoops measure_passes(std::vector<ContourPass>& passes) {
  FullLoops full{passes.size(), passes.size()};
  for (size_t i = 0; i < passes.size(); ++i) {
    ContourPass& p = passes[i];
    p.full_loop = p.u_high - p.u_low >= 0.99;
    double z = 0;
    for (const Vec3& q : p.programmed) z += q.z();
    p.mean_z_mm = z / static_cast<double>(p.programmed.size());
    if (p.full_loop) {
      if (full.first == passes.size()) full.first = i;
      full.last = i;
    }
  }
  return full;
}

// "loop 1", "loop 2", ...; partial passes are "entry" before the first loop, "exit" after the
// last and "part" between loops, or "part 1", "part 2", ... when there is no loop.
void name_passes(std::vector<ContourPass>& passes, FullLoops full) {
  size_t loops = 0, partial = 0;
  for (size_t i = 0; i < passes.size(); ++i) {
    ContourPass& p = passes[i];
    if (p.full_loop) p.name = "loop " + std::to_string(++loops);
    else if (full.first == passes.size()) p.name = "part " + std::to_string(++partial);
    else p.name = i < full.first ? "entry" : i > full.last ? "exit" : "part";
  }
}

// The full loop at the lowest Z; the longest pass when no pass is a full loop.
size_t bottom_loop(const std::vector<ContourPass>& passes, FullLoops full) {
  size_t bottom = 0;
  for (size_t i = 0; i < passes.size(); ++i) {
    const ContourPass& p = passes[i];
    const ContourPass& best = passes[bottom];
    const bool better = full.first == passes.size()
                            ? p.u_high - p.u_low > best.u_high - best.u_low
                            : p.full_loop && (!best.full_loop || p.mean_z_mm < best.mean_z_mm - 1e-6);
    if (better) bottom = i;
  }
  return bottom;
}

}  // namespace

ContourSplit split_contour(const SampledProgram& program, const ReferenceContour& reference, double capture_mm) {
  ContourSplit split;
  std::set<BlockKey> contour_blocks;
  const std::vector<Vec3> programmed = contour_samples(program, reference, capture_mm, split, contour_blocks);
  if (programmed.empty()) {
    split.bottom_loop = 0;
    return split;
  }
  std::vector<Vec3> tool;
  if (split.tool_radius_mm > 0)
    for (const SampledElement& e : program.tool_centre)
      if (contour_blocks.count(key_of(e))) append_samples(tool, e);

  const std::vector<double> u = unwrap(programmed, reference, 0.5);
  const double direction = u.back() >= u.front() ? 1.0 : -1.0;
  std::vector<ContourPass> passes = passes_by_turn(programmed, u, direction);
  merge_slivers(passes);
  if (!tool.empty()) assign_tool_centre(passes, tool, unwrap(tool, reference, u.front()), direction);

  const FullLoops full = measure_passes(passes);
  name_passes(passes, full);
  split.bottom_loop = bottom_loop(passes, full);
  split.passes = std::move(passes);
  return split;
}

}  // namespace drycut::workload
