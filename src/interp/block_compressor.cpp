#include "interp/block_compressor.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace drycut::interp {
namespace {

const char* compressor_label(Compressor mode) {
  switch (mode) {
    case Compressor::Compon: return "COMPON";
    case Compressor::Compcurv: return "COMPCURV";
    case Compressor::Compcad: return "COMPCAD";
    case Compressor::Compsurf: return "COMPSURF";
    case Compressor::Off: break;
  }
  return "COMPOF";
}

bool same_dynamics(const DynamicsMode& a, const DynamicsMode& b) {
  return a.transition == b.transition && a.profile == b.profile && a.exact_stop_this_block == b.exact_stop_this_block &&
         a.limits == b.limits;
}

// A straight G1 element of a simple block (not one the compensation inserted: a transition
// circle or connector keeps its own geometry; the pieces to and from the offsets' intersection
// at a flat outside corner are their blocks lengthened and join).
bool compressible_line(const PathElement& e) {
  return e.compressible && e.kind == ElementKind::Line && (!e.inserted || e.offset_extension) && e.curve &&
         e.compressor != Compressor::Off;
}

}  // namespace

BlockCompressor::BlockCompressor(ElementSink& next, const machine::MachineProfile& profile)
    : next_(next), profile_(profile), linearity_(profile) {}

geometry::CompressorFitOptions BlockCompressor::fit_options(const machine::MachineProfile& profile, Compressor mode) {
  const machine::CompressorData& c = profile.compressor;
  geometry::CompressorFitOptions o;
  o.continuity = mode == Compressor::Compon ? geometry::FitContinuity::C1 : geometry::FitContinuity::C2;
  const bool compcad = mode == Compressor::Compcad || mode == Compressor::Compsurf;  // COMPSURF: as COMPCAD
  // COMPON/COMPCURV join up to 10 blocks per polynomial; COMPCAD any number (FB1 B1).
  o.max_segments_per_span = compcad ? 0 : static_cast<size_t>(c.max_blocks_per_span);
  // MD20482 units digit: 0/2 the axis tolerances MD33100, 1/3 the contour tolerance SD42475.
  const int units = c.mode % 10;
  o.contour_tolerance = units == 1 || units == 3;
  o.contour_tol_mm = c.contur_tol_mm;
  for (int i = 0; i < 3; ++i) o.axis_tol_mm[i] = profile.axes[static_cast<size_t>(i)].compress_pos_tol_mm;
  // SD42470 is COMPCAD's corner angle; COMPON/COMPCURV detect no corners (a corner they cannot
  // round within the tolerance stays a pair of straight blocks, compressor_fit.hpp step 6).
  o.corner_angle_deg = compcad ? c.crit_spline_angle_deg : 180.0;
  return o;
}

bool BlockCompressor::joins_run(const PathElement& e) const {
  if (points_.empty() || !compressible_line(e) || e.follows_other_block || e.compressor != run_mode_) return false;
  const double length = e.curve->length();
  if (length > profile_.compressor.block_path_limit_mm) return false;
  if (std::abs(e.feed_mm_s - run_feed_mm_s_) > profile_.compressor.velo_tol_mm_s) return false;
  // Under G41/G42 with CFC the feed is the tool centre's, scaled per block by its length ratio
  // (a few per mille from chord to chord on a curved contour): the programmed contour feed must
  // stay within MD20172 as well, not the ratio be equal.
  if (std::abs(e.feed_mm_s / e.feed_scale - run_feed_mm_s_ / run_feed_scale_) > profile_.compressor.velo_tol_mm_s)
    return false;
  if (!same_dynamics(e.dynamics, run_dynamics_)) return false;
  // A zero-length block joins only a run that has a segment for it to ride on.
  if (length <= 0.0 && elements_.empty()) return false;
  return (e.curve->start() - points_.back()).norm() <= 1e-9 * (1.0 + points_.back().norm());
}

void BlockCompressor::start_run(const PathElement& e) {
  points_.assign(1, e.curve->start());
  start_tangent_.reset();
  run_mode_ = e.compressor;
  run_feed_mm_s_ = e.feed_mm_s;
  run_feed_scale_ = e.feed_scale;
  run_tolerances_ = e.smoothing;
  run_dynamics_ = e.dynamics;
}

void BlockCompressor::consume(PathElement&& element) {
  if (joins_run(element)) {
    const double length = element.curve->length();
    if (!linearity_.extend(element, length)) {
      // A further axis changes its rate along the path beyond MD33100: the run is cut here and
      // goes on from its last point with its tangent (extra_axis_linearity.hpp).
      flush(true);
      linearity_.restart();
      if (!joins_run(element) || !linearity_.extend(element, length)) {
        flush(false);
        start_or_pass(std::move(element));
        return;
      }
    }
    if (length > 0.0) points_.push_back(element.curve->end());
    point_of_.push_back(points_.size() - 1);
    elements_.push_back(std::move(element));
    if (points_.size() > static_cast<size_t>(profile_.compressor.flush_points)) {
      flush(true);
      linearity_.restart();
    }
    return;
  }
  flush(false);
  start_or_pass(std::move(element));
}

void BlockCompressor::start_or_pass(PathElement&& element) {
  if (compressible_line(element) && element.curve->length() > 0.0 &&
      element.curve->length() <= profile_.compressor.block_path_limit_mm) {
    start_run(element);
    linearity_.restart();
    linearity_.extend(element, element.curve->length());  // the first block always fits its line
    points_.push_back(element.curve->end());
    point_of_.push_back(1);
    elements_.push_back(std::move(element));
    return;
  }
  next_.consume(std::move(element));
}

void BlockCompressor::finish() {
  flush(false);
  next_.finish();
}

std::vector<SpanBlock> BlockCompressor::blocks_of_span(const geometry::FittedSpan& span, size_t begin, size_t end) {
  // The span's parameter is the chord length of the programmed points (compressor_fit.hpp,
  // step 2), so a block's end lies at its share of that chord length along the span.
  double total = 0.0;
  for (size_t p = span.first + 1; p <= span.last; ++p) total += (points_[p] - points_[p - 1]).norm();
  std::vector<SpanBlock> out;
  out.reserve(end - begin);
  double chord = 0.0;
  size_t p = span.first;
  for (size_t i = begin; i < end; ++i) {
    for (; p < point_of_[i]; ++p) chord += (points_[p + 1] - points_[p]).norm();
    if (elements_[i].offset_extension) continue;  // its block follows
    const float share = total > 0.0 ? static_cast<float>(chord / total) : 1.0f;
    if (i == begin) out.push_back(SpanBlock{share, elements_[i].source});  // (the span keeps its source)
    else out.push_back(SpanBlock{share, std::move(elements_[i].source)});
  }
  return out;
}

void BlockCompressor::flush(bool carry) {
  if (elements_.empty()) {
    points_.clear();
    return;
  }
  spans_.clear();
  geometry::CompressorFitOptions options = fit_options(profile_, run_mode_);
  // CTOL= / ATOL[ax]= of the program replace the contour / axis tolerances (PGA "CTOL, OTOL,
  // ATOL"); a block that programs them is not simple, so a run shares its first block's. A
  // programmed CTOL holds whatever tolerance set MD20482 selects, with priority over ATOL.
  if (run_tolerances_.ctol_mm > 0) {
    options.contour_tol_mm = run_tolerances_.ctol_mm;
    options.contour_tolerance = true;
  }
  for (int i = 0; i < 3; ++i)
    if (run_tolerances_.atol_mm[i] > 0) options.axis_tol_mm[i] = run_tolerances_.atol_mm[i];
  spans_ = geometry::fit_compressed_run(points_, options, start_tangent_);
  size_t next_element = 0;
  for (const geometry::FittedSpan& span : spans_) {
    const size_t begin = next_element;
    while (next_element < elements_.size() && point_of_[next_element] <= span.last) ++next_element;
    if (!span.curve) {
      for (size_t i = begin; i < next_element; ++i) next_.consume(std::move(elements_[i]));
      continue;
    }
    // Blocks, not elements: the pieces to an offsets' intersection belong to their block.
    std::vector<SpanBlock> span_blocks = blocks_of_span(span, begin, next_element);
    const size_t blocks = span_blocks.size();
    PathElement out = std::move(elements_[begin]);
    out.span_blocks = std::move(span_blocks);
    merge_extra_axes(out, begin + 1, next_element);
    out.kind = ElementKind::SplineSpan;
    out.curve = span.curve;
    out.label = compressor_label(run_mode_);
    out.inserted = out.offset_extension = false;  // a span of programmed blocks
    out.compressed_blocks = static_cast<uint32_t>(std::max<size_t>(1, blocks));
    out.compress_deviation_mm = span.deviation_mm;
    next_.consume(std::move(out));
  }
  const geometry::Vec3 last = points_.back();
  const std::optional<geometry::Vec3> tangent =
      spans_.empty() ? std::nullopt : std::optional<geometry::Vec3>(spans_.back().end_tangent);
  elements_.clear();
  point_of_.clear();
  points_.clear();
  if (carry) {
    // The next window goes on from the last point with the tangent this one ended with.
    points_.push_back(last);
    start_tangent_ = tangent;
  }
}

void BlockCompressor::merge_extra_axes(PathElement& span, size_t from, size_t to) const {
  // The further axes (A, C ...) of the blocks a span replaces move with it: each from where the
  // first of those blocks found it, by the sum of their travels, linearly along the span as in
  // any block (the compressor fits the X/Y/Z points only).
  for (size_t i = from; i < to; ++i) {
    for (const ExtraAxisMove& m : elements_[i].extra_axes) {
      auto same = std::find_if(span.extra_axes.begin(), span.extra_axes.end(),
                               [&](const ExtraAxisMove& s) { return s.axis == m.axis; });
      if (same == span.extra_axes.end()) span.extra_axes.push_back(m);
      else same->travel += m.travel;
    }
  }
}

}  // namespace drycut::interp
