#pragma once
// The NC block compressor stage (COMPON / COMPCURV / COMPCAD, docs/compressor.md): an element
// filter between the tool radius compensation and the planner. It gathers runs of G1 elements
// the interpreter marked compressible and hands them on as polynomial spans
// (geometry/compressor_fit.hpp); everything else passes unchanged and in order.
//
// A run grows while each new element
//   - is compressible (a simple G1 block, PathElement::compressible) under the same compressor,
//     with no other block between it and the run (follows_other_block false),
//   - is not longer than MD20170 COMPRESS_BLOCK_PATH_LIMIT,
//   - keeps F within MD20172 COMPRESS_VELO_TOL of the run's first block,
//   - keeps the dynamics mode (G60/G64..., BRISK/SOFT) and starts where the run ends.
// A run whose further axes (A, C ...) leave a straight line over path length by more than their
// MD33100 is cut there and goes on from its last point with its tangent, as at a window cut
// (extra_axis_linearity.hpp): a span moves those axes linearly.
// Anything else ends the run: it is fitted and handed on, then the element follows.
// Memory stays bounded: a run that reaches `flush_points` points (profile, drycut's choice) is
// fitted and handed on at once; the next window starts at its last point with its end tangent,
// so the path stays tangent-continuous across the cut (curvature may step there).
// Each span element copies its first block's element (source, feed, dynamics), is a SplineSpan
// labelled with the compressor, and records how many blocks it replaces and its deviation.
#include <optional>
#include <vector>

#include "interp/extra_axis_linearity.hpp"
#include "interp/geometry/compressor_fit.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

class BlockCompressor final : public ElementSink {
 public:
  BlockCompressor(ElementSink& next, const machine::MachineProfile& profile);

  void consume(PathElement&& element) override;
  void finish() override;

  // The fit settings the profile gives a compressor mode (COMPON: C1 and 10 blocks per span ...).
  static geometry::CompressorFitOptions fit_options(const machine::MachineProfile& profile, Compressor mode);

 private:
  bool joins_run(const PathElement& element) const;
  void start_run(const PathElement& first);
  // Starts a run with `element` when it can begin one, else hands it on.
  void start_or_pass(PathElement&& element);
  // Fits the run and hands on its elements in order. carry: the run goes on from its last
  // point (a window cut, `flush_points`); else it is closed.
  void flush(bool carry);
  // The blocks of elements_[begin, end) with where each ends along `span` (their sources moved
  // out, but for the first, which the span keeps).
  std::vector<SpanBlock> blocks_of_span(const geometry::FittedSpan& span, size_t begin, size_t end);
  // Adds the further-axis travels of elements_[from, to) to a span made from an earlier element.
  void merge_extra_axes(PathElement& span, size_t from, size_t to) const;

  ElementSink& next_;
  const machine::MachineProfile& profile_;
  // The run: points_[0] is where it starts; element i ends at points_[point_of_[i]] (a
  // zero-length element shares the point of the element before it).
  std::vector<geometry::Vec3> points_;
  std::vector<PathElement> elements_;
  std::vector<size_t> point_of_;
  std::optional<geometry::Vec3> start_tangent_;
  // What every element of the run shares with its first one.
  Compressor run_mode_ = Compressor::Off;
  double run_feed_mm_s_ = 0.0;
  double run_feed_scale_ = 1.0;
  DynamicsMode run_dynamics_;
  SmoothingRequest run_tolerances_;  // CTOL/ATOL of the run's first block
  std::vector<geometry::FittedSpan> spans_;  // reused
  ExtraAxisLinearity linearity_;  // the further axes since the run's start or last cut
};

}  // namespace drycut::interp
