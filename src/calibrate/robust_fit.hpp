#pragma once
// Bounded robust nonlinear least squares (the solver of `drycut calibrate`).
//
// ALGORITHM
// =========
// Problem: find p (n values, each inside [lower_j, upper_j], lower_j > 0) minimising
//   Σ_i ρ(r_i(p))   with the Huber loss ρ(r) = r²/2 for |r| <= k, k·|r| - k²/2 beyond,
// where r(p) is an m-vector (m >= n) computed by a black box (here: planning programs).
// 1. Bounds by a transform. Each value is fitted in log space through a logistic:
//      ln p_j = ln lower_j + (ln upper_j - ln lower_j) · σ(u_j),   σ(u) = 1 / (1 + e^-u),
//    so every real u gives a value inside the bounds and equal steps in u are equal ratios of p
//    near the middle. A start value is mapped back by the inverse (clamped 1e-6 inside).
// 2. Levenberg-Marquardt on u (Eigen's unsupported NonLinearOptimization LevenbergMarquardt,
//    MINPACK's lmder) minimising Σ_i w_i·r_i². The Jacobian is by forward differences with the
//    step `fd_step` in u: a planned time is piecewise smooth in the limits (a limit starts or stops
//    binding), so the step is a finite one (about 1 % of the value), not the rounding-size step of
//    an analytic derivative.
// 3. Robust loss by iteratively reweighted least squares: start with w_i = 1; after each LM run set
//    w_i = 1 where |r_i| <= k and k/|r_i| beyond (Huber's weights), and run LM again from where it
//    stopped, until the weights change by less than 1e-6 or after `irls_rounds` rounds. A
//    residual far out (a program the model cannot explain) then pulls linearly, not quadratically.
// 4. Multi-start: the whole of 2-3 from every start in the given, fixed list; the result with the
//    lowest Huber cost Σ ρ(r_i) wins (the first one on a tie), so the outcome is deterministic.
// Every residual vector the black box returns is cached by its argument: LM evaluates the point
// it then differentiates around, and restarts revisit points.
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace drycut::calibrate {

struct Bounds {
  double lower = 0;  // > 0
  double upper = 0;  // > lower
};

// Values (inside the bounds) -> residuals; the same length m for every call.
using ResidualFunction = std::function<Eigen::VectorXd(const std::vector<double>& values)>;

struct RobustFitOptions {
  double huber_k = 0.05;      // residuals beyond this get weight k/|r|
  int irls_rounds = 6;
  double fd_step = 0.01;      // forward-difference step in u
  int max_evaluations = 200;  // per LM run (MINPACK maxfev counts residual calls)
  // Relative step size in u at which LM stops: 1e-4 is below 0.1 % of any field value, finer than
  // the measurements can resolve (each evaluation plans every program).
  double xtol = 1e-4;
};

struct RobustFitResult {
  std::vector<double> values;
  Eigen::VectorXd residuals;
  Eigen::VectorXd weights;
  double cost = 0;       // Σ ρ(r_i)
  size_t start_index = 0;  // the start it came from
  int evaluations = 0;   // black-box calls (all starts, cache misses only)
};

// Maps between values and u (step 1), exposed for tests.
double to_unbounded(double value, const Bounds& b);
double from_unbounded(double u, const Bounds& b);
double huber_cost(const Eigen::VectorXd& r, double k);

RobustFitResult robust_fit(const ResidualFunction& f, const std::vector<Bounds>& bounds,
                           const std::vector<std::vector<double>>& starts, const RobustFitOptions& options = {});

}  // namespace drycut::calibrate
