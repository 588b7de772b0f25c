#pragma once
// The motion planner: consumes the PathElement stream and produces timing.
//
// ALGORITHM
// =========
// 1. Discretisation (element_discretisation.hpp). Every motion element becomes one or more
//    SEGMENTS between NODES on the path; the node between two elements (the JUNCTION) is
//    shared. A segment's cap and ramp limits are the worst case of the limits over it.
//    - A line has constant limits: one segment.
//    - A circle or helix (ArcCurve) costs what its limits vary, not its length: it starts as
//      ONE segment whose worst case is closed-form (per axis the largest |t_i|, |κ_i|, |P'''_i|
//      over the swept angle, from the ends and the interior extremes of the sine/cosine
//      components). Only where that worst case is more than 2 % below the better end (the
//      velocity bound varies, e.g. the axis or centripetal limit on a fast small arc), or, near
//      the element's ends where ramps run, the ramp jerk/acceleration varies by more than 5 %
//      (of the ramp time under SOFT), it is cut: first at the critical angles (quadrant points,
//      zeros of a helix tangent component), then in halves. On the 200,000-block arc benchmark
//      (bench/arcs) about 2 segments per arc instead of ~100.
//      These segments are timed along the RAMP ENVELOPE (envelope_segment.hpp): the limit of
//      the short equal segments used before, with the first cells next to a standstill timed
//      as those segments ran them, so planned times stay within 0.1 % of the former rule.
//    - Other curves (spline spans, offset curves) have no closed form. One not longer than
//      h = clamp(v_ref·T_IPO, 0.01 mm, 0.5 mm) (v_ref = F, or the rapid velocity) is one
//      segment with the lower limits of its ends (the former rule). A longer one is SAMPLED by
//      the variation of its own limits: a piece's worst case is that of the per-axis largest
//      |t_i|, |κ_i|, |P'''_i| at its ends and midpoint; it is halved while that worst case is
//      more than 0.2 % below the better end (ramp limits near the ends: 0.2 %) or the tangent
//      turns by more than 0.05 rad between samples (then a component's extreme between samples
//      exceeds the nearest sample by at most 1 - cos 0.025, 0.03 %). Pieces are timed along the
//      ramp envelope with the grid of h, as arcs: a span whose limits stay above F is one
//      segment instead of ceil(L/h). Planned times: within 0.1 % of 0.005 mm segments under
//      BRISK and of the former h segments under SOFT (tests/motion/arc_discretisation_test.cpp),
//      the reference experiment moved by at most 0.06 %.
//    PlannerOptions::reference_segments cuts every curve into the equal segments of h (or of
//    reference_segment_mm) instead: the former rule, a reference for tests.
//
// 2. Limits (path_constraints.hpp). At each node the POINT constraints give an upper bound on
//    the path velocity, each with its Limit tag: programmed F, axis velocity
//    v·|t_i| <= vmax_i, centripetal acceleration v²·|κ_i| <= share·a_i, SOFT curvature jerk
//    v³·|P'''_i| <= j_i, short block v <= factor·L/T_IPO. A segment's interior cap is the
//    lower of its two end nodes (on arcs: its closed-form worst case, step 1). At a junction the JUNCTION constraints apply too: exact
//    stop (G60/G9 -> 0) and the G64 overload rule |v·(t2_i - t1_i)| <= a_i·(OVL-1)·T_IPO.
//    Before Dwell, Stop and ToolChange the path ends at rest (the window is flushed).
//    Each segment also carries its tangential RampLimits: a_t = min_i a_i'/|t_i| (a_i' =
//    axis acceleration × SOFT/G0 factor, × (1 - share) where the path is curved) and, under
//    SOFT, j_t = min(path jerk, min_i j_i/|t_i|); under BRISK j_t = infinity.
//
// 3. Window. The planner keeps at most `lookahead_blocks` motion elements (nodes and segments
//    in ring buffers, the elements themselves in a deque). The LAST node of the window is
//    assumed to end at rest (Limit::Lookahead) as on the control, so memory never grows with
//    program length. When a new element arrives the old last node becomes an ordinary junction.
//
// 4. Backward pass (run after each append, from the new last node towards the front).
//    b[last] = 0; b[i] = min(limit[i], reach from b[i+1] backwards over segment i).
//    "Reach" is the closed-form ramp of velocity_ramp.hpp: trapezoid (BRISK) or jerk-limited
//    S-curve starting at zero acceleration (SOFT). A ramp that spans several short segments
//    is followed as ONE S-curve from its ANCHOR (the last node where a limit bound), using
//    the smallest acceleration and jerk seen since the anchor; if restarting from the
//    previous node reaches higher, the anchor moves there. Each node remembers its anchor.
//    Early exit (as grblHAL's "planned" pointer): once a node comes out unchanged and bound
//    by its own limit, nothing before it can change, so the pass stops there. Values only
//    grow as the window grows, so a velocity committed earlier stays feasible.
//
// 5. Commit (forward pass). When the window holds more than lookahead_blocks motion elements
//    (or on a flush) the FRONT element is committed: starting from the committed velocity at
//    its first node, v[i+1] = min(b[i+1], reach forward from v[i]) (anchored the same way).
//    Each segment then gets its profile: accelerate, cruise at the cap, decelerate, with
//    zero acceleration at both nodes; a segment too short for that (part of a ramp running
//    over several segments) uses constant acceleration between its node velocities, which
//    never exceeds the ramp's acceleration. A segment of a circle or helix instead follows
//    min(cap, rising ramp envelope, falling ramp envelope) from the two anchors (step 1).
//    Time = sum of the segment durations.
//    The element's BlockTiming (time, length, v_max, v_min and the Limit that bound v_min:
//    the limit at the node or, on a ramp, the limit the ramp comes from) goes to the
//    observer; optional samples at every IPO cycle (t = k·T_IPO) are evaluated from the
//    segment profiles.
//
// 6. Flush. Dwell, Stop, ToolChange and finish() flush: the last node is a real stop
//    (Limit::ExactStop), a full backward pass runs, and every element is committed. Dwell
//    adds dwell_s, ToolChange the profile's tool_change_time_s, M0 takes no time (the
//    operator restarts) but starts the "after M0" clock. The wait for the spindle run-up
//    (a Dwell with run_up_wait, interp/interpreter_spindle_run_up.cpp) is timed here: the
//    clock when the element that began its ramp started (run_up_start, noted when that
//    element is committed or, for a pause, reached) plus the ramp time run_up_s, less the
//    clock now; if that element never came through (another stage dropped its mark), the
//    interpreter's estimate dwell_s stands.
//
// 7. Extra axes (docs/axes.md). A synchronized extra axis (rotary A/B/C ...) moves linearly
//    along its element. The planner plans along the PATH LENGTH (PathElement::path_length:
//    the feed group's length, FGROUP), so the geometry's derivatives are scaled by
//    geometry_scale = curve length / path length (path_point) and each extra axis adds the
//    constant share t = travel / path length to the axis-velocity, tangential-acceleration,
//    jerk and corner rules above. Positioning axes (POS/POSA/SPOS, WAITP/WAITS) run beside the
//    path on their own interpolators (positioning_axes.hpp): POS flushes and waits, POSA starts
//    when the path reaches its block and is waited for at WAITP, a new programming or M30.
//
// 8. Corner smoothing (G641/G642/G643/G645; interp/corner_smoothing.hpp, docs/smoothing.md).
//    What the control does: it cuts both blocks at a corner and inserts a rounding block, which
//    the path runs through at the speed its curvature and the axis dynamics allow instead of
//    the G64 overload-factor corner velocity (FB1 B1 "Continuous-path mode"; the rounding
//    blocks of G641/G642 run with constant acceleration; each block takes at least one IPO
//    cycle). What drycut does: the stage before the planner delivers the trimmed lines and the
//    rounding as a SplineSpan (smoothing_deviation_mm >= 0). The planner times it like any
//    spline span, by the point constraints of step 2 (centripetal acceleration within
//    MD20602's share, SOFT curvature jerk), except that one up to 8 h long is cut into 8 equal
//    segments, each with the lower limits of its ends (step 1's "not longer than h" rule would
//    give a short rounding the limits of its ends only, and the sampled refinement follows its
//    fast-changing curvature into hundreds of pieces: 2.3x the CPU time on a COMPCAD raster).
//    Its middle, where a symmetric rounding's curvature peaks, is a node. A quadratic rounding
//    (G641..G643) gets its 8 stations at equal parameter steps instead, with their arc length
//    from a 5-node Gauss rule per step (no arc-length inversion; its speed varies by at most
//    1/cos(θ/2), so the steps stay within that ratio of equal lengths).
//    The junctions are tangent-continuous, so the G64 corner rule gives no limit there; under
//    SOFT the curvature step of a quadratic rounding (0 on the line, sin θ/(2d) on the
//    rounding) meets the curvature-step rule of step 2 (G645's cubic has none). The rounding is
//    a block for the short-block rule (its own length), the trimmed lines keep their programmed
//    block's length for it. *(guess)* The control's own rounding polynomial and its velocity
//    profile in the rounding block (MD20480 hundreds digit) are not published; drycut's Bezier
//    shapes are documented in corner_smoothing.hpp.
//
// Guarantees (tests/motion/planner_property_test.cpp): on lines every IPO sample keeps each
// axis velocity and acceleration within 1e-6 of its limit; on arcs the limits hold at the
// nodes and samples between them stay within 2 %. Jerk is limited inside each closed-form
// segment profile and by the curvature-jerk constraint at constant speed; where a ramp meets
// a limit, the opposite ramp or a block transition the acceleration may step (jerk is not
// checked there; at a step of the curvature between blocks the junction velocity is the one
// MD32432 PATH_TRANS_JERK_LIM allows, path_constraints.hpp, the step itself is taken at once).
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"
#include "motion/element_discretisation.hpp"
#include "motion/element_dynamics.hpp"
#include "motion/envelope_segment.hpp"
#include "motion/feed_dip_collector.hpp"
#include "motion/path_constraints.hpp"
#include "motion/plan_result.hpp"
#include "motion/positioning_axes.hpp"
#include "motion/ring_buffer.hpp"
#include "motion/velocity_ramp.hpp"

namespace drycut::motion {

class Planner : public interp::ElementSink {
 public:
  Planner(const machine::MachineProfile& profile, PlanObserver& observer, PlannerOptions options = {});

  void consume(interp::PathElement&& element) override;
  void finish() override;
  const PlanSummary& summary() const;

  // Window size now and the largest seen (memory stays bounded by the look-ahead depth).
  size_t window_nodes() const { return nodes_.size(); }
  size_t peak_window_nodes() const { return peak_nodes_; }
  size_t peak_window_elements() const { return peak_elements_; }

 private:
  // A ramp followed from the node where it started (see step 4).
  struct RampAnchor {
    double velocity = 0;
    double distance = 0;  // 0: the ramp starts at the current node
    RampLimits limits;
  };
  struct Node {
    double limit = 0;
    Limit limit_kind = Limit::Feed;
    double backward = 0;
    Limit backward_kind = Limit::Lookahead;
    RampAnchor anchor;
  };
  struct Segment {
    double length = 0;
    double s_start = 0;  // arc length in the element where the segment starts
    double cap = 0;
    RampLimits ramp;
    bool envelope = false;  // timed along the ramp envelope (envelope_segment.hpp)
    double grid = 0;        // h of the former equal segments of its element (envelope only)
  };
  struct WindowElement {
    interp::PathElement element;
    ElementDynamics dynamics;
    size_t segment_count = 0;
  };

  void append_motion(interp::PathElement&& element);
  WindowElement& new_window_element();
  bool discretise(const WindowElement& w, double length, double& grid);
  void append_passive(interp::PathElement element);
  void append_positioning(interp::PathElement element);
  // The run clock when the block of the element being committed started (POS/POSA timing).
  bool continues_block(const BlockRef& source) const;
  void note_block_start(const BlockRef& source);
  void backward_pass(bool full);
  // Step 5, the commit of the front element, in its parts.
  struct CommitTally;  // planner.cpp
  void commit_front();
  void commit_segment(const WindowElement& w, const Segment& seg, const Node& next, CommitTally& tally);
  double time_segment(const WindowElement& w, const Segment& seg, const Node& next, const RampAnchor& rise,
                      double v, double reach, double v1, double& peak);
  void report_commit(WindowElement& w, CommitTally& tally);
  void add_to_summary(const interp::PathElement& e, bool moved, const CommitTally& tally, double to_contour);
  void retire_front(WindowElement& w);
  void flush();
  void account_pause(const interp::PathElement& element, double duration);
  void emit_samples(const WindowElement& e, const Segment& seg, double duration,
                    const std::function<ProfileState(double)>& state_at);
  void emit_rest_samples(const interp::PathElement& element, double duration);
  void validate(const interp::PathElement& element) const;
  static double extend(RampAnchor& anchor, double v_here, const Segment& seg);
  // Whether extend() would reach `target` (its result >= target), without solving for the
  // reach: the inverse ramp (a distance) costs at most a square root, the reach a cube root.
  static bool reaches(const RampAnchor& anchor, double v_here, const Segment& seg, double target);

  machine::MachineProfile profile_;  // a copy: callers may pass a temporary
  PlanObserver& observer_;
  PlannerOptions options_;
  std::vector<std::unique_ptr<PointConstraint>> point_constraints_;
  std::vector<std::unique_ptr<JunctionConstraint>> junction_constraints_;
  DiscretisationRule discretisation_;
  std::vector<Station> stations_;  // reused by append_motion

  std::deque<std::unique_ptr<WindowElement>> elements_;
  std::vector<std::unique_ptr<WindowElement>> spare_elements_;  // popped elements, for reuse
  RingBuffer<Node> nodes_;
  RingBuffer<Segment> segments_;
  size_t motion_in_window_ = 0;
  // The last motion element with length in the window, for the next junction.
  const WindowElement* last_motion_ = nullptr;
  geometry::CurvePoint last_end_;

  // Forward state at the front node.
  double front_velocity_ = 0;
  Limit front_kind_ = Limit::ExactStop;
  RampAnchor front_anchor_;

  double clock_s_ = 0;
  uint64_t next_sample_ = 0;
  Vec3 position_ = Vec3::Zero();
  bool position_known_ = false;
  bool seen_m0_ = false;
  bool finished_ = false;
  bool any_cutting_ = false;
  size_t peak_nodes_ = 0;
  size_t peak_elements_ = 0;
  FeedDipCollector dips_;
  PlanSummary summary_;
  std::optional<BlockTiming> block_so_far_;  // the pieces of one block committed so far (report_commit)
  PositioningAxes positioning_;
  double block_start_s_ = 0;
  // The spindle ramp whose start was last passed (id 0: none) and the clock then.
  uint32_t run_up_id_ = 0;
  double run_up_start_s_ = 0;
  void note_run_up_start(const interp::PathElement& e);
  void stop_path(const interp::PathElement& pause);  // flush() before a pause element
  double dwell_time(const interp::PathElement& e) const;
  bool block_known_ = false;
  FileName block_file_ = nullptr;
  uint32_t block_line_ = 0;
};

}  // namespace drycut::motion
