#pragma once
// Internal to the interpreter's files (interpreter.cpp, interpreter_coordinates.cpp,
// interpreter_curves.cpp): the value ranges, small conversions and the per-block context.
#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interp/geometry/arc_solvers.hpp"
#include "interp/interpreter.hpp"

namespace drycut::interp::detail {

using Eigen::Vector3d;

inline constexpr double kMmPerInch = 25.4;
// Value ranges of the programming manual; beyond them the control raises an alarm (and drycut
// would otherwise report absurd times or convert out of range).
inline constexpr double kMinFeed = 0.001;          // F resolution (mm/min, inch/min, mm/rev)
inline constexpr double kMaxDwellS = 999999.999;   // G4 F range
inline constexpr double kMaxTurns = 999;           // TURN=0..999
inline constexpr double kMaxToolNumber = 32000;    // T number
inline constexpr double kMaxEdgeNumber = 32000;    // D number
inline constexpr int kUnsupported = 990006;  // catalogued: function not modelled, would change the path
inline constexpr int kValueLimited = 990013;  // catalogued warning: a value clipped to a machine limit
inline constexpr int kNotModelled = 990002;  // catalogued warning: no effect on the path modelled
// Largest value of a geometry address (9 digits before the decimal point, PGA Fundamentals
// "Address format"): beyond it a radius or knot span is no number the control takes.
inline constexpr double kMaxAddressValue = 999999999.999;

inline int axis_index(std::string_view name) {
  if (name.size() != 1) return -1;  // one compare, not a memcmp per letter
  switch (name[0]) {
    case 'X': return 0;
    case 'Y': return 1;
    case 'Z': return 2;
    default: return -1;
  }
}

// The machine axis of geometry axis X, Y, Z by its MD10000 AXCONF_MACHAX_NAME_TAB name: drycut's
// profiles name the machine axes after their channel axis with "1" (X1, Y1, Z1; the default
// machine data, machine_data_values.cpp), as G74/G75 address them (Fundamentals, "Fixed-point
// approach (G75)": `G75 FP=2 X1=0 Z1=0`).
inline int machine_axis_index(std::string_view name) {
  if (name.size() != 2 || name[1] != '1') return -1;
  return axis_index(name.substr(0, 1));
}

// The letters of further axes (A B C rotary, U V W linear by convention): a program may use them
// on a machine whose profile lacks them (a warning, never an alarm).
inline bool is_axis_letter_name(std::string_view n) {
  return n.size() == 1 && std::string_view("ABCUVW").find(n[0]) != std::string_view::npos;
}

// Extended axis addresses, an axis letter with a number (X2, Z3, C2, U1; Fundamentals, "Axis
// types"), and the lone assignable addresses Q and E: axes of the channel on machines whose
// profile lacks them. Together with the letters above and the machine axis names X1/Y1/Z1 they
// are the names drycut takes as an axis it does not simulate: warned wherever they stand (a
// word, POS[..], FA[..], WAITP(..), DIAMONA[..], ACC[..], FGROUP(..)), never an alarm.
inline bool is_extended_axis_address(std::string_view n) {
  if (n == "Q" || n == "E") return true;
  return n.size() > 1 && std::string_view("XYZABCUVWQE").find(n[0]) != std::string_view::npos &&
         n.find_first_not_of("0123456789", 1) == std::string_view::npos;
}

inline bool is_unsimulated_axis_name(std::string_view n) {
  return is_axis_letter_name(n) || is_extended_axis_address(n) || machine_axis_index(n) >= 0;
}

// A2/B2/C2 (orientation angles), A3/B3/C3 (direction vector), A4..C5 (surface normals): the tool
// orientation a 5-axis post writes in every block under TRAORI (Job Planning, "Three, four and
// five axis transformation"). drycut does not model orientation: warned, never an alarm; the
// compressor still joins such blocks (Job Planning, "Compression of the orientation").
inline bool is_orientation_word(std::string_view n) {
  return n.size() == 2 && (n[0] == 'A' || n[0] == 'B' || n[0] == 'C') && n[1] >= '2' && n[1] <= '5';
}

// A spindle as an axis, SP<n> (what SPI(n) gives: FA[SPI(1)], ACC[SPI(1)]).
inline bool is_spindle_axis_name(std::string_view n) {
  return n.size() > 2 && n.substr(0, 2) == "SP" &&
         std::all_of(n.begin() + 2, n.end(), [](char c) { return c >= '0' && c <= '9'; });
}

inline geometry::Plane to_geometry_plane(PlaneSelect plane) {
  switch (plane) {
    case PlaneSelect::G17: return geometry::Plane::G17;
    case PlaneSelect::G18: return geometry::Plane::G18;
    case PlaneSelect::G19: return geometry::Plane::G19;
  }
  return geometry::Plane::G17;
}

inline geometry::SplineEnd to_spline_end(SplineCondition condition, const Vector3d& tangent) {
  geometry::SplineEnd end;
  switch (condition) {
    case SplineCondition::Natural: end.condition = geometry::EndCondition::Natural; break;
    case SplineCondition::Tangent: end.condition = geometry::EndCondition::Tangent; break;
    case SplineCondition::Auto: end.condition = geometry::EndCondition::Auto; break;
  }
  end.tangent = tangent;
  return end;
}

// The programmable frame instruction a command names (A...: additive), if it is one.
inline std::optional<FrameInstruction> frame_instruction_kind(std::string_view name) {
  if (name == "TRANS" || name == "ATRANS") return FrameInstruction::Trans;
  if (name == "ROT" || name == "AROT") return FrameInstruction::Rot;
  if (name == "SCALE" || name == "ASCALE") return FrameInstruction::Scale;
  if (name == "MIRROR" || name == "AMIRROR") return FrameInstruction::Mirror;
  return std::nullopt;
}

// A block the NC block compressor may join (FB1 B1 "NC block compression": `N.. G1 X.. Y.. Z..
// F.. ;comment`, positions also as X=AC(..) or expressions): no word but G1, the positions of
// X/Y/Z and of the profile's further axes (A, C ...), tool orientation words (A3= ...) and F.
// Any other G code, M or H function, command, system-variable write, T, D ... interrupts
// compression (compress_rules.cpp).
bool is_simple_block(const parser::Block& block, const ExtraAxes& extra_axes);

// Minimum spline end-point blocks per window of 10 (facts §1.2).
inline int spline_quota(MotionMode mode, int cubic_spline_blocks) {
  switch (mode) {
    case MotionMode::ASpline: return 4;
    case MotionMode::BSpline: return 6;
    default: return std::min(10, cubic_spline_blocks + 1);
  }
}

}  // namespace drycut::interp::detail

namespace drycut::interp {

// Everything one block asks for, gathered before anything moves (SINUMERIK executes a block's
// words in a fixed order, not in the order they are written).
struct Interpreter::BlockContext {
  explicit BlockContext(const parser::Block& b) : block(b), named_words(has_named_words(b)) {}
  const std::string& file_name() const {
    static const std::string kNone;
    return block.file ? *block.file : kNone;
  }
  // An address of two or more letters (FP, AP, RP, ANG ...) in this block. A block of one-letter
  // words only (most blocks of a CAM program) answers at once, without a pass over its words.
  const parser::AddressWord* find_named(std::string_view name) const {
    return named_words ? block.find_address(name) : nullptr;
  }
  const parser::Block& block;
  const bool named_words;  // an address of two or more letters stands in the block
  bool exact_stop = false;      // G9
  bool suppress_offsets = false;  // G53, G153, SUPA: no frame for this block
  int home_move = 0;              // G74 (reference point) / G75 (fixed point) in this block
  bool tapping_chuck = false;     // G63: this block runs linear at F, the modal motion after it
  bool dwell = false;           // G4
  int speed_limit = 0;          // G25 / G26: S is the lower / upper spindle speed limit
  bool tool_change = false;     // M6
  std::optional<StopKind> stop;  // M0, M1, M2, M30
  bool preprocessing_stop = false;  // STOPRE
  bool motion_code = false;     // a group-1 code is written in this block
  // TRANS/ROT/SCALE/MIRROR (A...: additive): the axis words are the frame's values, not a target.
  std::optional<FrameInstruction> frame_instruction;
  bool additive_frame = false;
  int axial_offset = 0;  // G58 / G59: the axis words replace a part of the programmable translation
  std::optional<PoleReference> pole;  // G110/G111/G112: the axis or polar words define the pole
  bool compensation_changed = false;
  CompensationSide compensation_before = CompensationSide::None;  // G40/G41/G42 before this block
  double lead_change_mm = 0.0;  // F of a G34/G35 block (lead change per revolution)
  uint32_t compensation_column = 0;  // the G41/G42 word
  std::optional<double> block_feed;  // F in this block (not a G4 block)
  std::optional<double> nonmodal_feed;  // FB= of this block: its feed only, F stays modal
  bool contour_corner_done = false;     // the first of two ANG= lines ran: the angle is used
  int smooth_approach = 0;  // G147/G148/G247/G248/G347/G348 in this block (non-modal, group 2)
  double feed_before = 0.0;  // the modal F before this block's words
  // Extra axes written in this block (synchronized axes): index into the profile, the word.
  std::vector<std::pair<size_t, const parser::AddressWord*>> extra_words;
  std::vector<PositioningMove> positioning;  // POS/POSA/SPOS/SPOSA of this block
  std::vector<std::string> waits;            // WAITP/WAITS and implicit waits, before the motion
  double waits_until_s = 0;                  // when the last of them arrives (interpreter clock)
  // RND=/CHF=/CHR= of this block (RND wins over a chamfer in the same block), FRC= as programmed.
  ContourCornerKind corner = ContourCornerKind::None;
  double corner_size_mm = 0.0;
  uint32_t corner_column = 0;
  double frc = 0.0;
  bool corner_used = false;  // request_corner took the block's words
  bool simple = false;  // a block the active compressor may join: nothing but G1, X/Y/Z and F (compress_rules.cpp); false while none is active
  GeometryPositioning geometry_positioning = GeometryPositioning::None;  // POS/POSA of X/Y/Z

 private:
  static bool has_named_words(const parser::Block& b) {
    for (const parser::AddressWord& a : b.addresses)
      if (a.name.size() > 1) return true;
    return false;
  }
};


}  // namespace drycut::interp
