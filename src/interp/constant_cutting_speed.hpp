#pragma once
// G96 constant cutting speed along one move (Fundamentals, "Constant cutting rate (G96/G961/
// G962, G97/G971/G972/G973, LIMS, SCC)"): the spindle turns at n = Vc / (π·D), D = 2|x| the
// diameter at the tool (x the position of the SCC axis), limited to [n_min, n_max] (LIMS, G26,
// MD35100 above; G25 below). Under G95 the path speed is v = f·n/60, so on a facing or taper
// cut the feed changes with the diameter; the planner takes one feed per block, the one that
// gives the block its true time.
//
// Algorithm: x runs linearly from x0 to x1 over the block (exact for a straight move; a circle
// is taken with the same linear run of x between its end points). The time is
//   T = ∫ ds / v = (L / |x1 − x0|) · ∫_{x0}^{x1} 60 / (f · n(x)) |dx|,
// so the constant speed with that time is the harmonic mean n_eff = |x1 − x0| / ∫ |dx| / n(x).
// 1/n is piecewise linear in r = |x|: 1/n_max for r ≤ r_max = Vc / (2π·n_max), 2π·r / Vc up to
// r_min = Vc / (2π·n_min), 1/n_min beyond; each piece is integrated exactly, and a move across
// the centre (x0, x1 of opposite signs) is split there. x0 = x1: n at x0.
namespace drycut::interp {

// `speed_mm_min` Vc; `x0`, `x1` the SCC axis position (mm, radius) at the block's start and end;
// `min_rpm` 0 for none; `max_rpm` > 0.
double constant_cutting_speed_rpm(double speed_mm_min, double x0, double x1, double min_rpm, double max_rpm);

}  // namespace drycut::interp
