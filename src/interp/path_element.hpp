#pragma once
// The canonical boundary: the one interface between interpreter and planner. The interpreter
// turns blocks into a stream of these plain elements; the planner knows nothing else about
// the program. Every element carries the source block it came from.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "interp/geometry/curve.hpp"
#include "interp/geometry/projected_length.hpp"
#include "machine/dynamic_groups.hpp"
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
  Positioning,     // POS/POSA/SPOS/SPOSA: axes on their own interpolators (`positioning`)
  AxisWait,        // WAITP/WAITS (or an implicit wait): the program waits for positioning axes
};

// How consecutive blocks are joined (G group 10 plus G9).
enum class TransitionMode {
  ExactStop,   // G60, or G9 in this block: decelerate to rest at the block end
  Continuous,  // G64
  SmoothDistance,   // G641: rounding by distance ADIS/ADISPOS (src/interp/corner_smoothing.hpp)
  SmoothTolerance,  // G642/G643/G644/G645: rounding within tolerances (G644: as G64, not modelled)
};

// Which G code of group 10 selected the smoothing (0: none, else 641 ... 645) and the program's
// smoothing settings at the block (docs/smoothing.md). A negative tolerance means "not
// programmed": the machine/setting data value applies (CTOL=-1 restores it, so does reset).
struct SmoothingRequest {
  int code = 0;                  // 641, 642, 643, 644, 645; 0 under G60/G64
  double adis_mm = 0.0;          // ADIS= (path blocks), 0 = not programmed: G641 behaves as G64
  double adispos_mm = 0.0;       // ADISPOS= (G0 blocks)
  double ctol_mm = -1.0;         // CTOL= contour tolerance, < 0: SD42465 (smoothing) / SD42475 (compressor)
  double atol_mm[3] = {-1.0, -1.0, -1.0};  // ATOL[X/Y/Z]= axis tolerances, < 0: MD33100
};

enum class AccelProfile { Brisk, Soft };

// The NC block compressor of G group 30 (docs/compressor.md): COMPOF, COMPON, COMPCURV, COMPCAD.
// G group 30. COMPSURF (the Top Surface compressor, an option whose smoothing Siemens does not
// publish) is planned as COMPCAD, with a warning (docs/compressor.md).
enum class Compressor { Off, Compon, Compcurv, Compcad, Compsurf };

enum class StopKind { None, ProgramStop /*M0*/, OptionalStop /*M1*/, ProgramEnd /*M2/M30*/, Preprocessing /*STOPRE*/ };

// ACC[ax]=, VELOLIM[ax]=, JERKLIM[ax]=: factors (1 = 100 %) on the X/Y/Z axes' limits.
struct AxisLimitFactors {
  std::array<float, 3> accel{1.0f, 1.0f, 1.0f};
  std::array<float, 3> velocity{1.0f, 1.0f, 1.0f};
  std::array<float, 3> jerk{1.0f, 1.0f, 1.0f};
  bool operator==(const AxisLimitFactors&) const = default;
};

struct DynamicsMode {
  TransitionMode transition = TransitionMode::ExactStop;
  AccelProfile profile = AccelProfile::Brisk;
  bool exact_stop_this_block = false;  // G9
  machine::DynamicGroup group = machine::DynamicGroup::Norm;  // G group 59: which MD array element
  AxisLimitFactors limits;
};

// Tool radius compensation requested for the element (G40/G41/G42 and their companions). The
// interpreter records it; the compensation stage (src/interp/cutter_compensation) applies it.
enum class CompensationSide { None, Left /*G41*/, Right /*G42*/ };

// What F refers to under tool radius compensation (G group 16; Fundamentals, "Feedrate
// correction for circles and curves: CFC, CFTCP, CFIN"): the contour (CFC, reset default), the
// tool centre (CFTCP), or the contour only on inside curves (CFIN: the centre slows down there,
// it does not speed up outside).
enum class ContourFeed : uint8_t { Contour /*CFC*/, ToolCentre /*CFTCP*/, InsideOnly /*CFIN*/ };

struct CompensationRequest {
  CompensationSide side = CompensationSide::None;
  ContourFeed contour_feed = ContourFeed::Contour;
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
  // A turning tool with cutting edge position 1..8: the tool tip P the lengths are measured to,
  // seen from the cutting edge centre S the compensation guides (P - S, in the plane, machine
  // coordinates). Zero for every other tool: S is the reference point.
  geometry::Vec3 reference_shift = geometry::Vec3::Zero();
};

// A channel axis beyond X, Y, Z moving with the element (a synchronized axis: rotary A/B/C,
// linear U/V/W), interpolated linearly along it. `axis` indexes MachineProfile::extra_axes.
struct ExtraAxisMove {
  int axis = 0;
  std::string name;    // "A", "C1" (listings)
  double start = 0;    // machine position (degrees for a rotary axis)
  double travel = 0;   // signed
  bool in_feed_group = false;  // FGROUP: its travel counts in the length F refers to
  // mm of path per unit of travel in that length: FGREF[ax]=r gives a rotary axis 2·π·r/360 mm
  // per degree; 1 without FGREF (degrees count as mm).
  double feed_weight = 1.0;
};

// A programmed block inside a compressed span: it ends at `end_share` of the span's length.
struct SpanBlock {
  float end_share = 0;
  BlockRef block;
};

// The block of a span at `share` of its length (0..1): the first whose end lies at or after it.
inline const BlockRef& span_block_at(const std::vector<SpanBlock>& blocks, const BlockRef& fallback, double share) {
  if (blocks.empty()) return fallback;
  const auto it = std::lower_bound(blocks.begin(), blocks.end(), share,
                                   [](const SpanBlock& b, double s) { return b.end_share < s; });
  return it == blocks.end() ? blocks.back().block : it->block;
}

// A positioning axis (POS/POSA, SPOS/SPOSA): its own interpolator, from rest to rest.
struct PositioningMove {
  std::string axis;          // "A"; "S1" for spindle 1
  double travel = 0;         // distance (mm or degrees), >= 0
  double velocity = 0;       // FA, else MD32060 (spindle: MD35300), units per s
  double accel = 0;          // MAX_AX_ACCEL (spindle: MD35210)
  double jerk = 0;           // 0: no jerk limit (BRISKA)
  double lead_time_s = 0;    // SPOS of a turning spindle: braking to the positioning speed first
  bool block_synchronous = true;  // POS/SPOS: the block ends when it arrives; POSA/SPOSA run on
  double entry_velocity = 0;      // SPOS from rotation: turning at this speed when position control takes over
};

// A chamfer or rounding asked for at the end of this element (RND=, RNDM=, CHF=, CHR=; the
// filter in src/interp/contour_corners.hpp inserts it). size_mm is r or c, converted to mm.
enum class ContourCornerKind : uint8_t { None, Round /*RND, RNDM*/, Chamfer /*CHF*/, ChamferLeg /*CHR*/ };
struct ContourCornerRequest {
  ContourCornerKind kind = ContourCornerKind::None;
  double size_mm = 0.0;
  double feed_mm_s = 0.0;  // FRC / FRCM converted (0: the feed of the next block)
  bool modal = false;      // from RNDM (the label says so)
  int program_level = 0;   // the block's program level (the next motion must be in the same)
};

// G96 under G95 on a cut (interp/constant_cutting_speed.hpp): the spindle speed at a point p
// follows x = along·p + offset, the SCC axis's position in the workpiece system (tool length
// taken off), so the feed f·n changes along the element. Set by the interpreter; the last stage
// before the planner splits the element at its feeds (interp/cutting_speed_pieces.hpp).
struct CuttingSpeedLaw {
  double speed_mm_min = 0.0;  // Vc
  double min_rpm = 0.0;       // G25 (0: none)
  double max_rpm = 0.0;       // LIMS, G26, MD35100
  geometry::Vec3 along = geometry::Vec3::Zero();
  double offset = 0.0;
  double x_at(const geometry::Vec3& p) const { return along.dot(p) + offset; }
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
  // Of those: a straight piece to or from the offsets' intersection at an outside corner (G451,
  // or G450 flatter than MD20230). On the control that is the adjacent block lengthened, so the
  // compressor joins it with its neighbours (cutter_compensation.cpp, block_compressor.cpp).
  bool offset_extension = false;
  // The next element is a piece of the same programmed block (a G96 cut split at its feeds):
  // reported as one block with it; no block change (and no exact stop) between them.
  bool continues_block = false;
  std::shared_ptr<const CuttingSpeedLaw> cutting_speed;  // G96 under G95 on a straight cut

  DynamicsMode dynamics;
  double dwell_s = 0.0;          // Dwell
  // The spindle run-up (interp/interpreter_spindle_run_up.cpp): the element that begins ramp
  // `run_up_start` (0: none); on the dwell that waits for it, the ramp's id and its time into the
  // set range counted from that start (the planner times the wait from them).
  uint32_t run_up_start = 0;
  uint32_t run_up_wait = 0;
  double run_up_s = 0.0;
  StopKind stop = StopKind::None;
  CompensationRequest compensation;
  std::string label;             // what produced it: "G1", "G2", "ASPLINE", "M0", "M6 FR_4", "G4"
  BlockRef source;               // the block it belongs to
  // Synchronized axes beyond X, Y, Z (docs/axes.md); empty for most elements.
  std::vector<ExtraAxisMove> extra_axes;
  // The geometry axes in the feed group (FGROUP): bit 0 X, bit 1 Y, bit 2 Z; 7 is the default.
  uint8_t geometry_feed_axes = 7;
  std::vector<PositioningMove> positioning;  // Positioning
  std::vector<std::string> wait_axes;        // AxisWait: the axes waited for; empty = every axis
  // The compressor (src/interp/block_compressor.hpp): the mode active for the block, whether the
  // block was a "simple" G1 block it may join (nothing but axes X/Y/Z and F), and whether a
  // block that is not simple came between it and the previous element (that ends a run).
  Compressor compressor = Compressor::Off;
  bool compressible = false;
  bool follows_other_block = true;
  // Set on the compressor's output: how many programmed blocks the element replaces (0: not a
  // compressed element) and how far it strays from their programmed end points and lines (mm).
  uint32_t compressed_blocks = 0;
  double compress_deviation_mm = 0.0;
  // For a compressed span: the blocks it replaces, each with the share of the span's length at
  // which its programmed end point lies, so a feed dip inside the span is reported at the block
  // where it happens, not at the span's first (empty for every other element).
  std::vector<SpanBlock> span_blocks;
  // Corner smoothing (src/interp/corner_smoothing.hpp): the program's settings for the block,
  // and on the output: an inserted smoothing element has smoothing_deviation_mm >= 0 (its
  // closest distance to the programmed corner it rounds); a neighbour the stage trimmed keeps
  // the length of its programmed block for the short-block rule (0: its own length).
  SmoothingRequest smoothing;
  double smoothing_deviation_mm = -1.0;
  double block_length_mm = 0.0;
  // A chamfer or rounding programmed at the end of the element (interpreter output only).
  ContourCornerRequest corner;

  // The length the path feed F refers to and the planner plans along (FGROUP, PGA Fundamentals
  // "Feedrate (G93, G94, G95, F, FGROUP)"): the geometry's length counted on the grouped geometry
  // axes (all three by default; FGROUP(X,Y) on a helix: its length in the plane), with every
  // grouped extra axis's travel added as a further coordinate. A block moving no grouped axis but
  // others (`G1 A90 F1000`, or `G1 Z-5` under FGROUP(X,Y)) takes F for the axes it moves.
  double path_length() const {
    const double geometry = curve ? curve->length() : 0.0;
    if (extra_axes.empty() && geometry_feed_axes == 7) return geometry;
    const double grouped_geometry =
        geometry_feed_axes == 7 ? geometry : curve ? geometry::projected_length(*curve, geometry_feed_axes) : 0.0;
    double grouped = grouped_geometry * grouped_geometry, all = geometry * geometry;
    for (const auto& m : extra_axes) {
      all += m.travel * m.travel;
      if (m.in_feed_group) grouped += m.travel * m.travel * m.feed_weight * m.feed_weight;
    }
    return std::sqrt(grouped > 1e-18 ? grouped : all);
  }

  bool is_motion() const {
    return kind == ElementKind::Line || kind == ElementKind::Arc || kind == ElementKind::SplineSpan;
  }
};

// Receives the element stream (the planner, the path sampler, a test collecting a listing).
class ElementSink {
 public:
  virtual ~ElementSink() = default;
  virtual void consume(PathElement&& element) = 0;
  // Called once after the last element.
  virtual void finish() {}
};

}  // namespace drycut::interp
