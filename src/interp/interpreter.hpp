#pragma once
// The interpreter: gives the evaluated blocks of the loader their SINUMERIK meaning and emits the
// canonical stream of path elements (lines, arcs, spline spans, dwells, stops, tool changes).
// It knows meaning, not time: feed and dynamics modes are recorded on the elements for the planner.
//
// Coordinates: elements are in machine coordinates of the tool carrier. A programmed point
// (workpiece coordinates, Cartesian or polar AP=/RP= about the pole) goes through one frame, the
// product of the frame chain (settable frame G54..G599, programmable frame TRANS/ROT/SCALE/MIRROR;
// frame_chain.hpp), in one place: target_position for end points, build_arc for circles (built in
// the workpiece system, then mapped as a whole); the tool length along the plane normal is added
// to the tip (docs/controller-state.md "Tools and offsets"). With the default profile's zero G54,
// no programmable frame and a length-0 tool the elements equal the programmed coordinates.
#include <vector>
#include <array>
#include <map>
#include <set>
#include <string>

#include "interp/contour_corners.hpp"
#include "interp/contour_recording.hpp"
#include "interp/extra_axes.hpp"
#include "interp/frame_components.hpp"
#include "interp/modal_state.hpp"
#include "interp/path_element.hpp"
#include "interp/spline_block_quota.hpp"
#include "interp/smooth_approach.hpp"
#include "interp/spline_run.hpp"
#include "interp/tool_state.hpp"
#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"
#include "parser/block.hpp"

namespace drycut::geometry {
struct ArcResult;
}

namespace drycut::interp {

// A block's POS/POSA of geometry axes: none, alone (a positioning move; AloneAsync: a POSA
// among them, planned as POS) or beside path axes.
enum class GeometryPositioning : uint8_t { None, Alone, AloneAsync, WithPath };

struct InterpreterOptions {
  bool optional_stop_active = false;  // M1 stops only when the operator selected it
};

class Interpreter {
 public:
  Interpreter(const machine::MachineProfile& profile, ElementSink& sink, Diagnostics& diagnostics,
              InterpreterOptions options = {});

  // Executes one block; throws AlarmError when the control would raise an alarm.
  void execute(const parser::Block& block);
  // End of the block stream: completes an open spline run and tells the sink.
  void finish();

  const ModalState& state() const { return state_; }
  const Eigen::Vector3d& position() const { return position_; }
  // The tool tip in the workpiece system, in the program's units (G70/G71, DIAMON on a facing
  // axis): what an absolute end point must say to come back here ($P_EP). `actual`: of the
  // point the machine goes to (actual_position, $AA_IW).
  Eigen::Vector3d workpiece_position(bool actual = false) const;
  // Where the tool carrier actually is after the last block ($AA_IM): position() unless G41/G42
  // moved it off the programmed contour (interpreter_compensated_position.cpp).
  Eigen::Vector3d actual_position() const;
  // $P_UIFR[index] = frame (index 0 = G500, 1..4 = G54..G57, 5..99 = G505..G599). Takes effect
  // when the frame is next selected, as on the control; other indices are ignored.
  void set_settable_frame(int index, const Frame& frame);
  const Frame& settable_frame(int index) const { return settable_frames_.at(static_cast<size_t>(index)); }
  const FrameComponents& settable_components(int index) const { return settable_components_.at(static_cast<size_t>(index)); }
  // $P_PFRAME = frame: replaces the programmable frame at once.
  void set_programmable_frame(const Frame& frame);
  // The frame a block without G53 maps with (settable * programmable): e.g. the machine direction
  // of the plane normal for tool length is frame().vector_to_outer(unit normal).
  const Frame& frame() const { return state_.frames.total(false); }
  // Tool, edge and the run's copy of the tool table ($TC_DP writes go through
  // tools().set_edge_parameter).
  const ToolState& tools() const { return tools_; }
  ToolState& tools() { return tools_; }
  bool ended() const { return ended_; }
  int master_spindle() const { return master_spindle_; }  // MD20090, SETMS(n)
  // $P_S[n] / $AA_S[n] of spindle n (0: the master): the last programmed speed, and the speed it
  // turns at in a dry run (0 when stopped, negative under M4; interpreter_spindle.cpp).
  double programmed_spindle_speed(int spindle) const;
  // $P_SDIR[n] / $AC_SDIR[n]: 3 (M3), 4 (M4) or 5 (stopped, also after SPOS); 0 = master.
  int spindle_direction(int spindle) const;
  double actual_spindle_speed(int spindle) const;
  // $AA_S: the speed on the spindle's run-up ramp (MD35200) at the interpreter's clock; the set
  // speed once the ramp is through (interpreter_spindle_run_up.cpp).
  double spindle_speed_on_ramp(int spindle) const;
  // A lower bound of the time so far (path length / feed, dwells, clock polls).
  double nominal_time_s() const { return nominal_time_s_ + clock_wait_s_; }
  // The part of it spent moving at feed with a tool active (tool action time, $AC_CUTTING_TIME).
  double cutting_time_s() const { return cutting_time_s_; }
  // A read of the run clock ($AC_OPERATING_TIME, $AC_TIMER, $A_SECOND ...) on program line `line`
  // (a running count): the time it sees. The line waits for the main run (a main-run variable
  // stops the block preparation); when nothing that takes time ran since the last line that read
  // the clock (no motion, no dwell: a STOPRE or an M function does not count), the program is
  // polling it, and each such line takes one interpolation cycle: a wait loop ends when its time
  // has passed. The wait becomes a dwell before the
  // next block's elements (docs/controller-state.md, "Clock, run-time counters").
  double poll_clock(uint64_t line);
  // Channel axes beyond X, Y, Z ($AA_IM[A] reads their positions).
  const ExtraAxes& extra_axes() const { return extra_axes_; }
  // Where extra axis i is now: on its way while a POSA runs (its actual position, $AA_IM).
  double extra_axis_actual_position(size_t i) const;
  // The contour of the last DRYCUT_CONTOUR_BEGIN ... END ($DRYCUT_CONTOUR, contour_recording.hpp).
  const ContourRecorder& recorded_contour() const { return recorder_; }
  // mm per unit of the tool data a program reads ($P_TOOLR, $P_TOOLL): the programmed unit under
  // G700/G710, the base system (MD10240) under G70/G71, as F (Fundamentals, G70/G700 table).
  double tool_data_unit() const { return feed_unit(); }

 private:
  struct BlockContext;
  // An end point in the workpiece system (as programmed) and in the machine system.
  // A programmed end point: in the workpiece system of the tool tip, and the machine position of
  // the tool carrier (the tip + the tool length applied after the block).
  struct Target {
    Eigen::Vector3d workpiece;
    Eigen::Vector3d machine;
    Eigen::Vector3d length_before = Eigen::Vector3d::Zero();  // tool length applied at the start
    Eigen::Vector3d length_after = Eigen::Vector3d::Zero();
  };

  void apply_system_writes(const parser::Block& block);  // system_variable_writes.cpp
  // $P_UIFR[n] = frame / $P_UIFR[n, axis, component] = value, $P_PFRAME = frame; false: not one.
  bool write_programmable_component(const parser::SystemWrite& w, size_t first);  // $P_PFRAME[ax, comp]=
  bool write_frame_variable(const parser::Block& block, const parser::SystemWrite& write);
  void apply_modal_save(parser::ModalSave what);         // PROC ... SAVE
  void apply_g_words(BlockContext& ctx);
  void apply_commands(BlockContext& ctx);
  void apply_addresses(BlockContext& ctx);
  // apply_addresses' words with rules of their own (interpreter_addresses.cpp).
  void note_tool_change_m_words(BlockContext& ctx);  // the tool change M function (MD22550 = 1)
  void apply_feed_address(BlockContext& ctx, const parser::AddressWord& a);  // F
  void apply_tool_address(BlockContext& ctx, const parser::AddressWord& a);  // T, T<n>=
  void change_tool_regardless_of_status(BlockContext& ctx, const parser::CommandWord& c);  // TCA
  void apply_edge_address(BlockContext& ctx, const parser::AddressWord& a);  // D
  bool apply_smoothing_address(BlockContext& ctx, const parser::AddressWord& a);
  // RND=, RNDM=, CHF=, CHR=, FRC=, FRCM= (interpreter_corners.cpp, contour_corners.hpp).
  bool apply_corner_address(BlockContext& ctx, const parser::AddressWord& a);
  // The chamfer or rounding the block asks for at the end of its element e (a G0/G1 line);
  // warns where the block is of another kind.
  // The chamfer/rounding words of a block (RND/RNDM/CHF/CHR with FRC), as request_corner reads them.
  struct CornerWords {
    ContourCornerKind kind = ContourCornerKind::None;
    double size_mm = 0.0, frc = 0.0;
    uint32_t column = 0;
  };
  static CornerWords corner_words(const BlockContext& ctx);
  void request_corner(BlockContext& ctx, PathElement& e) { request_corner(ctx, e, corner_words(ctx)); }
  void request_corner(BlockContext& ctx, PathElement& e, const CornerWords& words);
  void warn_unused_corner(BlockContext& ctx);  // RND/CHF/CHR in a block without a line
  void apply_m_words(BlockContext& ctx);
  // Extra axes and positioning axes (interpreter_axes.cpp, docs/axes.md).
  bool note_extra_axis_word(BlockContext& ctx, const parser::AddressWord& word);
  bool note_unknown_axis_word(BlockContext& ctx, const parser::AddressWord& word);
  bool apply_axis_command(BlockContext& ctx, const parser::CommandWord& command);
  void apply_axis_words(BlockContext& ctx);
  // DIAMON ... DIAMCYCOF, DIAMONA[ax] ... DIAMCHANA[ax], DIAMCHAN, SCC[ax] (interpreter_turning.cpp).
  bool apply_turning_command(BlockContext& ctx, const parser::CommandWord& command);
  void add_positioning(BlockContext& ctx, const parser::AxisWord& word);
  // POS[X]=.., POSA[Z]=.. of geometry axes: the block with them written as axis words X=.. Z=..
  // (nullopt when the block has none), so that frames, units and tool length apply as to a path
  // move; `mode` tells whether the block has path axes of its own besides.
  std::optional<parser::Block> geometry_positioning_block(const parser::Block& block, GeometryPositioning& mode) const;
  void position_geometry_axes(BlockContext& ctx, std::vector<ExtraAxisMove> extra);
  void move_to_fixed_point(BlockContext& ctx);  // G74 / G75 (interpreter_axes.cpp)
  void set_feed_reference_radius(BlockContext& ctx, const parser::AxisWord& w);  // FGREF[ax]=
  void execute_block(const parser::Block& block, GeometryPositioning geometry_positioning);
  void set_axis_limit(BlockContext& ctx, const parser::AxisWord& word);  // ACC/VELOLIM/JERKLIM[ax]=
  bool names_channel_axis(const std::string& name) const;  // the axis of FA[..], ACC[..] is valid
  void add_spindle_positioning(BlockContext& ctx, const parser::AxisWord& word);
  std::vector<ExtraAxisMove> take_extra_axis_moves(BlockContext& ctx);
  // Moves extra axis i to a programmed value (alarms 168xx, 10720); returns the travel.
  double move_extra_axis(const BlockContext& ctx, size_t i, double value, parser::ValueMode mode, uint32_t column);
  void attach_extra_axes(BlockContext& ctx, PathElement& element, std::vector<ExtraAxisMove> moves);
  void emit_axis_waits(BlockContext& ctx);
  // A POSA/SPOSA move starts (the clock knows when it arrives); a block waits for `axis`.
  void mark_running(const PositioningMove& m, double from, double travel);
  void wait_for(BlockContext& ctx, const std::string& axis);
  void emit_positioning(BlockContext& ctx);
  void execute_motion(BlockContext& ctx, MotionMode modal_motion);
  void emit_dynamics_change(BlockContext& ctx);  // transition, acceleration, limits changed
  // Frame instruction, G58/G59, G25/G26, pole or G74/G75: the block's axis words are data of
  // the instruction, not a path end point. True when the block was one of them (done).
  bool execute_axis_instruction(BlockContext& ctx);
  // A block with an end point or a full circle (interpreter_curves.cpp): spline point or element.
  void move_to_target(BlockContext& ctx, std::vector<ExtraAxisMove> extra);
  void emit_lead_change_thread(BlockContext& ctx, PathElement&& e);  // G34/G35 in pieces
  // The element of a G0/G1 or circle block from the current position (nothing emitted yet).
  PathElement build_line(BlockContext& ctx, const Eigen::Vector3d& target);
  PathElement build_arc(BlockContext& ctx, const Target& target);
  // build_arc's parts (interpreter_curves.cpp): the circle of CIP, CT and G2/G3 in its system.
  struct ArcSpace;
  geometry::ArcResult cip_arc(const BlockContext& ctx, const ArcSpace& space) const;
  geometry::ArcResult ct_arc(const BlockContext& ctx, const ArcSpace& space) const;
  geometry::ArcResult g2_g3_arc(const BlockContext& ctx, const ArcSpace& space) const;
  int arc_turns(const BlockContext& ctx) const;
  bool arc_centre(const BlockContext& ctx, const ArcSpace& space, Eigen::Vector3d& center) const;
  PathElement build_polynomial(BlockContext& ctx, const Eigen::Vector3d& target);  // POLY (interpreter_polynomial.cpp)
  void add_spline_point(BlockContext& ctx, const Eigen::Vector3d& target);
  void end_spline_run(const Eigen::Vector3d* next_direction);
  void emit(PathElement&& element);  // by rvalue: one PathElement move less per element
  void emit_clock_wait(const BlockContext& ctx);
  // G41/G42 selected, no block has moved in the working plane since: such an element is not
  // compensated yet (the selection waits for the first block that moves in the plane).
  void defer_compensation_selection(PathElement& element);
  // 10753/10754: G41/G42 selected or G40 deselected in a circle, spline or polynomial block.
  void refuse_compensation_change_on_curve(const BlockContext& ctx, bool moves) const;
  void emit_preprocessing_stop(BlockContext& ctx, const char* label);  // STOPRE, explicit or implicit
  void emit_block_end(BlockContext& ctx);  // tool change, STOPRE, M0/M1/M2/M30 after the motion
  void add_nominal_time(const PathElement& element);
  void add_element_time(const PathElement& e);
  // Marks a G1 element for the compressor stage (docs/compressor.md) and warns once about
  // compressor settings drycut does not model.
  void mark_for_compressor(const BlockContext& ctx, PathElement& element);
  void emit_control(BlockContext& ctx, ElementKind kind, std::string label);
  PathElement element_template(const BlockContext& ctx, ElementKind kind);
  // A line from a to b, built in spare_curve_ when nothing else holds it (no allocation).
  geometry::CurvePtr line_curve(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  // The path feed of a block of this length and chord (src/interp/feed_rate); alarms raised.
  double feed_mm_s(BlockContext& ctx, double length_mm, const Eigen::Vector3d& chord);
  // Tooth feed G95 FZ (tooth_feed.cpp): the FZ word, an F in a block after FZ, and the feed
  // state the block runs with (state_, or `scratch` with F = FZ · teeth under G95).
  void apply_tooth_feed(BlockContext& ctx, const parser::AddressWord& a);
  void apply_f_after_tooth_feed(BlockContext& ctx, const parser::AddressWord& f);
  const ModalState& feed_state(const BlockContext& ctx, ModalState& scratch);
  // The spindle speed the feed and G4 S use (G96 resolved; 0 when it stands).
  // SVC=: the spindle speed from a cutting speed and the active tool radius (interpreter_spindle.cpp).
  void apply_cutting_speed(BlockContext& ctx, const parser::AddressWord& svc);
  void speed_from_cutting_speed(const BlockContext& ctx, uint32_t column);  // S from SVC and the edge radius
  // `chord`: the block's move (end - start), over which G96 follows the diameter.
  double spindle_speed(const BlockContext& ctx, const Eigen::Vector3d* chord = nullptr);
  // G96 under G95 on a line: the spindle-speed law the last stage cuts it into pieces by.
  void attach_cutting_speed_law(BlockContext& ctx, PathElement& e);
  double geometry_unit() const;  // mm per unit of positions (G70/G71/G700/G710)
  double cutting_speed_mm_min(double speed) const;  // G96 S / SVC (m/min or ft/min) in mm/min
  double feed_unit() const;      // mm per length unit of F (G700/G710, else the base unit MD10240)
  // A thread or tapping block: takes its lead I/J/K and, for a thread (G33..G35) that does not
  // continue a chain of the same kind, emits the profile's spindle_ramp_time as a dwell before
  // it. Rigid tapping instead limits the lead axis's acceleration (limit_tapping_acceleration).
  void start_thread_block(BlockContext& ctx);
  void limit_tapping_acceleration(PathElement& e) const;
  // Raises the first alarm among the tool notices, reports the warnings.
  void report_tool_notices(const BlockContext& ctx, const std::vector<ToolNotice>& notices, uint32_t column);
  void program_tool(BlockContext& ctx, const std::string& id, uint32_t column);
  void change_tool(BlockContext& ctx);
  // Tool length compensation: the lengths of the active edge on the axes (by type and plane).
  Eigen::Vector3d tool_length_vector() const;
  // A turning tool's P - S under G41/G42 for the request's plane (CompensationRequest).
  Eigen::Vector3d edge_reference_shift(const CompensationRequest& request) const;
  // Remembers where the compensation puts the end of a compensated motion (actual_position).
  void note_compensated_end(const PathElement& element);
  void orient_tool(const BlockContext& ctx, const std::string& command, uint32_t column);
  // Frames and polar coordinates.
  const Frame& block_frame(const BlockContext& ctx) const;
  bool is_incremental(const parser::AddressWord& a) const;
  PolarWords polar_words(const BlockContext& ctx) const;
  void select_settable_frame(const BlockContext& ctx, int code, uint32_t column);
  void apply_frame_instruction(const BlockContext& ctx);
  void warn_frame_of_extra_axis(const BlockContext& ctx, const parser::AddressWord& a);  // TRANS C30, G58 A10
  void apply_axial_offset(const BlockContext& ctx);  // G58/G59
  void define_pole(const BlockContext& ctx);
  bool frame_mirrors_plane(const Frame& frame) const;
  void tilt_compensation_plane(const BlockContext& ctx, CompensationRequest& request) const;
  Target target_position(BlockContext& ctx);
  void apply_contour_angle(const BlockContext& ctx, const Frame& frame, Target& t);  // ANG= with one end coordinate
  // Smooth approach and retraction G147..G348 (interpreter_smooth_approach.cpp, smooth_approach.hpp):
  // DISR/DISCL/FAD/DISRP words; the SAR block's movements (an approach waits for the next
  // motion's start direction: held in emit until it comes).
  bool apply_smooth_approach_address(BlockContext& ctx, const parser::AddressWord& a);
  void execute_smooth_approach(BlockContext& ctx, MotionMode modal_motion);
  bool hold_for_smooth_approach(PathElement& element);
  void release_smooth_approach(const Eigen::Vector3d* next_tangent);
  void emit_smooth_approach_pieces(const PathElement& block_element, const std::vector<SarPiece>& pieces,
                                   const SarSpeeds& speeds, bool check_limits);
  // 10720 for a SAR sub-movement beyond the software limits (its end, or a circle's extremes),
  // reported at the SAR block.
  void check_smooth_approach_limits(const PathElement& block_element, const geometry::Curve& curve) const;
  // Two straight lines by angles: holds the first ANG=, then runs the first line to the corner.
  bool hold_contour_angle(BlockContext& ctx, bool has_axis);
  void run_to_contour_corner(BlockContext& ctx);
  void check_limits(const BlockContext& ctx, const Eigen::Vector3d& target);
  void check_arc_limits(const BlockContext& ctx, const geometry::Curve& curve);
  // The software limit switch a machine point violates (10720's detail), if any.
  std::optional<std::string> limit_violation(const Eigen::Vector3d& p) const;
  // TRANSMIT/TRACYL/TRAANG/TRAORI on, TRAFOOF off (transformation_limits.cpp); false when the
  // word is none of them.
  bool apply_transformation_command(const parser::CommandWord& c);
  // False (warned once) while a transformation drycut does not model is active.
  bool limits_checked(const BlockContext& ctx);
  [[noreturn]] void raise(const BlockContext& ctx, int number, const std::string& detail,
                          uint32_t column = 0) const;
  // A warning once per text: 990002 (not modelled), or the given catalogue number.
  // A thread block whose lead at the spindle speed asks an axis for more than its MAX_AX_VELO.
  void warn_thread_beyond_axis_velocity(BlockContext& ctx, double feed_mm_s, double length_mm,
                                        const Eigen::Vector3d& chord);
  void warn_once(const BlockContext& ctx, const std::string& what, uint32_t column);
  void warn_once(const BlockContext& ctx, int number, const std::string& what, uint32_t column);
  // "S2" -> 2 (the spindle of a numbered speed address S<n>=), 0 for any other name.
  static int numbered_spindle(std::string_view name);
  void apply_spindle_speed(BlockContext& ctx, const parser::AddressWord& a);  // S, S<n>=
  // G25 S / G26 S: the master spindle's lower / upper speed limit (interpreter_spindle.cpp).
  void set_speed_limit(const BlockContext& ctx, const parser::AddressWord& a);
  // A spindle speed limited by G25/G26 (warning 990013 where a limit acts).
  double limit_to_g25_g26(const BlockContext& ctx, double rpm, bool constant_cutting_speed);  // warns
  double within_g25_g26(double rpm) const;  // the same limits, silently
  double g96_speed_ceiling() const;         // MD35100, LIMS, G26: the highest G96 speed
  void apply_speed_limit_lims(BlockContext& ctx, const parser::AddressWord& a);  // LIMS=, LIMS[n]=
  double lims_ceiling() const;              // LIMS where it acts (G96, G961, G962, G97), else 0
  double within_lims(const BlockContext& ctx, double rpm);  // warns
  static bool ends_constant_cutting_speed(const parser::Block& block);  // G97.., G93/G94/G95
  void note_group15_change(BlockContext& ctx, bool was_g96, FeedMode feed_before, double frozen_rpm);  // 990019
  void combine_feed_type_and_speed_mode(BlockContext& ctx);  // `G96 G95`, `G94 G97` in one block
  PathElement dwell_element(BlockContext& ctx);             // G4 F / S / S<n>=
  void warn_working_area(const BlockContext& ctx);          // G25/G26 with axis words
  // G4 S<rev> / G4 S<n>=<rev>: the dwell in seconds.
  double dwell_in_revolutions(const BlockContext& ctx, const parser::AddressWord& s);

  // DRYCUT_CONTOUR_BEGIN / END (interpreter_contour_recording.cpp).
  void record_contour(const BlockContext& ctx, bool begin, uint32_t column);

  const machine::MachineProfile& profile_;
  ElementSink& downstream_;  // the stream after the interpreter (compensation, planner)
  ContourCorners corners_;  // every element goes through it (sink_ is this filter)
  ElementSink& sink_;
  // What the sink left in the last moved-from element (the pipeline hands back a retired
  // element's block reference and curve, pipelined_sink.hpp): the next element's block text and
  // line are written into them instead of new heap blocks (element_template, line_curve).
  BlockRef spare_source_;
  geometry::CurvePtr spare_curve_;
  // feed_mm_s's copy of the state with F = FB or FZ · teeth (feed_state): a member, so that the
  // blocks that need none (nearly all) construct no ModalState.
  ModalState feed_scratch_;
  // Contour recording: where corners_ sends the elements between BEGIN and END, and what END
  // restores (the tool has not moved).
  ContourRecorder recorder_;
  // What the blocks of a recorded contour may change and END puts back (the tool has not moved,
  // no time has passed, no tool was changed, nothing is left open for the next real block).
  struct RecordingStart {
    Eigen::Vector3d position, length_applied, last_tangent;
    bool has_last_tangent = false;
    double nominal_time_s = 0.0, cutting_time_s = 0.0;
    DynamicsMode last_dynamics;
    std::optional<double> held_angle_deg;
    CornerWords held_corner;
    std::optional<MotionMode> thread_chain;
    bool block_between_compressible = true;
    bool compensation_selection_pending = false;
    ToolState tools;
    ExtraAxes extra_axes;
  };
  std::optional<RecordingStart> recording_start_;
  void stop_recording();  // back to the real stream, the state as at BEGIN
  Diagnostics& diagnostics_;
  InterpreterOptions options_;
  ModalState state_;
  std::vector<ModalState> saved_states_;  // PROC ... SAVE, innermost last
  ToolState tools_;
  Eigen::Vector3d position_;  // tool carrier reference point (tool tip + applied length)
  // The tool length already contained in position_, per axis: it changes for an axis with the
  // first motion that programs that axis after a new length (W1: TLC with the first traversing
  // motion of the axis).
  Eigen::Vector3d length_applied_ = Eigen::Vector3d::Zero();
  // Under G96 the position whose diameter the spindle speed was last set for: the end of the last
  // cut (G0 leaves the speed as it is) or where the spindle command last changed.
  Eigen::Vector3d g96_speed_position_;
  bool has_last_tangent_ = false;
  Eigen::Vector3d last_tangent_ = Eigen::Vector3d::UnitX();
  // The last motion was compensated (G41/G42): the carrier is this far off position_ at its end.
  bool last_motion_compensated_ = false;
  Eigen::Vector3d compensated_offset_ = Eigen::Vector3d::Zero();
  SplineRun spline_;
  BlockRef last_spline_block_;  // where an alarm of the run's last spans belongs
  SplineBlockQuota quota_;
  DynamicsMode last_dynamics_;
  bool ended_ = false;
  std::optional<double> held_angle_deg_;  // ANG= of a block without end point: the first of two lines
  struct PendingApproach {
    PathElement element;  // the SAR block's straight move P0 -> P4 (its template for the pieces)
    SarRequest request;
    Eigen::Vector3d normal;
    double radius = 0.0;
    int compensation_side = 0;
    SarSpeeds speeds;
    // The SAR block named no axis of the plane: P4 is the next motion block's end point, its
    // move the SAR contour's (Fundamentals, "Programming of end point P4").
    bool end_from_next = false;
    bool check_limits = true;  // the software limits are checked at the SAR block (limits_checked)
  };
  std::optional<PendingApproach> sar_pending_;  // a SAR approach waiting for the next motion
  std::vector<PathElement> sar_held_;             // elements emitted meanwhile (after it in order)
  bool sar_releasing_ = false;
  // RND/CHF/CHR (and FRC) written in that block: the corner where the two lines meet.
  CornerWords held_corner_;
  double nominal_time_s_ = 0.0;  // path length / feed and dwells so far (timers, add_nominal_time)
  // A lower bound of the planned time so far (rapid moves at their top speed, no ramps): whether
  // a spindle run-up may still be going on (interpreter_spindle_run_up.cpp).
  double least_time_s_ = 0.0;
  double cutting_time_s_ = 0.0;  // the part of it at feed with a tool active
  double clock_wait_s_ = 0.0;    // clock polls not yet emitted as a dwell (poll_clock)
  uint64_t work_additions_ = 0;  // elements that added motion, dwell or tool change time (not clock waits)
  uint64_t work_at_poll_ = ~uint64_t{0};  // work_additions_ at the last line that read the clock
  uint64_t line_at_poll_ = UINT64_MAX;   // that line
  bool block_between_compressible_ = true;  // a block not simple since the last compressible element
  std::optional<MotionMode> thread_chain_;  // the thread mode of the last motion block, if any
  std::set<std::string> warned_;
  bool compensation_selection_pending_ = false;  // G41/G42 selected, not yet moved in the plane
  // The motion block being executed names an axis of the plane (or AP/RP): a selection block
  // that does (G41 G1 X.. Y.. where the tool already is) selects, by W1's wording, even unmoved.
  bool block_names_plane_axis_ = false;
  std::string unmodelled_transformation_;  // TRANSMIT ... until TRAFOOF; empty: none
  // The master spindle's last M5: when (the nominal clock) and from which speed it braked.
  struct SpindleBraking {
    double since_s = 0.0;
    double from_rpm = 0.0;
  };
  SpindleBraking master_braking_;
  // Spindle run-up (MD35500, interpreter_spindle_run_up.cpp): after a programmed change of a
  // spindle's speed it ramps at MD35200 from the speed it had to the new set speed (signed: M4
  // negative); the master's first path block with feed waits until it is in the set range
  // (MD35150).
  struct SpindleCommand {
    SpindleState state = SpindleState::Stopped;
    double value = 0.0;  // S, or the cutting speed under G96 (mm/min)
    bool constant_cutting_speed = false;
    int master = 1;
    bool operator==(const SpindleCommand&) const = default;
  };
  struct SpindleRunUp {
    double since_s = 0.0;  // the nominal clock at the change
    double since_least_s = 0.0;  // least_time_s_ then
    double from_rpm = 0.0;
    double to_rpm = 0.0;
    bool pending = false;  // no path block with feed has started since
    // Under G96 once its first cut has started: the spindle follows the set speed along X.
    bool follows_set_speed = false;
    // The planner times the wait from the element that began this ramp (the ids of
    // PathElement::run_up_start / run_up_wait); 0: a ramp SETMS brought back, estimated here.
    uint32_t id = 0;
  };
  void settle_spindles_at_stop();  // M0/M1: every ramp done, no braking left
  SpindleCommand spindle_command_;
  SpindleRunUp run_up_;
  uint32_t run_up_count_ = 0;
  uint32_t run_up_mark_ = 0;  // a ramp began: the next element emitted carries its id
  // M6 stopped the turning spindle and no S, M3/M4/M5 or SPOS came since: the first cut restarts
  // it at the old speed, which the machine's tool-change cycle may not do (warned there).
  bool spindle_left_to_changer_ = false;
  void note_spindle_programmed(const parser::Block& block);
  void note_spindle_change();
  SpindleRunUp standing_run_up() const;  // a spindle standing since now
  SpindleRunUp next_run_up(const SpindleCommand& old, const SpindleRunUp& ramp, double set_rpm) const;
  void become_master_run_up(const SpindleCommand& command, const SpindleRunUp& ramp);
  void note_tool_change_stops_spindle();
  void wait_for_spindle_speed(const PathElement& next);
  struct ChordLimits {
    double v = 0, a = 0, j = 0;  // path velocity, acceleration, jerk (0: BRISK) along a straight move
  };
  ChordLimits chord_limits(const PathElement& e, double length) const;
  bool clock_at_rest_ = true;  // the clock's last motion ended at rest (G60/G9), or none yet
  double g96_set_speed(const Eigen::Vector3d& machine_position, double cutting_speed_mm_min) const;
  Eigen::Vector3d transformation_start_ = Eigen::Vector3d::Zero();  // the position when it began
  ExtraAxes extra_axes_;
  double spindle_angle_ = 0.0;  // master spindle position after SPOS (degrees)
  std::array<double, 3> geometry_positioning_feed_{};  // FA[X/Y/Z] (mm/s), else MD32060 of the axis
  // G25 S / G26 S (SD43210 SPIND_MIN_VELO_G25, SD43220 SPIND_MAX_VELO_G26), 0: no limit.
  double spindle_min_rpm_ = 0.0;
  double spindle_max_rpm_ = 0.0;
  // The master spindle (MD20090, SETMS(n)): S, M3/M4/M5, G95, G96 and G4 S refer to it.
  int master_spindle_ = 1;
  // Spindles other than the master: their programmed speed and direction are kept (G4 S<n>=,
  // and SETMS(n) makes one the master with them).
  struct OtherSpindle {
    double rpm = 0.0;
    SpindleState state = SpindleState::Clockwise;  // Stopped after M<n>=5 (else assumed turning)
    SpindleCommand command;  // what its run-up last ramped to
    SpindleRunUp run_up;
    double angle_deg = 0.0;  // where its last SPOS left it (0 at the start), as spindle_angle_
    bool turning() const { return state != SpindleState::Stopped; }
  };
  std::map<int, OtherSpindle> other_spindles_;
  void set_master_spindle(const BlockContext& ctx, const parser::CommandWord& c);
  // A swivel head's rotation of the tool (TCOABS/TCOFR with swivel_kinematics "head").
  Eigen::Matrix3d tool_orientation_ = Eigen::Matrix3d::Identity();
  // SD42940 / SD42950 (profile, or written by the program): the plane whose length assignment
  // holds (0: the selected one) and the tool type the lengths are assigned by (0: the tool's own).
  int tool_length_const_ = profile_.tool_length_const;
  int tool_length_type_ = profile_.tool_length_type;
  // A swivel (TCOABS/TCOFR in a rotated frame) on a machine whose part turns ("table") or whose
  // kinematics the profile lacks: the linear axes' positions depend on the table's pivot.
  bool part_swivelled_ = false;
  // On the heap (~46 KB for the 100 frames): an Interpreter on the stack stays small.
  std::vector<Frame> settable_frames_ = std::vector<Frame>(kSettableFrames);  // $P_UIFR
  std::array<bool, kSettableFrames> settable_defined_{};
  std::vector<FrameComponents> settable_components_ = std::vector<FrameComponents>(kSettableFrames);  // $P_UIFR[n, ax, TR]
  FrameComponents active_settable_components_;  // $P_IFRAME: the selected one's, or as written
};

}  // namespace drycut::interp
