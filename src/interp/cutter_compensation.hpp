#pragma once
// Tool radius compensation G41/G42/G40 as a stage of the element stream: it turns the PROGRAMMED
// elements into TOOL-CENTRE elements (SINUMERIK group 7, with G450/G451, NORM/KONT, CDON/CDOF).
//
// What is modelled (docs/controller-state.md; PGsl "Tool radius compensation"):
// - Selection: the first motion with side != None is the approach, always a straight move.
//   NORM: it ends perpendicular to the start direction of the next element in the plane
//   (tool centre = next start + r * normal on the compensation side). KONT: if the approach
//   meets the contour at an outside corner (start point "behind" the contour) the tool ends the
//   approach perpendicular to the approach direction and travels around the start point by the
//   G450/G451 rule; otherwise as NORM. The approach keeps its own block.
// - Deselection: the first motion with side == None (G40) starts perpendicular at the end of the
//   last compensated element (NORM) and goes straight to its programmed end point; KONT goes
//   around the end point first when that is an outside corner.
// - Outside corners: G450 circle of the tool radius around the corner (DISC is not modelled:
//   always the plain circle) unless the direction change is below MD20230 (then the
//   intersection), G451 the intersection of the offset lines unless the direction change
//   exceeds MD20210 (then the circle); cutter_compensation_corner.hpp. Corner elements belong
//   to the NEXT block.
//   A joint whose offset points are closer than 1e-6 mm is tangential and gets no corner element.
// - Offsets of lines and arcs in the plane are exact LineCurves / ArcCurves; anything else is a
//   geometry::OffsetCurve. Only the in-plane part is offset; for the normal see below.
// - Inside corners and loops (one model for both): the raw tool-centre path is the chain of the
//   offsets, with a straight "gap bridge" from one offset's end to the next one's start at every
//   inside joint. That raw path folds over itself wherever the tool cannot follow the contour: at
//   an inside corner (the bridge runs backwards), and where a line, arc or spline span bends
//   tighter than the tool radius on the compensation side (the offset runs backwards). Such a
//   fold is removed by cutting the raw path at the point where it crosses itself, which is where
//   the control's intersection search finds it: between the offsets of one block, of adjacent
//   blocks, or of blocks up to MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS apart (so an inside corner
//   followed by blocks shorter than r tan(angle/2) is resolved several blocks on; a fold under
//   CDOF further, see below). Only a stretch
//   that contains such a fold is cut: a crossing of sound offsets (a contour that crosses itself,
//   a loop over the same path at another depth) stays. The approach and the retract move take
//   part in the search (an entry spline that turns back sharply loops across its approach).
//   Every block cut out completely gets warning 10763. Alarm 10751 (collision danger): a gap
//   bridge that is still in the path when it leaves the window (no crossing within the checked
//   blocks: an inside corner, W1 "Compensation at inner corners", predictive search over MD20240).
// - Folds (an offset running backwards where the contour bends tighter than the tool radius, its
//   blocks joined tangentially, so no inside corner between blocks): under CDON the MD20240 reach
//   applies as to inside corners (10751 when the fold leaves the window uncut). Under CDOF (the
//   reset default) the control searches the previous block and "if necessary even earlier
//   blocks" (PGA, CDON/CDOF); MD20240 is the limit of CDON and of the inside-corner prediction.
//   So an open CDOF fold holds the window (itself and the MD20240 blocks before it, where its
//   loop's incoming side lies) until a later offset crosses it, however many blocks on; a fold
//   still open at G40, at the end or kFoldSearchBlocks on is a collision (10751). Inside corners
//   keep their MD20240 reach while a fold holds the window. Rule, evidence (the B-spline entry
//   of EKVI_B_90 / POLAR_B_1): docs/controller-state.md, "Bottleneck detection and folds".
// - The normal axis (Z under G17) follows the programmed blocks: where the tool centre is in step
//   with the program it is at the programmed value; where the compensation shortens, cuts or
//   joins blocks, the motion along the normal is spread over the in-plane length so that both
//   sides of a cut meet at one point in 3-D (no element moves the normal axis alone, no vertical
//   step at an inside corner); inserted elements share their block's slope
//   (cutter_compensation_normal_axis.hpp).
// - Feed: the tool-centre path gets the programmed F unchanged (F is the tool-centre velocity,
//   not CFC's contour velocity). Every output element keeps the source block, feed, dynamics and
//   label of the block it comes from; a block split into several elements stops (G9/G60) only
//   after its last one.
// - Non-motion elements and motions without in-plane length (e.g. a Z infeed) keep their order
//   and run at the current tool-centre point; more than MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS of
//   them in a row (Dwell, Stop, ToolChange, DynamicsChange, zero in-plane motion): alarm 10762.
//   A plane other than the selection plane while active: alarm 10757.
// - Radius or side changed while active: the two offsets are joined by a straight move.
// - Turning tools with cutting edge position 1..8: the programmed elements are first moved by
//   P - S (cutter_compensation_edge_reference.hpp), so the tip P, not the edge centre S, is the
//   point the output guides.
// Memory: the window holds the elements of the last CUTCOM_MAXNUM_CHECK_BLOCKS blocks (more
// while a CDOF fold is open, at most kFoldSearchBlocks).
#include <deque>
#include <optional>

#include "interp/cutter_compensation_corner.hpp"
#include "interp/cutter_compensation_crossing.hpp"
#include "interp/cutter_compensation_edge_reference.hpp"
#include "interp/cutter_compensation_piece.hpp"
#include "interp/path_element.hpp"
#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

class CutterCompensation : public ElementSink {
 public:
  CutterCompensation(ElementSink& downstream, const machine::MachineProfile& profile, Diagnostics& diagnostics);

  void consume(PathElement&& element) override;
  void finish() override;

 private:
  enum class Phase { Inactive, Approaching, Active };

  // An element waiting in the window: a tool-centre piece, or a passenger (non-motion element or
  // motion without in-plane length) that runs at the current tool-centre point.
  struct Item {
    PathElement element;
    std::optional<OffsetPiece> piece;
    int block = 0;          // serial number of the programmed motion block
    bool gap_bridge = false;  // the straight bridge over an inside joint: must be cut out
  };

  void select(PathElement approach);
  void complete_approach(const PathElement& first);
  void deselect(PathElement retract);
  void add_motion(const PathElement& element);
  void resolve_crossings(size_t first_new, int check_blocks);
  bool cut_out_is_defective(size_t earlier, size_t later, const PieceCrossing& crossing) const;
  bool loop_turns_as_programmed(size_t earlier, size_t later, const PieceCrossing& crossing) const;
  void cut_between(size_t earlier, size_t later, double u_earlier, double u_later);
  void release_old_blocks(int check_blocks);
  std::optional<int> pending_fold_block() const;
  int oldest_searched_block(int check_blocks) const;
  void flush_window();
  void emit_front();
  geometry::NormalRamp normal_axis_shift(const Item& item) const;
  void apply_constant_contour_feed(PathElement& element, double contour_mm, double centre_mm) const;
  void emit(PathElement element, geometry::CurvePtr curve, bool last_of_block);
  void emit_passenger(PathElement element);
  void count_dummy(const PathElement& element);
  std::optional<size_t> last_piece_index() const;
  int check_blocks() const;
  OutsideCornerRule corner_rule(const CompensationRequest& compensation) const;

  ElementSink& downstream_;
  const machine::MachineProfile& profile_;
  Diagnostics& diagnostics_;

  EdgeReferenceShift edge_reference_;
  Phase phase_ = Phase::Inactive;
  CompensationPlane plane_;
  int plane_axis_ = 2;
  PathElement approach_;
  std::deque<Item> window_;
  int block_serial_ = 0;
  int dummy_count_ = 0;
  geometry::Vec3 tool_position_ = geometry::Vec3::Zero();
  // The last compensated element released: its programmed end direction and offset (retract).
  geometry::Vec3 last_direction_ = geometry::Vec3::UnitX();
  double last_offset_ = 0.0;
};

}  // namespace drycut::interp
