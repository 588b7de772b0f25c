#include "calibrate/robust_fit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unsupported/Eigen/NonLinearOptimization>

namespace drycut::calibrate {
namespace {

// The black box in u, with its cache (step 4).
class CachedProblem {
 public:
  CachedProblem(const ResidualFunction& f, const std::vector<Bounds>& bounds) : f_(f), bounds_(bounds) {}

  std::vector<double> values(const Eigen::VectorXd& u) const {
    std::vector<double> v(u.size());
    for (int j = 0; j < u.size(); ++j) v[j] = from_unbounded(u[j], bounds_[j]);
    return v;
  }
  const Eigen::VectorXd& residuals(const Eigen::VectorXd& u) {
    std::vector<double> key(u.data(), u.data() + u.size());
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    ++evaluations;
    Eigen::VectorXd r = f_(values(u));
    if (size_ < 0) size_ = static_cast<int>(r.size());
    if (r.size() != size_) throw std::logic_error("robust_fit: residual count changed between calls");
    return cache_.emplace(std::move(key), std::move(r)).first->second;
  }
  int size() {
    if (size_ < 0) throw std::logic_error("robust_fit: size before the first evaluation");
    return size_;
  }
  int evaluations = 0;

 private:
  const ResidualFunction& f_;
  const std::vector<Bounds>& bounds_;
  std::map<std::vector<double>, Eigen::VectorXd> cache_;
  int size_ = -1;
};

// Weighted residuals sqrt(w)·r in u, with a forward-difference Jacobian (step 2).
struct WeightedFunctor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  CachedProblem& problem;
  Eigen::VectorXd sqrt_w;
  double step;
  int n;

  int inputs() const { return n; }
  int values() const { return static_cast<int>(sqrt_w.size()); }
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& fvec) const {
    fvec = problem.residuals(u).cwiseProduct(sqrt_w);
    return 0;
  }
  int df(const Eigen::VectorXd& u, Eigen::MatrixXd& fjac) const {
    const Eigen::VectorXd base = problem.residuals(u).cwiseProduct(sqrt_w);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd moved = u;
      moved[j] += step;
      fjac.col(j) = (problem.residuals(moved).cwiseProduct(sqrt_w) - base) / step;
    }
    return 0;
  }
};

Eigen::VectorXd huber_weights(const Eigen::VectorXd& r, double k) {
  Eigen::VectorXd w(r.size());
  for (int i = 0; i < r.size(); ++i) w[i] = std::abs(r[i]) <= k ? 1.0 : k / std::abs(r[i]);
  return w;
}

// Steps 2-3 from one start.
Eigen::VectorXd fit_from(CachedProblem& problem, Eigen::VectorXd u, const RobustFitOptions& o) {
  const int m = static_cast<int>(problem.residuals(u).size());
  Eigen::VectorXd w = Eigen::VectorXd::Ones(m);
  for (int round = 0; round < o.irls_rounds; ++round) {
    WeightedFunctor functor{problem, w.cwiseSqrt(), o.fd_step, static_cast<int>(u.size())};
    Eigen::LevenbergMarquardt<WeightedFunctor> lm(functor);
    lm.parameters.maxfev = o.max_evaluations;
    lm.parameters.xtol = o.xtol;
    lm.parameters.ftol = 1e-10;
    lm.minimize(u);
    const Eigen::VectorXd next = huber_weights(problem.residuals(u), o.huber_k);
    const double change = (next - w).cwiseAbs().maxCoeff();
    w = next;
    if (change < 1e-6) break;
  }
  return u;
}

}  // namespace

double to_unbounded(double value, const Bounds& b) {
  const double lo = std::log(b.lower), hi = std::log(b.upper);
  double s = (std::log(std::clamp(value, b.lower, b.upper)) - lo) / (hi - lo);
  s = std::clamp(s, 1e-6, 1.0 - 1e-6);
  return std::log(s / (1.0 - s));
}

double from_unbounded(double u, const Bounds& b) {
  const double lo = std::log(b.lower), hi = std::log(b.upper);
  return std::exp(lo + (hi - lo) / (1.0 + std::exp(-u)));
}

double huber_cost(const Eigen::VectorXd& r, double k) {
  double c = 0;
  for (int i = 0; i < r.size(); ++i) {
    const double a = std::abs(r[i]);
    c += a <= k ? 0.5 * a * a : k * a - 0.5 * k * k;
  }
  return c;
}

RobustFitResult robust_fit(const ResidualFunction& f, const std::vector<Bounds>& bounds,
                           const std::vector<std::vector<double>>& starts, const RobustFitOptions& options) {
  if (bounds.empty() || starts.empty()) throw std::invalid_argument("robust_fit: no parameters or no start");
  for (const Bounds& b : bounds)
    if (!(b.lower > 0 && b.upper > b.lower)) throw std::invalid_argument("robust_fit: bounds need 0 < lower < upper");
  CachedProblem problem(f, bounds);
  RobustFitResult best;
  bool have = false;
  for (size_t s = 0; s < starts.size(); ++s) {
    if (starts[s].size() != bounds.size()) throw std::invalid_argument("robust_fit: start of the wrong size");
    Eigen::VectorXd u(bounds.size());
    for (size_t j = 0; j < bounds.size(); ++j) u[j] = to_unbounded(starts[s][j], bounds[j]);
    if (problem.residuals(u).size() < static_cast<int>(bounds.size()))
      throw std::invalid_argument("robust_fit: fewer residuals than parameters");
    u = fit_from(problem, u, options);
    const Eigen::VectorXd& r = problem.residuals(u);
    const double cost = huber_cost(r, options.huber_k);
    if (!have || cost < best.cost) {
      have = true;
      best.values = problem.values(u);
      best.residuals = r;
      best.weights = huber_weights(r, options.huber_k);
      best.cost = cost;
      best.start_index = s;
    }
  }
  best.evaluations = problem.evaluations;
  return best;
}

}  // namespace drycut::calibrate
