#pragma once
// The interpreter's modal state: everything a block leaves behind for the next one (G groups,
// units, frames, feed, spindle, dynamics modes, spline conditions, compensation).
// Tool and edge live in ToolState (interp/tool_state.hpp).
// Reset values come from the machine profile's reset_gcodes (the MD20150 analogue), not from code.
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "interp/diameter_programming.hpp"
#include "interp/frame_chain.hpp"
#include "interp/path_element.hpp"
#include "interp/polar_coordinates.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

// G group 1 (with the spline types, which are members of it on the SINUMERIK).
enum class MotionMode {
  Rapid, Linear, ArcCw, ArcCcw, ArcThroughPoint, ArcTangent, ASpline, BSpline, CSpline,
  Polynomial /*POLY*/, Thread /*G33*/, ThreadIncreasing /*G34*/, ThreadDecreasing /*G35*/, Tapping /*G331*/, TappingRetract /*G332*/
};

// G group 15: what F means.
enum class FeedMode { PerMinute /*G94*/, PerRevolution /*G95*/, InverseTime /*G93*/ };

enum class PlaneSelect { G17, G18, G19 };

enum class SplineCondition { Natural, Tangent, Auto };  // BNAT/ENAT, BTAN/ETAN, BAUTO/EAUTO

enum class SpindleState { Stopped, Clockwise, CounterClockwise };

struct ModalState {
  MotionMode motion = MotionMode::Linear;
  PlaneSelect plane = PlaneSelect::G17;
  bool absolute = true;             // G90 (true) / G91
  bool inch = false;                // G70/G700: geometry in inch
  bool feed_in_geometry_unit = false;  // G700/G710: F in the unit of the geometry, else in the base unit (MD10240)
  FeedMode feed_mode = FeedMode::PerMinute;
  // G group 15 as it concerns the spindle: G96/G961/G962 (S is m/min at the tool) or not, and
  // whether LIMS acts (under G96, G961, G962 and G97; not under G93-G95, G971-G973).
  bool constant_cutting_speed = false;
  bool lims_acts = false;
  double spindle_speed_limit = 0.0;     // LIMS= rev/min (0 = none)
  double thread_lead_mm = 0.0;          // last thread lead I/J/K of G33..G35/G331/G332 (mm/rev)
  int thread_lead_axis = 2;             // the axis of that lead (I: X, J: Y, K: Z)
  std::string work_offset = "G500"; // G500, G54..G57, G505..G599
  FrameChain frames;                // settable and programmable frame (src/interp/frame_chain.hpp)
  PolarState polar;                 // pole, AP, RP
  double feed = 0.0;                // as programmed (per minute, per revolution, or 1/min under G93)
  // G93/G94/G95 changed and no F programmed since: the old value would be read in the new unit
  // (Fundamentals, "Feedrate": F is to be programmed again after such a change).
  bool feed_type_changed = false;
  double feed_unit_mm = 1.0;        // mm per length unit of F when it was programmed (25.4: inch)
  // FZ tooth feed as programmed (0: none, F governs); under G95 the feed per revolution is
  // FZ times the active edge's number of teeth. Deleted by a change of G93/G94/G95.
  double tooth_feed = 0.0;
  double tooth_feed_unit_mm = 1.0;  // as feed_unit_mm, for FZ
  double spindle_rpm = 0.0;         // S outside G96 (rev/min); G97 freezes the G96 speed into it
  double cutting_speed = 0.0;       // S under G96/G961/G962 (m/min, ft/min); 0: none programmed yet
  double cutting_speed_svc = 0.0;  // SVC= in m/min (ft/min), 0: the speed is the S programmed
  SpindleState spindle = SpindleState::Stopped;
  TransitionMode transition = TransitionMode::ExactStop;  // G60/G64/G641/G642...
  SmoothingRequest smoothing;  // G641..G645 and ADIS/ADISPOS/CTOL/ATOL (corner_smoothing.hpp)
  AccelProfile accel = AccelProfile::Brisk;               // BRISK/SOFT
  int exact_stop_window = 601;  // G601/G602/G603: read back by $P_GG[12], no effect on the set-point
  machine::DynamicGroup dynamic_group = machine::DynamicGroup::Norm;  // DYNNORM ... DYNPREC
  AxisLimitFactors axis_limits;                                       // ACC[ax] VELOLIM[ax] JERKLIM[ax]
  SplineCondition spline_begin = SplineCondition::Natural;
  SplineCondition spline_end = SplineCondition::Natural;
  int bspline_degree = 3;           // SD=
  CompensationSide compensation = CompensationSide::None;  // G40/G41/G42
  bool intersection_corners = false;  // G451 / G450
  bool contour_approach = false;      // KONT / NORM
  bool collision_detection = false;   // CDON / CDOF
  ContourFeed contour_feed = ContourFeed::Contour;  // CFC / CFTCP / CFIN
  double disc = 0.0;                  // DISC=
  // Smooth approach and retraction (smooth_approach.hpp): G140..G143, G340/G341 and the values
  // last programmed with DISR=, DISCL= (DISCL=AC(): absolute), FAD= (0: none), kept as the
  // control keeps them [I: modal].
  int sar_side_rule = 140;
  bool sar_in_plane = false;
  double sar_disr = 0.0;
  double sar_discl = 0.0;
  bool sar_discl_absolute = false;
  double sar_fad = 0.0;
  int sar_fad_type = 0;  // FAD=PM(..): 94, FAD=PR(..): 95, 0: the active feed type
  double offn_mm = 0.0;            // OFFN=: contour offset added to the tool radius under G41/G42
  Compressor compressor = Compressor::Off;  // COMPOF / COMPON / COMPCURV / COMPCAD / COMPSURF
  DiameterState diameter;             // DIAMON/DIAMOF/DIAM90/DIAMCYCOF, DIAMONA[ax] ... (MD20100)
  int cutting_speed_axis = 0;         // SCC[ax]: the axis whose position is G96's radius (X..Z)
  double rndm_mm = 0.0;               // RNDM=: modal rounding radius (0: off; contour_corners.hpp)
  double frcm = 0.0;                  // FRCM=: modal chamfer/rounding feed as programmed (0: off)

  // Applies one reset/program code by name ("G64", "SOFT", "BTAN", ...). Returns false if the
  // name is not a modal code this state knows (the caller decides whether that is an error).
  bool apply_code(std::string_view name);

  int plane_normal_axis() const { return plane == PlaneSelect::G17 ? 2 : plane == PlaneSelect::G18 ? 1 : 0; }
  // G17: (X, Y, normal Z); G18: (Z, X, normal Y); G19: (Y, Z, normal X).
  PlaneIndices plane_indices() const { return indices_of(plane); }
  static PlaneIndices indices_of(PlaneSelect p) {
    return p == PlaneSelect::G17 ? PlaneIndices{0, 1, 2} : p == PlaneSelect::G18 ? PlaneIndices{2, 0, 1} : PlaneIndices{1, 2, 0};
  }
  bool thread_mode() const {
    return motion == MotionMode::Thread || motion == MotionMode::ThreadIncreasing ||
           motion == MotionMode::ThreadDecreasing || motion == MotionMode::Tapping ||
           motion == MotionMode::TappingRetract;
  }
  // G0 or G1: the motions a contour definition by angle (ANG=) applies to.
  bool straight_mode() const { return motion == MotionMode::Linear || motion == MotionMode::Rapid; }
  bool spline_mode() const {
    return motion == MotionMode::ASpline || motion == MotionMode::BSpline || motion == MotionMode::CSpline;
  }
};

// The state at program start: every code of the profile's reset list applied in order.
// Throws machine::ProfileError naming a reset code this state does not know.
ModalState reset_state(const machine::MachineProfile& profile);

std::string_view motion_mode_name(MotionMode mode);

}  // namespace drycut::interp
