#pragma once
// A move from rest to rest on the interpreter's clock (interpreter_clock.cpp): its time, and how
// far a positioning axis has come along it (POSA, read back by $AA_IM while it runs).

namespace drycut::interp {

// Rest-to-rest time over a distance d at velocity v, acceleration a and jerk j (j <= 0: none).
double rest_to_rest_s(double d, double v, double a, double j);

// Time to come to rest over a distance d when the move starts at velocity v0 >= 0 (SPOS from
// rotation: the spindle enters position control turning), cruising at most at max(v, v0) with
// acceleration a; no jerk limit is taken when v0 > 0 (the spindle's moves have none). v0 = 0 is
// rest_to_rest_s. d must be at least the braking distance v0²/(2a) (else the braking alone).
double move_to_rest_s(double d, double v0, double v, double a, double j);

// Share (0..1) of a rest-to-rest move of `distance` at velocity v and acceleration a (trapezoid,
// BRISKA) covered `t` seconds after its start; `duration` is the move's time as the clock has it
// (with a jerk limit longer than the trapezoid's: the trapezoid is stretched to it).
double positioning_share(double distance, double v, double a, double duration, double t);

}  // namespace drycut::interp
