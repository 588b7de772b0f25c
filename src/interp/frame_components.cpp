#include "interp/frame_components.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  if (composed_) return *composed_;
  return Frame::translation(translation + fine)
      .then(Frame::rotation_rpy(rotation_deg))
      .then(Frame::scale(scale))
      .then(Frame::mirror(mirror));
}

bool FrameComponents::set(int axis, std::string_view component, double value) {
  if (axis < 0 || axis > 2 || composed_) return false;
  if (component == "TR") translation[axis] = value;
  else if (component == "FI") fine[axis] = value;
  else if (component == "RT") rotation_deg[axis] = value;
  else if (component == "SC") scale[axis] = value;
  else if (component == "MI") mirror[static_cast<size_t>(axis)] = value != 0;
  else return false;
  return true;
}

std::string FrameComponents::assign(std::string_view d, double unit) {
  // A chain "F1(..):F2(..)" is the product F1·F2. Functions in the components' own order
  // (translations, then CROT, CSCALE, CMIRROR) merge into components; any other order is kept
  // as the product (and then cannot be written by component).
  FrameComponents merged;
  Frame product;
  int last_rank = -1;
  bool in_order = true;
  size_t start = 0;
  for (size_t i = 0; i <= d.size(); ++i) {
    if (i < d.size() && d[i] != ':') continue;
    FrameComponents one;
    int rank = 0;
    const std::string error = one.assign_function(d.substr(start, i - start), unit, rank);
    if (!error.empty()) return error;
    product = product.then(one.frame());
    // A whole frame (CFRAME) has no components: the chain is kept as the product.
    in_order = in_order && !one.composed_ && (rank > last_rank || (rank == 0 && last_rank == 0));
    if (in_order) {
      merged.translation += one.translation;
      merged.fine += one.fine;
      if (rank == 1) merged.rotation_deg = one.rotation_deg;
      if (rank == 2) merged.scale = one.scale;
      if (rank == 3) merged.mirror = one.mirror;
    }
    last_rank = std::max(last_rank, rank);
    start = i + 1;
  }
  if (!product.invertible()) return "a scale factor 0 leaves no inverse";
  *this = merged;
  if (!in_order) composed_ = product;
  return {};
}

std::string FrameComponents::assign_function(std::string_view d, double unit, int& rank) {
  const size_t open = d.find('(');
  if (open == std::string_view::npos || d.empty() || d.back() != ')') return "a frame expression drycut cannot read";
  const std::string_view name = d.substr(0, open);
  if (name == kWholeFrameFunction) {
    // drycut's own text for a frame read from the control ($P_PFRAME, $P_UIFR[n]): the linear
    // part row by row, then the translation in the program's unit. Kept as the product.
    const auto args = split_arguments(d.substr(open + 1, d.size() - open - 2));
    if (args.size() != 12) return "a whole frame needs 12 values";
    Eigen::Matrix3d linear;
    Eigen::Vector3d offset;
    for (int k = 0; k < 9; ++k) linear(k / 3, k % 3) = std::strtod(std::string(args[k]).c_str(), nullptr);
    for (int k = 0; k < 3; ++k) offset[k] = std::strtod(std::string(args[9 + k]).c_str(), nullptr) * unit;
    rank = 1;
    composed_ = Frame::affine(linear, offset);
    return {};
  }
  rank = name == "CTRANS" || name == "CFINE" ? 0 : name == "CROT" ? 1 : name == "CSCALE" ? 2 : name == "CMIRROR" ? 3 : -1;
  if (rank < 0) return std::string(name) + " is not a frame function";
  const auto args = split_arguments(d.substr(open + 1, d.size() - open - 2));
  const bool pairs = rank != 3;
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
    else if (rank == 1) rotation_deg[axis] = value;
    else if (rank == 2) scale[axis] = value;
    else mirror[static_cast<size_t>(axis)] = true;
  }
  return {};
}

std::optional<FrameComponents> FrameComponents::of_product(const Frame& frame) {
  const Eigen::Matrix3d& l = frame.linear();
  FrameComponents c;
  c.translation = frame.offset();
  Eigen::Matrix3d r = l;
  for (int i = 0; i < 3; ++i) {
    c.scale[i] = l.col(i).norm();
    if (c.scale[i] <= 0) return std::nullopt;
    r.col(i) /= c.scale[i];
  }
  if (r.determinant() < 0 || !(r.transpose() * r).isIdentity(1e-9)) return std::nullopt;
  c.rotation_deg = rpy_degrees(r);
  return c;
}

Eigen::Vector3d rpy_degrees(const Eigen::Matrix3d& r) {
  const double deg = 180.0 / 3.14159265358979323846;
  return Eigen::Vector3d(std::atan2(r(2, 1), r(2, 2)), std::asin(std::clamp(-r(2, 0), -1.0, 1.0)),
                         std::atan2(r(1, 0), r(0, 0))) * deg;
}

std::string FrameComponents::text(double unit) const {
  std::string out;
  char buf[40];
  const char* axes[] = {"X", "Y", "Z"};
  auto function = [&](const char* name, const Eigen::Vector3d& v, double divisor) {
    if (!out.empty()) out += ':';
    out += name;
    out += '(';
    for (int i = 0; i < 3; ++i) {
      std::snprintf(buf, sizeof buf, "%s%s,%.17g", i > 0 ? "," : "", axes[i], v[i] / divisor);
      out += buf;
    }
    out += ')';
  };
  function("CTRANS", translation, unit);
  if (fine != Eigen::Vector3d::Zero()) function("CFINE", fine, unit);
  if (rotation_deg != Eigen::Vector3d::Zero()) function("CROT", rotation_deg, 1.0);
  if (scale != Eigen::Vector3d::Ones()) function("CSCALE", scale, 1.0);
  if (mirror[0] || mirror[1] || mirror[2]) {
    out += ":CMIRROR(";
    bool first = true;
    for (int i = 0; i < 3; ++i)
      if (mirror[static_cast<size_t>(i)]) {
        out += first ? "" : ",";
        out += axes[i];
        first = false;
      }
    out += ')';
  }
  return out;
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
