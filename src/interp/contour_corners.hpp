#pragma once
// Contour corners: chamfer and rounding written into a block (RND=, RNDM=, CHF=, CHR=, FRC=,
// FRCM=; docs/controller-state.md "Contour corners"). An element filter inside the interpreter,
// before tool radius compensation: the inserted element belongs to the programmed contour, so
// the compensation, the compressor, the smoothing and the planner see it as any other element,
// and `drycut path --elements` lists it.
//
// WHAT THE CONTROL DOES (Fundamentals, "Contour corners: chamfer, rounding")
//   The word stands in the block that leads to the corner; the element is inserted between that
//   block and the next block that traverses in the working plane (G17/G18/G19). RND=r: a circle
//   of radius r tangent to both blocks. CHF=c: a straight chamfer whose own length is c. CHR=c:
//   a straight chamfer whose legs, measured along the two blocks from the corner, are c. RNDM=r
//   rounds every following corner until RNDM=0. FRC= (this block) / FRCM= (modal, 0 = off) give
//   the feed of the inserted element; without them it takes the feed of the block leading away
//   from the corner (MD20201 default); on a G0 element F, FRC and FRCM do not act. A value too
//   large for the blocks is reduced. No element is inserted across a plane change or when more
//   than three blocks without motion in the plane come between.
//
// WHAT DRYCUT DOES (both blocks straight, G0/G1, in the plane)
//   u1 = unit direction of the block into the corner C, u2 = of the block out of it, n the plane
//   normal in machine coordinates (the frame applied). θ = angle between u1 and u2 (the change
//   of direction, 0 < θ < π). Each block gives up the leg t next to C:
//     RND=r:  t = r·tan(θ/2)       CHF=c:  t = c / (2·cos(θ/2))       CHR=c:  t = c
//   P1 = C - t·u1 (the first block now ends there), P2 = C + t·u2 (the second starts there).
//   Rounding: w = unit(u2 - (u2·u1)·u1) points from the first line to the inside of the turn;
//   centre M = P1 + r·w; the arc starts at P1 with e1 = -w, e2 = u1 and sweeps +θ (its tangent
//   at the start is u1, at the end u2); length r·θ. Chamfer: the line P1 → P2, length
//   2·t·cos(θ/2) (= c for CHF). The path gets shorter by 2t minus the inserted length.
//   A leg longer than the room on either block (what is left of the first block after its own
//   start was trimmed, the whole second block) is reduced to that room and the value with it
//   (drycut's warning 990015; the manual says only that the value is reduced, not by how
//   much: drycut takes the largest that fits). Feed: FRC, else FRCM, else the second
//   block's feed; rapid if the second block is G0. The inserted element carries the first
//   block's source, dynamics and compensation request; a G9 of the first block moves to it.
//   RND/RNDM next to a circle (line-circle, circle-line, circle-circle in the plane): the
//   rounding circle tangent to both, rounding_with_arcs.hpp; it is not reduced when too large
//   (the corner stays sharp, warned).
//   Not modelled (warning 990002 naming it, the corner stays sharp): CHF/CHR next to a circle, a
//   spline or other curve on either side, a helix, a block moving out of the plane (third-axis component) or moving extra
//   axes, a dwell, stop, tool change or positioning between the blocks, the next motion in
//   another program level, no next motion at all, a reversal (θ = π). Parallel blocks (θ = 0)
//   have no corner: nothing is inserted, silently.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "interp/path_element.hpp"
#include "machine/alarm.hpp"

namespace drycut::interp {

// The legs t and the inserted element of one corner (see above); nullopt when the corner is not
// a corner (parallel or reversing directions). size: r for a rounding, c for a chamfer.
struct CornerGeometry {
  double leg = 0;           // t along each block
  geometry::CurvePtr curve;  // arc (rounding) or line (chamfer) from P1 to P2
};
std::optional<CornerGeometry> corner_geometry(ContourCornerKind kind, double size_mm, const geometry::Vec3& corner,
                                              const geometry::Vec3& u1, const geometry::Vec3& u2);
// The word that asks for the corner: RND, RNDM (modal rounding), CHF or CHR.
const char* corner_word(const ContourCornerRequest& r);
// The leg a chamfer or rounding of this size has at a change of direction θ (radians).
double corner_leg(ContourCornerKind kind, double size_mm, double theta);
// The size that gives leg t (the inverse, for the reduction).
double corner_size_for_leg(ContourCornerKind kind, double leg_mm, double theta);

class ContourCorners final : public ElementSink {
 public:
  ContourCorners(ElementSink& next, Diagnostics& diagnostics) : next_(&next), diagnostics_(diagnostics) {}

  // The interpreter starts a block (one without elements still counts as a block between).
  void begin_block() {
    if (pending_) ++blocks_since_;
  }
  void consume(PathElement&& element) override;
  void finish() override;

  uint64_t corners_inserted() const { return inserted_; }

  // Hands on the element held for a corner that has not come yet (none will: the stream is
  // being redirected), then sends what follows to `next` (contour recording, contour_recording.hpp).
  void redirect(ElementSink& next) {
    flush();
    next_ = &next;
  }

 private:
  void hold(PathElement&& line);
  // Inserts the corner between pending_ and b; false: not modelled here (warned) or no corner.
  bool insert_corner(PathElement& b);
  // RND next to a circle (rounding_with_arcs.hpp); the same contract as insert_corner.
  bool insert_rounding_with_arcs(PathElement& b, const geometry::Vec3& n);
  static PathElement corner_element(PathElement& a, const PathElement& b, ElementKind kind, geometry::CurvePtr curve);
  void hand_on_corner(bool first_left, PathElement&& inserted);
  // Hands on pending_ unchanged, then what came after it, with a warning naming why.
  // modal_silent: an RNDM request gives up without a warning (no corner follows).
  void give_up(const std::string& why, bool modal_silent = false);
  void flush();
  void warn(const PathElement& at, const std::string& what);

  ElementSink* next_;
  Diagnostics& diagnostics_;
  std::optional<PathElement> pending_;  // a straight element whose end gets the corner
  std::vector<PathElement> between_;     // DynamicsChange elements after it
  int blocks_since_ = 0;                 // blocks begun since pending_ arrived
  uint64_t inserted_ = 0;
  std::set<std::string> warned_;
};

}  // namespace drycut::interp
