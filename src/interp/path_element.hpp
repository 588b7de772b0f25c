#pragma once
// The canonical boundary: the one interface between interpreter and planner. The interpreter
// turns blocks into a stream of these plain elements; the planner knows nothing else about
// the program. Every element carries the source block it came from.
#include <string>

#include "interp/geometry/curve.hpp"
#include "machine/source_location.hpp"

namespace drycut::interp {

enum class ElementKind {
  Line,            // G0/G1 straight move
  Arc,             // G2/G3/CIP/CT arc or helix
  SplineSpan,      // one block's span of an A/B/C spline
  Dwell,           // G4: time passes, no motion
  Stop,            // M0/M1/M2/M30 or an explicit exact stop: the path comes to rest
  ToolChange,      // M6 (the path comes to rest; tool_change_time from the profile)
  DynamicsChange,  // a change of the modes below between motions (informational)
};

// How consecutive blocks are joined (G group 10 plus G9).
enum class TransitionMode {
  ExactStop,   // G60, or G9 in this block: decelerate to rest at the block end
  Continuous,  // G64
  SmoothDistance,   // G641 (treated as G64 by the planner until smoothing is modelled)
  SmoothTolerance,  // G642/G643/G645 (likewise)
};

enum class AccelProfile { Brisk, Soft };

enum class StopKind { None, ProgramStop /*M0*/, OptionalStop /*M1*/, ProgramEnd /*M2/M30*/, Preprocessing /*STOPRE*/ };

struct DynamicsMode {
  TransitionMode transition = TransitionMode::ExactStop;
  AccelProfile profile = AccelProfile::Brisk;
  bool exact_stop_this_block = false;  // G9
};

// Tool radius compensation requested for the element (G40/G41/G42 and their companions). The
// interpreter records it; the compensation stage (src/interp/cutter_compensation) applies it.
enum class CompensationSide { None, Left /*G41*/, Right /*G42*/ };

struct CompensationRequest {
  CompensationSide side = CompensationSide::None;
  double radius_mm = 0.0;        // cutter radius of the active tool edge (D)
  bool intersection_corners = false;  // G451 (true) or G450 transition arcs (false)
  bool contour_approach = false;      // KONT (true) or NORM (false)
  bool collision_detection = false;   // CDON
  double disc = 0.0;                  // DISC= (0..100) for G450
  int plane_normal_axis = 2;          // 2 = G17 (XY), 1 = G18 (ZX), 0 = G19 (YZ)
  // A frame that tilts the working plane (3+2 machining, CYCLE800): the plane's first axis and
  // normal in machine coordinates, the normal oriented so that `side` (already swapped for a
  // mirrored plane) is judged about it. Unset: the plane of plane_normal_axis.
  bool tilted = false;
  geometry::Vec3 tilted_first = geometry::Vec3::UnitX();
  geometry::Vec3 tilted_normal = geometry::Vec3::UnitZ();
};

struct PathElement {
  ElementKind kind = ElementKind::Line;
  geometry::CurvePtr curve;      // set for Line, Arc, SplineSpan
  bool rapid = false;            // G0
  double feed_mm_s = 0.0;        // path feed (mm/s) of this curve, already converted from G94/G95
  // Tool-centre length per programmed contour length (CFC: F holds on the contour, so the
  // compensation stage scales feed_mm_s by it). Velocities are reported divided by it: the
  // feed a programmer sees is the contour feed, as on the control's display.
  double feed_scale = 1.0;
  // An element the control inserts (G450 transition circle, intersection connector, join of a
  // cut-out stretch). It is not an NC block of its own, so the block-change (short-block) limit
  // does not apply to it.
  bool inserted = false;
  DynamicsMode dynamics;
  double dwell_s = 0.0;          // Dwell
  StopKind stop = StopKind::None;
  CompensationRequest compensation;
  std::string label;             // what produced it: "G1", "G2", "ASPLINE", "M0", "M6 FR_4", "G4"
  BlockRef source;               // the block it belongs to

  bool is_motion() const {
    return kind == ElementKind::Line || kind == ElementKind::Arc || kind == ElementKind::SplineSpan;
  }
};

// Receives the element stream (the planner, the path sampler, a test collecting a listing).
class ElementSink {
 public:
  virtual ~ElementSink() = default;
  virtual void consume(PathElement element) = 0;
  // Called once after the last element.
  virtual void finish() {}
};

}  // namespace drycut::interp
