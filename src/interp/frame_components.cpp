#include "interp/frame_components.hpp"

#include <cstdlib>
#include <vector>

#include "interp/frame_chain.hpp"

namespace drycut::interp {
namespace {

int axis_number(std::string_view a) { return a == "X" ? 0 : a == "Y" ? 1 : a == "Z" ? 2 : -1; }

std::vector<std::string_view> split_arguments(std::string_view s) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == ',') {
      out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

}  // namespace

Frame FrameComponents::frame() const {
  return Frame::translation(translation + fine)
      .then(Frame::rotation_rpy(rotation_deg))
      .then(Frame::scale(scale))
      .then(Frame::mirror(mirror));
}

bool FrameComponents::set(int axis, std::string_view component, double value) {
  if (axis < 0 || axis > 2) return false;
  if (component == "TR") translation[axis] = value;
  else if (component == "FI") fine[axis] = value;
  else if (component == "RT") rotation_deg[axis] = value;
  else if (component == "SC") scale[axis] = value;
  else if (component == "MI") mirror[static_cast<size_t>(axis)] = value != 0;
  else return false;
  return true;
}

std::string FrameComponents::assign(std::string_view d, double unit) {
  const size_t open = d.find('(');
  if (open == std::string_view::npos || d.back() != ')') return "a frame expression drycut cannot read";
  const std::string_view name = d.substr(0, open);
  const auto args = split_arguments(d.substr(open + 1, d.size() - open - 2));
  *this = FrameComponents{};
  const bool pairs = name != "CMIRROR";
  for (size_t i = 0; i < args.size() && !args[i].empty(); i += pairs ? 2 : 1) {
    const int axis = axis_number(args[i]);
    if (axis < 0) return std::string(name) + ": " + std::string(args[i]) + " is not a geometry axis X, Y or Z";
    double value = 0;
    if (pairs) {
      if (i + 1 >= args.size()) return std::string(name) + ": axis " + std::string(args[i]) + " needs a value";
      value = std::strtod(std::string(args[i + 1]).c_str(), nullptr);
    }
    if (name == "CTRANS") translation[axis] = value * unit;
    else if (name == "CFINE") fine[axis] = value * unit;
    else if (name == "CROT") rotation_deg[axis] = value;
    else if (name == "CSCALE") scale[axis] = value;
    else if (name == "CMIRROR") mirror[static_cast<size_t>(axis)] = true;
    else return std::string(name) + " is not a frame function";
  }
  if (!frame().invertible()) return std::string(name) + ": a scale factor 0 leaves no inverse";
  return {};
}

FrameComponents profile_frame_components(const machine::MachineProfile& profile, int index) {
  FrameComponents c;
  const std::string name = settable_frame_name(index);
  if (auto it = profile.work_offsets.find(name); it != profile.work_offsets.end()) c.translation = it->second;
  if (auto it = profile.work_offset_rotations_deg.find(name); it != profile.work_offset_rotations_deg.end())
    c.rotation_deg = it->second;
  return c;
}

}  // namespace drycut::interp
