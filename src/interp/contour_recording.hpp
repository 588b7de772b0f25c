#pragma once
// Contour recording: how drycut's own contour cycles (CYCLE95 ...) read the contour they
// machine. The control's cycles do this with contour preparation: CONTPRON(table, ...) before
// the contour's blocks makes the control decode them into a table instead of moving, and
// EXECUTE(error) returns to normal running (Job Planning, "User stock removal programs",
// CONTPRON / EXECUTE). drycut's cycles use their own pair of commands with the same meaning,
// DRYCUT_CONTOUR_BEGIN / DRYCUT_CONTOUR_END, and read the elements as
// $DRYCUT_CONTOUR_N (how many) and $DRYCUT_CONTOUR[i, k] (i from 0); CONTPRON's own table
// layout is not reproduced (docs/cycles.md, "Contour cycles").
//
// WHAT HAPPENS
//   BEGIN: the elements the interpreter makes from this block on (lines, circles, the chamfers and
//   roundings of RND/CHF, after the frames and the tool length) go to the recorder instead of
//   the planner. The blocks run as usual otherwise: modal state, variables, warnings.
//   END: the recorder stops; the position, the tool length applied, the path tangent, the clock,
//   the dynamics mode, the tool, the further axes and what a block leaves open for the next go
//   back to what they were at BEGIN (Interpreter::stop_recording): the tool has not moved and no
//   time has passed. Modal G functions are left to the cycle (its SAVE restores them).
//   Each element is kept in the workpiece system (the inverse of the frames and the tool length
//   in force when it was made), in program units, plane ordinates as radius (not diameter).
//   $DRYCUT_CONTOUR[i, k], in the working plane active when it is read (G18: abscissa Z,
//   ordinate X): k = 0 kind (0 G0, 1 G1, 2 G2, 3 G3: a circle's sense, clockwise G2, is judged
//   looking along the plane normal from its positive side, as for G2/G3), 1/2 start
//   abscissa/ordinate, 3/4 end, 5/6 circle centre, 7 the circle's sweep in degrees (positive
//   counter-clockwise: G3), 8 its radius (7/8 as 5/6 are 0 for a line). A spline or other curve
//   is recorded as the line between its ends (the cycles see its chord).
#include <functional>
#include <optional>
#include <vector>

#include "interp/path_element.hpp"
#include "interp/polar_coordinates.hpp"

namespace drycut::interp {

struct RecordedContourElement {
  bool rapid = false;
  bool arc = false;
  // Workpiece system, program units, radius; quarter: the point a quarter along (its sense).
  geometry::Vec3 start, quarter, end, centre;
  double sweep_deg = 0;  // a circle's angle, without sign (frames keep it; the sense is from quarter)
};

class ContourRecorder final : public ElementSink {
 public:
  // Maps a machine position of the element to the workpiece system (see above).
  using ToWorkpiece = std::function<geometry::Vec3(const geometry::Vec3&)>;

  void start(ToWorkpiece to_workpiece) {
    elements_.clear();
    to_workpiece_ = std::move(to_workpiece);
    active_ = true;
  }
  void stop() { active_ = false; }
  bool active() const { return active_; }

  void consume(PathElement&& element) override;
  void finish() override {}

  static constexpr int kColumns = 9;  // k = 0 .. 8 (see above)
  size_t size() const { return elements_.size(); }
  // Column k of element i in the given plane; nullopt out of range.
  std::optional<double> value(size_t i, int k, const PlaneIndices& plane) const;

 private:
  std::vector<RecordedContourElement> elements_;
  ToWorkpiece to_workpiece_;
  bool active_ = false;
};

}  // namespace drycut::interp
