#include "interp/frame_chain.hpp"

#include "interp/frame_components.hpp"

namespace drycut::interp {

const Frame FrameChain::kIdentity{};

int settable_frame_index(int g_code) {
  if (g_code == 500) return 0;
  if (g_code >= 54 && g_code <= 57) return g_code - 53;
  if (g_code >= 505 && g_code <= 599) return g_code - 500;
  return -1;
}

std::string settable_frame_name(int index) {
  if (index == 0) return "G500";
  if (index >= 1 && index <= 4) return "G" + std::to_string(53 + index);
  return "G" + std::to_string(500 + index);
}

bool profile_has_settable_frame(const machine::MachineProfile& profile, int index) {
  const std::string name = settable_frame_name(index);
  return profile.work_offsets.count(name) > 0 || profile.work_offset_rotations_deg.count(name) > 0;
}

Frame profile_settable_frame(const machine::MachineProfile& profile, int index) {
  // Within one frame the translation is outermost and the rotation acts inside it.
  return profile_frame_components(profile, index).frame();
}

Frame instruction_frame(FrameInstruction kind, const FrameInstructionWords& words, int plane_normal_axis) {
  auto value = [&](int i, double none) { return words.axes[static_cast<size_t>(i)].value_or(none); };
  switch (kind) {
    case FrameInstruction::Trans: return Frame::translation({value(0, 0), value(1, 0), value(2, 0)});
    case FrameInstruction::Rot:
      if (words.rpl) return Frame::rotation_about(plane_normal_axis, *words.rpl);
      return Frame::rotation_rpy({value(0, 0), value(1, 0), value(2, 0)});
    case FrameInstruction::Scale: return Frame::scale({value(0, 1), value(1, 1), value(2, 1)});
    case FrameInstruction::Mirror:
      return Frame::mirror({words.axes[0].has_value(), words.axes[1].has_value(), words.axes[2].has_value()});
  }
  return Frame{};
}

void FrameChain::set_settable(const Frame& frame) {
  settable_ = frame;
  update();
}

void FrameChain::set_programmable(const Frame& frame) {
  programmable_ = frame;
  absolute_translation_ = frame.offset();  // a frame written whole ($P_PFRAME): all absolute
  additive_translation_.setZero();
  update();
}

void FrameChain::program(const Frame& component, bool additive) {
  const bool parts_known = programmable_.is_pure_translation();
  programmable_ = additive ? programmable_.then(component) : component;
  if (additive && parts_known && component.is_pure_translation()) {
    additive_translation_ += component.offset();
  } else {
    absolute_translation_ = programmable_.offset();
    additive_translation_.setZero();
  }
  update();
}

bool FrameChain::axial_offset(int axis, double value, bool additive) {
  if (!programmable_.is_pure_translation() || axis < 0 || axis > 2) return false;
  (additive ? additive_translation_ : absolute_translation_)[axis] = value;
  programmable_ = Frame::translation(absolute_translation_ + additive_translation_);
  update();
  return true;
}

void FrameChain::update() { total_ = settable_.then(programmable_); }

}  // namespace drycut::interp
