#include "motion/planner.hpp"

#include <algorithm>
#include <cmath>

#include "interp/geometry/polynomial_span.hpp"
#include "machine/alarm.hpp"

namespace drycut::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxSegmentsPerElement = 20000;
constexpr size_t kSpareElements = 256;

DiscretisationRule discretisation_rule(const PlannerOptions& options) {
  DiscretisationRule rule;
  rule.equal_segments = options.reference_segments;
  rule.fixed_segment_mm = options.reference_segment_mm;
  rule.max_segments = kMaxSegmentsPerElement;
  return rule;
}

SourceLocation location_of(const BlockRef& ref) { return SourceLocation{ref.file_name(), ref.line, 0}; }

[[noreturn]] void raise(int number, const std::string& detail, const interp::PathElement& e) {
  throw AlarmError(make_alarm(number, detail, location_of(e.source), e.source.text));
}

RampLimits min_limits(RampLimits a, RampLimits b) {
  return {std::min(a.accel, b.accel), std::min(a.jerk, b.jerk)};
}

}  // namespace

Planner::Planner(const machine::MachineProfile& profile, PlanObserver& observer, PlannerOptions options)
    : profile_(profile),
      observer_(observer),
      options_(options),
      point_constraints_(default_point_constraints()),
      junction_constraints_(default_junction_constraints()),
      discretisation_(discretisation_rule(options)),
      dips_(options.dip_threshold, options.max_dips) {
  position_ = profile.start_position;
}

const PlanSummary& Planner::summary() const { return summary_; }

void Planner::validate(const interp::PathElement& e) const {
  if (e.is_motion()) {
    if (!e.curve) raise(990020, "motion element without geometry", e);
    const double length = e.path_length();
    if (!std::isfinite(length) || length < 0) raise(990020, "path length is not a finite number", e);
    if (!e.curve->start().allFinite() || !e.curve->end().allFinite())
      raise(990020, "path end points are not finite", e);
    if (!e.rapid) {
      if (std::isnan(e.feed_mm_s) || e.feed_mm_s == 0.0) raise(10860, "", e);
      if (e.feed_mm_s < 0 || !std::isfinite(e.feed_mm_s)) raise(14800, "", e);
    }
  } else if (e.kind == interp::ElementKind::Dwell) {
    if (!std::isfinite(e.dwell_s) || e.dwell_s < 0) raise(12160, "dwell time must be >= 0", e);
  }
}

void Planner::consume(interp::PathElement&& element) {
  validate(element);
  switch (element.kind) {
    case interp::ElementKind::Line:
    case interp::ElementKind::Arc:
    case interp::ElementKind::SplineSpan:
      if (element.path_length() > 1e-9) {
        append_motion(std::move(element));
      } else {
        append_passive(std::move(element));  // zero length: no motion, no corner
      }
      break;
    case interp::ElementKind::DynamicsChange:
      append_passive(std::move(element));
      break;
    case interp::ElementKind::Dwell: {
      stop_path(element);
      account_pause(element, dwell_time(element));
      break;
    }
    case interp::ElementKind::ToolChange:
      stop_path(element);
      account_pause(element, profile_.tool_change_time_s);
      break;
    case interp::ElementKind::Stop: {
      stop_path(element);
      // The program ends when every positioning axis is in position too.
      const double ready = element.stop == interp::StopKind::ProgramEnd ? positioning_.wait({}) : 0.0;
      account_pause(element, std::max(0.0, ready - clock_s_));
      if (element.stop == interp::StopKind::ProgramStop) seen_m0_ = true;
      break;
    }
    case interp::ElementKind::Positioning:
      append_positioning(std::move(element));
      break;
    case interp::ElementKind::AxisWait: {
      stop_path(element);
      const double ready = positioning_.wait(element.wait_axes);
      account_pause(element, std::max(0.0, ready - clock_s_));
      break;
    }
  }
}

void Planner::stop_path(const interp::PathElement& pause) {
  flush();
  note_run_up_start(pause);  // a pause that begins a spindle ramp begins it now
}

void Planner::note_run_up_start(const interp::PathElement& e) {
  if (e.run_up_start == 0) return;
  run_up_id_ = e.run_up_start;
  run_up_start_s_ = clock_s_;
}

double Planner::dwell_time(const interp::PathElement& e) const {
  if (e.run_up_wait == 0 || e.run_up_wait != run_up_id_) return e.dwell_s;
  return std::max(0.0, run_up_start_s_ + e.run_up_s - clock_s_);
}

void Planner::finish() {
  if (finished_) return;
  flush();
  finished_ = true;
  if (!any_cutting_) summary_.min_feed_mm_s = 0;
  summary_.dips = dips_.dips();
  summary_.dips_not_listed = dips_.not_listed();
}

void Planner::append_passive(interp::PathElement element) {
  if (nodes_.empty()) {
    // Nothing in motion: report it at once (zero time).
    note_run_up_start(element);
    BlockTiming t;
    t.source = element.source;
    t.label = element.label;
    t.rapid = element.rapid;
    t.after_first_m0 = seen_m0_;
    t.limit = Limit::ExactStop;
    ++summary_.elements;
    observer_.on_block(t);
    return;
  }
  WindowElement& w = new_window_element();
  w.element = std::move(element);
  w.dynamics = ElementDynamics{};
  w.segment_count = 0;
}

// The window's elements are recycled (a PathElement with its dynamics is larger than a deque
// block: one allocation per element otherwise). Addresses stay fixed while in the window.
Planner::WindowElement& Planner::new_window_element() {
  if (spare_elements_.empty()) {
    elements_.push_back(std::make_unique<WindowElement>());
  } else {
    elements_.push_back(std::move(spare_elements_.back()));
    spare_elements_.pop_back();
  }
  return *elements_.back();
}

void Planner::append_positioning(interp::PathElement element) {
  const auto& moves = element.positioning;
  const bool synchronous = std::any_of(moves.begin(), moves.end(), [](const auto& m) { return m.block_synchronous; });
  if (!synchronous && !nodes_.empty()) {
    append_passive(std::move(element));  // POSA starts when the path gets there (commit_front)
    return;
  }
  if (synchronous) flush();
  note_run_up_start(element);
  const double block_start = continues_block(element.source) ? block_start_s_ : clock_s_;
  double ready = clock_s_;
  for (const auto& m : moves) {
    if (m.block_synchronous) ready = std::max(ready, block_start + PositioningAxes::move_time(m));
    else positioning_.start(m, block_start);
  }
  account_pause(element, ready - clock_s_);
}

bool Planner::continues_block(const BlockRef& source) const {
  return block_known_ && source.line == block_line_ && source.file == block_file_;
}

void Planner::note_block_start(const BlockRef& source) {
  if (continues_block(source)) return;
  block_start_s_ = clock_s_;
  block_known_ = true;
  block_file_ = source.file;
  block_line_ = source.line;
}

namespace {

// 8 equal parameter steps of a corner rounding (step 8 of planner.hpp), each segment with the
// lower limits of its ends, as the equal segments of element_discretisation.hpp.
template <typename LimitsAt>
void rounding_stations(const geometry::PolynomialSpan& span, double length, const LimitsAt& limits_at,
                       std::vector<Station>& out) {
  out.clear();
  const double u_end = span.parameter_end();
  double s = 0.0;
  for (int k = 0; k <= 8; ++k) {
    const double u = u_end * k / 8.0;
    if (k > 0) s = k == 8 ? length : s + span.arc_length_between(u_end * (k - 1) / 8.0, u);
    const CurvePoint point = geometry::PolynomialSpan::by_arc_length(span.derivatives(u));
    const LocalLimits limits = limits_at(point);
    Station st{s, point, limits.bound, limits.ramp, {}, {}};
    if (k > 0) {
      const Station& prev = out.back();
      st.piece_bound = prev.bound.velocity <= st.bound.velocity ? prev.bound : st.bound;
      st.piece_ramp = {std::min(prev.ramp.accel, st.ramp.accel), std::min(prev.ramp.jerk, st.ramp.jerk)};
    }
    out.push_back(std::move(st));
  }
}

}  // namespace

// Fills stations_ for the element (see append_motion); returns whether its segments are timed
// along the ramp envelope, and their grid.
bool Planner::discretise(const WindowElement& w, double length, double& grid) {
  const geometry::Curve& curve = *w.element.curve;
  const ElementDynamics& dyn = w.dynamics;
  auto bound_at = [&](const CurvePoint& p) {
    VelocityBound b;
    for (const auto& c : point_constraints_) {
      const double v = c->max_velocity(dyn, p);
      if (v < b.velocity) b.tighten(v, c->limit());  // the limit's name only when it binds
    }
    if (dyn.rapid && b.limit == Limit::Feed) b.limit = Limit::Axis;
    return b;
  };

  std::vector<Station>& stations = stations_;
  bool envelope = false;
  if (w.element.kind == interp::ElementKind::Line) {
    stations.resize(2);
    stations[0].s = 0.0;
    stations[0].point = path_point(dyn, curve, 0.0);
    stations[0].bound = bound_at(stations[0].point);
    stations[0].ramp = tangential_limits(dyn, stations[0].point);
    stations[1] = stations[0];
    stations[1].s = length;
    stations[1].point = path_point(dyn, curve, length);
    stations[1].piece_bound = stations[0].bound;
    stations[1].piece_ramp = stations[0].ramp;
  } else {
    auto limits_at = [&](const CurvePoint& p) { return LocalLimits{bound_at(p), tangential_limits(dyn, p)}; };
    const double v_ref = dyn.rapid ? dyn.axis_velocity.minCoeff() : dyn.feed;
    const double fine_step = std::clamp(v_ref * profile_.ipo_cycle_s, 0.01, 0.5);
    // A corner-smoothing rounding is curved inside and its curvature changes fast: one up to
    // 8 h long gets 8 equal segments (its middle, where the curvature peaks, is a node), a
    // longer one is sampled as any span (step 1 and 8, "Corner smoothing").
    // The stations of a quadratic rounding (G641..G643: its speed varies by at most
    // 1/cos(θ/2) over the span) are taken at equal steps of its parameter, without the arc-length
    // inversion (a third of the planner's work on a program of roundings). G645's cubic, whose
    // speed varies more, keeps equal arc-length steps.
    DiscretisationRule rule = discretisation_;
    if (w.element.smoothing_deviation_mm >= 0 && !rule.equal_segments && length <= 8 * fine_step) {
      const auto* span = dynamic_cast<const geometry::PolynomialSpan*>(&curve);
      if (span && dyn.geometry_scale == 1.0 && w.element.smoothing.code != 645) {
        rounding_stations(*span, length, limits_at, stations);
        grid = length / std::clamp(std::ceil(length / fine_step), 1.0, double(kMaxSegmentsPerElement));
        return false;
      }
      rule.equal_segments = true;
      rule.fixed_segment_mm = length / 8 * (1 + 1e-12);
    }
    // With grouped extra axes the path parameter is not the curve's arc length: the discretiser
    // sees the curve through path_point (equal segments then; the arc rule needs an arc).
    const PathParameterCurve scaled(curve, dyn, length);
    const geometry::Curve& along = dyn.geometry_scale == 1.0 ? curve : scaled;
    envelope = discretise_element(along, length, fine_step, rule, limits_at, stations);
    grid = length / std::clamp(std::ceil(length / fine_step), 1.0, double(kMaxSegmentsPerElement));
  }
  return envelope;
}

void Planner::append_motion(interp::PathElement&& element) {
  WindowElement& w = new_window_element();
  // A spare still holds the block reference and curve of the element it carried (retire_front):
  // they go back with the caller's moved-from element to the thread that made them (the
  // producer's, interp/pipelined_sink.hpp), which writes the next block's text and line into them.
  BlockRef spare_source = std::move(w.element.source);
  geometry::CurvePtr spare_curve = std::move(w.element.curve);
  w.element = std::move(element);
  const double length = w.element.path_length();
  w.dynamics = make_element_dynamics(w.element, length, profile_);
  const ElementDynamics& dyn = w.dynamics;

  // Discretise: lines have constant limits, curves get nodes where their limits vary
  // (element_discretisation.hpp).
  std::vector<Station>& stations = stations_;
  double grid = 0;
  const bool envelope = discretise(w, length, grid);
  const size_t n = stations.size() - 1;
  const CurvePoint& start = stations[0].point;
  const VelocityBound start_bound = stations[0].bound;

  // The junction node: the window's start at rest, or the previous element's end.
  if (nodes_.empty()) {
    Node rest;
    rest.limit = 0;
    rest.limit_kind = Limit::ExactStop;
    rest.backward = 0;
    rest.backward_kind = Limit::ExactStop;
    nodes_.push_back(rest);
    front_velocity_ = 0;
    front_kind_ = Limit::ExactStop;
    front_anchor_ = {};
  } else {
    Node& j = nodes_.back();
    VelocityBound b{j.limit, j.limit_kind};
    b.tighten(start_bound.velocity, start_bound.limit);
    if (last_motion_) {
      Junction junction{last_motion_->element, last_motion_->dynamics, last_end_, w.element, dyn, start};
      for (const auto& c : junction_constraints_) b.tighten(c->max_velocity(junction), c->limit());
    }
    j.limit = b.velocity;
    j.limit_kind = b.limit;
  }

  for (size_t k = 1; k <= n; ++k) {
    const Station& a = stations[k - 1];
    const Station& b = stations[k];
    Segment seg;
    seg.length = b.s - a.s;
    seg.s_start = a.s;
    seg.cap = b.piece_bound.velocity;
    seg.ramp = b.piece_ramp;
    seg.envelope = envelope;
    seg.grid = grid;
    segments_.push_back(seg);
    Node node;
    node.limit = b.bound.velocity;
    node.limit_kind = b.bound.limit;
    if (k == n && ends_in_exact_stop(w.element)) {
      node.limit = 0;
      node.limit_kind = Limit::ExactStop;
    }
    nodes_.push_back(node);
  }
  w.segment_count = n;
  last_motion_ = &w;
  last_end_ = stations[n].point;
  ++motion_in_window_;

  backward_pass(false);
  peak_nodes_ = std::max(peak_nodes_, nodes_.size());
  peak_elements_ = std::max(peak_elements_, elements_.size());
  while (motion_in_window_ > static_cast<size_t>(profile_.lookahead_blocks)) commit_front();
  element.source = std::move(spare_source);
  element.curve = std::move(spare_curve);
}

double Planner::extend(RampAnchor& anchor, double v_here, const Segment& seg) {
  if (anchor.distance > 0) {
    const RampLimits chained_limits = min_limits(anchor.limits, seg.ramp);
    const double chained = ramp_reach(anchor.velocity, anchor.distance + seg.length, chained_limits);
    // The restart from here is only computed when a cheap upper bound of it beats the chain
    // (the passes' hot spot: mostly one ramp_reach per node instead of two; same decision).
    // Not even the bound when the segment's jerk limit is the chain's and the chained ramp
    // stays below full acceleration: such ramps do not depend on the acceleration limit, and
    // one ramp over a distance reaches at least as high as two ramps (the chain up to here,
    // then the restart) over it.
    const bool same_jerk_below_accel =
        seg.ramp.jerk == anchor.limits.jerk &&
        chained - anchor.velocity < chained_limits.accel * chained_limits.accel / chained_limits.jerk;
    const bool chain_wins = same_jerk_below_accel || chained >= reach_upper_bound(v_here, seg.length, seg.ramp);
    const double direct = chain_wins ? 0.0 : ramp_reach(v_here, seg.length, seg.ramp);
    if (chain_wins || chained >= direct) {
      anchor.distance += seg.length;
      anchor.limits = chained_limits;
      return chained;
    }
    anchor = {v_here, seg.length, seg.ramp};
    return direct;
  }
  anchor = {v_here, seg.length, seg.ramp};
  return ramp_reach(v_here, seg.length, seg.ramp);
}

bool Planner::reaches(const RampAnchor& anchor, double v_here, const Segment& seg, double target) {
  if (target <= v_here) return true;
  if (ramp_distance(v_here, target, seg.ramp) <= seg.length) return true;  // restarting here
  if (anchor.distance <= 0) return false;
  if (target <= anchor.velocity) return true;
  return ramp_distance(anchor.velocity, target, min_limits(anchor.limits, seg.ramp)) <= anchor.distance + seg.length;
}

void Planner::backward_pass(bool full) {
  const size_t last = nodes_.size() - 1;
  Node& end = nodes_[last];
  end.backward = 0;
  end.backward_kind = (end.limit == 0 && end.limit_kind == Limit::ExactStop) ? Limit::ExactStop : Limit::Lookahead;
  end.anchor = {};
  // Node 0 carries the committed velocity; it is never revised.
  for (size_t i = last; i-- > 1;) {
    Node& node = nodes_[i];
    const Node& next = nodes_[i + 1];
    RampAnchor anchor = next.anchor;
    // The node's own limit binds where the ramp reaches it. The reach is solved first: a pass
    // visits the nodes of the braking ramp into the window's end (~4 per append on short
    // blocks) and one node off it, so asking reaches() first (two inverse ramps) cost more on
    // the ramp's nodes than it saved on the one node off it.
    double b = node.limit;
    Limit kind = node.limit_kind;
    if (node.limit <= next.backward) {
      anchor = {};
    } else {
      const double reach = extend(anchor, next.backward, segments_[i]);
      if (node.limit <= reach) {
        anchor = {};
      } else {
        b = reach;
        kind = next.backward_kind;
      }
    }
    const bool settled = !full && b == node.backward && kind == node.backward_kind && b == node.limit;
    node.backward = b;
    node.backward_kind = kind;
    node.anchor = anchor;
    if (settled) break;
  }
}

// The forward pass's running values over the front element's segments (step 5).
struct Planner::CommitTally {
  double v;     // velocity at the current node
  Limit kind;   // the limit that bound it
  double v_min, v_max;
  Limit v_min_kind;
  // Lowest velocity outside planned standstills (ramps into and out of exact stops).
  double cut_min = kInf;
  Limit cut_kind = Limit::Feed;
  double cut_s = 0;  // where along the element (arc length) it occurs
  double time = 0;
  double length = 0;

  void note_cut(double vel, Limit k, double s) {
    if (k != Limit::ExactStop && vel < cut_min) {
      cut_min = vel;
      cut_kind = k;
      cut_s = s;
    }
  }
  // Moves on to the segment's end node, reached at v1 bound by k1.
  void advance(double v1, Limit k1, double s) {
    if (v1 < v_min) {
      v_min = v1;
      v_min_kind = k1;
    }
    note_cut(v1, k1, s);
    v = v1;
    kind = k1;
  }
};

void Planner::commit_front() {
  WindowElement& w = *elements_.front();
  const interp::PathElement& e = w.element;
  note_block_start(e.source);
  note_run_up_start(e);
  if (e.kind == interp::ElementKind::Positioning)
    for (const auto& m : e.positioning) positioning_.start(m, block_start_s_);

  CommitTally tally{.v = front_velocity_,
                    .kind = front_kind_,
                    .v_min = front_velocity_,
                    .v_max = front_velocity_,
                    .v_min_kind = front_kind_};
  if (w.segment_count > 0) tally.note_cut(tally.v, tally.kind, 0.0);
  for (size_t k = 0; k < w.segment_count; ++k) commit_segment(w, segments_[k], nodes_[k + 1], tally);
  if (w.segment_count > 0) {
    position_ = e.curve->end();
    position_known_ = true;
  }
  for (size_t k = 0; k < w.segment_count; ++k) {
    nodes_.pop_front();
    segments_.pop_front();
  }
  front_velocity_ = tally.v;
  front_kind_ = tally.kind;

  report_commit(w, tally);
  retire_front(w);
}

// One segment of the front element: the velocity at its end node, then its timed profile.
void Planner::commit_segment(const WindowElement& w, const Segment& seg, const Node& next,
                             CommitTally& tally) {
  const double v = tally.v;
  // A line segment whose end bound is reachable needs no reach (only arcs' envelopes use it).
  const bool bound_reached = !seg.envelope && reaches(front_anchor_, v, seg, next.backward);
  const double reach = bound_reached ? next.backward : extend(front_anchor_, v, seg);
  const RampAnchor rise = front_anchor_;
  double v1;
  Limit k1;
  if (next.backward <= reach) {
    v1 = next.backward;
    k1 = next.backward_kind;
    front_anchor_ = {};
  } else {
    v1 = reach;
    k1 = tally.kind;
  }
  double peak;
  const double duration = time_segment(w, seg, next, rise, v, reach, v1, peak);
  // A positive but absurdly small F would take forever: the control cannot move that slowly.
  if (!std::isfinite(duration)) raise(14800, "feed too small to traverse the block", w.element);
  clock_s_ += duration;
  tally.time += duration;
  tally.length += seg.length;
  tally.v_max = std::max(tally.v_max, peak);
  tally.advance(v1, k1, seg.s_start + seg.length);
}

// The duration of a segment run from v to v1 (`rise`: the forward ramp's anchor, `reach`: where
// it gets to) and its highest velocity in `peak`; emits the IPO samples if asked to.
double Planner::time_segment(const WindowElement& w, const Segment& seg, const Node& next,
                             const RampAnchor& rise, double v, double reach, double v1, double& peak) {
  double duration;
  if (seg.envelope && v >= seg.cap && v1 >= seg.cap) {
    duration = seg.length / seg.cap;  // cruise: no ramp in this segment
    peak = seg.cap;
    if (options_.emit_samples)
      emit_samples(w, seg, duration,
                   [&](double t) { return ProfileState{std::min(seg.cap * t, seg.length), seg.cap, 0, 0}; });
  } else if (seg.envelope) {
    RampAnchor fall = next.anchor;
    const double fall_far = extend(fall, next.backward, seg);
    const EnvelopeSegment profile = plan_envelope_segment(
        seg.length, seg.cap, {rise.velocity, rise.distance - seg.length, rise.limits, v, reach, seg.grid},
        {fall.velocity, fall.distance - seg.length, fall.limits, next.backward, fall_far, seg.grid});
    duration = profile.duration;
    peak = profile.peak;
    if (options_.emit_samples && std::isfinite(duration))
      emit_samples(w, seg, duration, [&](double t) { return evaluate(profile, t); });
  } else {
    const SegmentProfile profile = plan_segment(v, v1, seg.cap, seg.length, seg.ramp);
    duration = profile.duration;
    peak = profile.peak;
    if (options_.emit_samples && std::isfinite(duration))
      emit_samples(w, seg, duration, [&](double t) { return evaluate(profile, t); });
  }
  return duration;
}

// The committed element's BlockTiming for the observer, and its share of the summary.
void Planner::report_commit(WindowElement& w, CommitTally& tally) {
  const interp::PathElement& e = w.element;
  BlockTiming timing;
  timing.rapid = e.rapid;
  timing.after_first_m0 = seen_m0_;
  // Reported feeds are the ones the control displays: tool-centre velocity / feed_scale (the
  // contour feed where CFC/CFIN scaled the centre; the centre feed under CFTCP).
  const double to_contour = e.feed_scale > 0 ? 1.0 / e.feed_scale : 1.0;
  tally.v_max *= to_contour;
  tally.v_min *= to_contour;
  if (tally.cut_min < kInf) tally.cut_min *= to_contour;
  timing.time_s = tally.time;
  timing.length_mm = tally.length;
  timing.v_max_mm_s = tally.v_max;
  timing.v_min_mm_s = tally.v_min;
  timing.limit = tally.v_min_kind;

  add_to_summary(e, w.segment_count > 0, tally, to_contour);
  // The element leaves the window here: its source and label move into the timing uncopied.
  timing.source = std::move(w.element.source);
  timing.label = std::move(w.element.label);
  timing.compressed_blocks = w.element.compressed_blocks;
  timing.compress_deviation_mm = w.element.compress_deviation_mm;
  timing.smoothing_deviation_mm = w.element.smoothing_deviation_mm;
  if (block_so_far_ || e.continues_block) {
    // Pieces of one programmed block (a G96 facing cut at its changing feeds): one timing.
    if (block_so_far_) {
      BlockTiming& b = *block_so_far_;
      b.time_s += timing.time_s;
      b.length_mm += timing.length_mm;
      b.v_max_mm_s = std::max(b.v_max_mm_s, timing.v_max_mm_s);
      if (timing.v_min_mm_s < b.v_min_mm_s) {
        b.v_min_mm_s = timing.v_min_mm_s;
        b.limit = timing.limit;
      }
    } else {
      block_so_far_ = timing;
    }
    if (e.continues_block) {
      w.element.source = std::move(timing.source);
      return;
    }
    observer_.on_block(*block_so_far_);
    block_so_far_.reset();
  } else {
    observer_.on_block(timing);
  }
  w.element.source = std::move(timing.source);  // kept by the spare (append_motion)
}

// Totals, the lowest and highest cutting feed and the feed dips (feeds already at the contour).
void Planner::add_to_summary(const interp::PathElement& e, bool moved, const CommitTally& tally,
                             double to_contour) {
  summary_.time_s += tally.time;
  if (seen_m0_) summary_.time_after_m0_s += tally.time;
  summary_.path_length_mm += tally.length;
  ++summary_.elements;
  if (moved && !e.rapid) {
    summary_.max_feed_mm_s = std::max(summary_.max_feed_mm_s, tally.v_max);
    // A block run from standstill to standstill (G60, G9, a plunge after G0) has no velocity
    // outside its planned ramps but its top speed: that is the feed it cut at (not a dip).
    const double cut_low = tally.cut_min < kInf ? tally.cut_min : tally.v_max;
    summary_.min_feed_mm_s = any_cutting_ ? std::min(summary_.min_feed_mm_s, cut_low) : cut_low;
    any_cutting_ = true;
    if (tally.cut_min < kInf) {
      // Inside a compressed span: the programmed block at the lowest velocity.
      const BlockRef& at = interp::span_block_at(e.span_blocks, e.source, tally.length > 0 ? tally.cut_s / tally.length : 0.0);
      dips_.add(e.source, at, e.feed_mm_s * to_contour, tally.cut_min, tally.cut_kind, tally.length);
    }
  } else if (moved) {
    dips_.interrupt();
  }
}

// The committed element leaves the window (kept as a spare for reuse while there is room; it
// keeps its block reference and curve until append_motion hands them back).
void Planner::retire_front(WindowElement& w) {
  if (w.segment_count > 0) --motion_in_window_;
  if (last_motion_ == &w) last_motion_ = nullptr;
  if (spare_elements_.size() < kSpareElements) {
    spare_elements_.push_back(std::move(elements_.front()));
  }
  elements_.pop_front();
}

void Planner::flush() {
  if (nodes_.empty()) return;
  Node& end = nodes_.back();
  end.limit = 0;
  end.limit_kind = Limit::ExactStop;
  backward_pass(true);
  while (!elements_.empty()) commit_front();
  nodes_.clear();
  segments_.clear();
  motion_in_window_ = 0;
  last_motion_ = nullptr;
  front_velocity_ = 0;
  front_kind_ = Limit::ExactStop;
  front_anchor_ = {};
}

void Planner::account_pause(const interp::PathElement& e, double duration) {
  BlockTiming t;
  t.source = e.source;
  t.label = e.label;
  t.time_s = duration;
  t.limit = Limit::ExactStop;
  t.after_first_m0 = seen_m0_;
  if (options_.emit_samples) emit_rest_samples(e, duration);
  clock_s_ += duration;
  summary_.time_s += duration;
  if (seen_m0_) summary_.time_after_m0_s += duration;
  ++summary_.elements;
  dips_.interrupt();
  observer_.on_block(t);
}

void Planner::emit_samples(const WindowElement& w, const Segment& seg, double duration,
                           const std::function<ProfileState(double)>& state_at) {
  const double end = clock_s_ + duration;
  for (;;) {
    const double t = static_cast<double>(next_sample_) * profile_.ipo_cycle_s;
    if (t > end) break;
    const ProfileState st = state_at(t - clock_s_);
    const CurvePoint p = path_point(w.dynamics, *w.element.curve, seg.s_start + st.s);
    TrajectorySample sample;
    sample.t_s = t;
    sample.position = p.position;
    sample.v_mm_s = st.v;
    sample.a_mm_s2 = st.a;
    sample.j_mm_s3 = st.j;
    sample.source = &w.element.source;
    sample.tangent = p.tangent;
    sample.axis_velocity_mm_s = st.v * p.tangent;
    sample.axis_accel_mm_s2 = st.a * p.tangent + st.v * st.v * p.curvature_vector;
    observer_.on_sample(sample);
    ++next_sample_;
  }
}

void Planner::emit_rest_samples(const interp::PathElement& e, double duration) {
  const double end = clock_s_ + duration;
  for (;;) {
    const double t = static_cast<double>(next_sample_) * profile_.ipo_cycle_s;
    if (t > end) break;
    TrajectorySample sample;
    sample.t_s = t;
    sample.position = position_;
    sample.source = &e.source;
    observer_.on_sample(sample);
    ++next_sample_;
  }
}

}  // namespace drycut::motion
