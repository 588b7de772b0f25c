#pragma once
// How the axis normal to the compensation plane (Z under G17) moves on the tool-centre path.
//
// The compensation works in the plane; the normal axis follows the programmed blocks. Where the
// tool centre is "in step" with the program - at the end of an offset piece that still ends where
// its programmed block ends (outside corners, tangential joints, the approach and the retract) -
// it is at the programmed normal coordinate. Elsewhere drycut chooses (the manuals do not say;
// docs/controller-state.md "Tool radius compensation on sloped blocks"):
//
//   From the tool's current normal coordinate z_t, the path up to the next in-step point (the
//   "stretch": the first span ahead whose end is in step, else the last span in the window) has
//   to rise Q = z_anchor - z_t. Each span has a natural rise r_i (the programmed block's own
//   motion over the stretch of it that is left: a line's slope, a helix's pitch, a spline's
//   profile); an element the control inserts (transition circle, G451 intersection lines, the
//   join after a radius change) borrows the slope of the programmed piece of its block (its
//   natural rise per mm in the plane). Passengers (motions without in-plane length: a programmed
//   Z infeed) keep their own rise. What the natural rises miss, D = Q - sum r_i (the programmed
//   motion of the contour an inside corner or a cut loop skips, plus whatever an earlier
//   stretch left over), is spread over the spans of the stretch that move along the normal
//   themselves, in proportion to their in-plane length (a flat span stays flat: an approach at a
//   safe height does not start to descend because the ramp after it was shortened); when no span
//   moves, over all of them:
//       end of span 0 = z_t + r_0 + D * l_0 / sum l_i   (sums over the moving spans).
//   So both pieces at an inside corner reach the intersection at one normal coordinate, a block
//   shortened to a sliver between sloped neighbours gets a sliver of the rise (no steep or
//   vertical element), an inserted circle shares its block's slope, and an untouched block
//   (D = 0) keeps its own motion exactly (a helix its pitch).
//   A span without in-plane length (or a stretch of none) does not move the normal axis: the next
//   stretch takes the rise over.
// Where the plane is smooth (at the ends of a transition circle) the slope may still change from
// one stretch to the next: a kink of the size of that change (at most about 1 degree on the
// experiment's 5 % ramps). A cubic blend over the inserted element would remove it, but on
// circles of a few micrometres that is a bend of thousands of 1/mm for the planner.
// The window is streamed: span 0 is emitted now; the later spans may still be shortened when more
// blocks arrive, and are planned again when their turn comes (from where span 0 ended).
#include <vector>

namespace drycut::interp {

struct NormalAxisSpan {
  double in_plane_mm = 0.0;     // length in the compensation plane
  double natural_start = 0.0;   // normal coordinate of its start as the programmed block has it
  double natural_end = 0.0;     // ... and of its end
  bool inserted = false;        // an element the control inserts (borrows its block's slope)
  bool in_step_at_end = false;  // its end is the offset of its programmed block's end point
  int block = 0;                // the programmed block it belongs to
};

// The normal coordinate at the end of ahead[0], the tool being at `tool_normal` (its start).
// ahead: the span to emit now, then the spans after it in path order (at least one).
double normal_value_at_end(double tool_normal, const std::vector<NormalAxisSpan>& ahead);

}  // namespace drycut::interp
