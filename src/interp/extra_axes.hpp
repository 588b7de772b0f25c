#pragma once
// Channel axes beyond X, Y, Z (docs/axes.md): their machine positions, how a programmed value
// becomes a travel, the feed group (FGROUP), positioning-axis feeds (FA) and the POSA moves the
// program has not waited for yet.
//
// RULES (PGA Fundamentals "Absolute dimensions for rotary axes (DC, ACP, ACN)" and "Feedrate
// ... FGROUP"; Function Manual Axes and Spindles, R2 "Rotary axes"):
// - A linear extra axis moves like X: G90/G91, AC()/IC(), in the geometry unit (G70/G71...).
// - A rotary axis moves in degrees in every unit system. Without modulo (MD30310 = 0) it is
//   programmed like a linear axis.
// - A modulo rotary axis (range R = MD30330) keeps its position in [0, R):
//     IC / G91: travel = the value (more than a turn is allowed);
//     AC / G90: the position value reduced into [0, R); the axis travels from where it stands
//               to it like a linear axis inside the range (target > position: positive way);
//               with MD30455 bit 2 it goes the shortest way, as DC;
//     DC:  the shortest way (at most R/2; exactly R/2: positive);
//     ACP: the positive way, ACN: the negative way (zero travel when already there);
//     DC/ACP/ACN need a value in [0, R): else alarm 16830.
// - DC/ACP/ACN on a rotary axis without modulo: the same ways to the position value reduced
//   into [0, 360) from the axis position reduced likewise; on a linear axis: alarm 16800 (DC),
//   16810 (ACP), 16820 (ACN).
// - FGROUP(ax, ...) names the axes whose travel counts in the path length F refers to; FGROUP()
//   restores the default, the geometry axes. A geometry axis named makes the geometry count
//   (drycut counts X, Y, Z as one: naming only some of them is taken as all three).
#include <string>
#include <vector>

#include "machine/machine_profile.hpp"
#include "parser/block.hpp"

namespace drycut::interp {

// x reduced into [0, range) (a modulo axis's position, a spindle angle).
double wrap_modulo(double x, double range);

class ExtraAxes {
 public:
  explicit ExtraAxes(const machine::MachineProfile& profile);

  size_t size() const { return axes_.size(); }
  // Index of the axis named `name` (upper case) or -1.
  int index(std::string_view name) const;
  const machine::AxisData& data(size_t i) const { return axes_[i]; }
  double position(size_t i) const { return position_[i]; }

  struct Travel {
    double travel = 0;   // signed, in the axis unit (mm or degrees)
    int alarm = 0;       // nonzero: the control refuses the value
    std::string detail;
  };
  // The travel of axis i to a value written as `mode` (Default: G90/G91 from `absolute`);
  // `unit` converts a linear axis's value to mm.
  Travel travel_to(size_t i, double value, parser::ValueMode mode, bool absolute, double unit) const;
  // Moves axis i by `travel` (a modulo axis wraps into [0, R)).
  void move(size_t i, double travel);

  // FGROUP: `names` as written; returns the first name that is not an axis, or empty.
  std::string set_feed_group(const std::vector<std::string>& names);
  // The geometry axes in the group: bit 0 X, bit 1 Y, bit 2 Z (7: all, the default).
  uint8_t geometry_feed_axes() const { return geometry_group_; }
  bool in_feed_group(size_t i) const { return in_group_[i]; }
  // FGREF[ax]: mm of path per degree of rotary axis i in the feed group (1: not set).
  void set_feed_weight(size_t i, double mm_per_unit) { feed_weight_[i] = mm_per_unit; }
  double feed_weight(size_t i) const { return feed_weight_[i]; }

  // FA[ax]: the positioning feed in units per s; MD32060 until programmed.
  void set_positioning_feed(size_t i, double per_s) { positioning_feed_[i] = per_s; }
  double positioning_feed(size_t i) const { return positioning_feed_[i]; }

  // POSA moves not yet waited for (WAITP, or a block that programs the axis again): where the
  // axis started, its signed travel and when it started and arrives on the interpreter's clock.
  struct AsyncMove {
    std::string axis;  // "A"; "S1" for spindle 1
    double from = 0, travel = 0;
    double start_s = 0, arrival_s = 0;
    double velocity = 0, accel = 0;  // of its rest-to-rest profile (positioning_share)
  };
  void mark_running(AsyncMove move);
  bool running(const std::string& axis) const;
  // Ends the wait for `axis` (no longer running); returns when it arrives (0: it was not running).
  double clear_running(const std::string& axis);
  void clear_all_running() { running_.clear(); }
  // The move of `axis` while it runs at `now` (before its arrival), else none.
  const AsyncMove* moving_at(const std::string& axis, double now) const;

 private:
  std::vector<machine::AxisData> axes_;
  std::vector<double> position_;
  std::vector<bool> in_group_;
  std::vector<double> feed_weight_;
  uint8_t geometry_group_ = 7;
  std::vector<double> positioning_feed_;
  std::vector<AsyncMove> running_;
};

}  // namespace drycut::interp
