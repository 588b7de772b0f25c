#pragma once
// The chain of frames between the workpiece coordinates a program writes and the machine
// coordinates the elements carry (docs/controller-state.md, "Frames"):
//
//   machine = basic ( settable ( programmable ( workpiece ) ) )
//
// basic: the basic frame (none in drycut's profiles: identity); settable: the frame selected by
// G500/G54..G57/G505..G599 from the table $P_UIFR[0..99]; programmable: TRANS/ROT/SCALE/MIRROR
// and their additive forms, innermost, so it acts first on a programmed point. G53 suppresses
// settable and programmable frame for one block, G153 also the basic frame, SUPA also the
// offsets drycut does not model (DRF, external, PRESET), so all three are the same here.
//
// The chain's product is cached: every element of the block is mapped with one matrix.
#include <array>
#include <optional>
#include <string>

#include "interp/frame.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

// $P_UIFR[n]: n = 0 is G500, 1..4 are G54..G57, 5..99 are G505..G599.
constexpr int kSettableFrames = 100;
// The table index of a settable-frame G code, or -1 if the code selects none.
int settable_frame_index(int g_code);
// "G500", "G54", "G505" ... for a table index.
std::string settable_frame_name(int index);
// The settable frame of table index `index` as the profile gives it (work_offsets_mm and
// work_offset_rotations_deg; absent entries are the zero frame).
Frame profile_settable_frame(const machine::MachineProfile& profile, int index);
bool profile_has_settable_frame(const machine::MachineProfile& profile, int index);

// The programmable frame instructions and the words written with them.
enum class FrameInstruction { Trans, Rot, Scale, Mirror };
struct FrameInstructionWords {
  std::array<std::optional<double>, 3> axes;  // X Y Z values (TRANS: mm; ROT: degrees; SCALE: factor)
  std::optional<double> rpl;                  // ROT RPL=: degrees about the plane normal
};
// The frame one instruction describes. Axes not written: offset 0, angle 0, factor 1, no mirror.
// ROT RPL= turns about the normal of the active plane (`plane_normal_axis` 0 = X, 1 = Y, 2 = Z).
Frame instruction_frame(FrameInstruction kind, const FrameInstructionWords& words, int plane_normal_axis);

class FrameChain {
 public:
  const Frame& settable() const { return settable_; }
  const Frame& programmable() const { return programmable_; }
  // basic * settable * programmable; with `suppress` (G53/G153/SUPA in the block) identity.
  const Frame& total(bool suppress) const { return suppress ? kIdentity : total_; }

  void set_settable(const Frame& frame);
  void set_programmable(const Frame& frame);
  // TRANS/ROT/SCALE/MIRROR replace the whole programmable frame by `component` (an instruction
  // without values therefore clears it); ATRANS/AROT/ASCALE/AMIRROR chain it inside.
  void program(const Frame& component, bool additive);
  // G58 (additive false) / G59 (true) axis=value: replace, for that axis only, the absolute
  // (TRANS) or the additive (ATRANS) part of the programmable frame's translation; the other
  // part stays (PGA Fundamentals, "Axial programmable zero offset (G58, G59)"). drycut keeps the
  // two parts apart while the programmable frame is a pure translation; false (nothing changed)
  // when it also rotates, scales or mirrors.
  bool axial_offset(int axis, double value, bool additive);

 private:
  void update();
  static const Frame kIdentity;
  Frame settable_;
  Frame programmable_;
  Frame total_;
  // The programmable translation split as TRANS/G58 and ATRANS/G59 wrote it (programmable_ is
  // translation(absolute_ + additive_) whenever it is a pure translation).
  Eigen::Vector3d absolute_translation_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d additive_translation_ = Eigen::Vector3d::Zero();
};

}  // namespace drycut::interp
