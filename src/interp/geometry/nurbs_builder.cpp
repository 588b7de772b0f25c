// BSPLINE: NURBS through streamed control points (see spline_builder.hpp for the knot layout).
//
// Knot vector for control points P_0..P_n, degree p, with L_j the knot span of block j and
// C_k = L_1 + ... + L_k:  u_0..u_p = 0,  u_{p+k} = C_k (k = 0..n-p+1),  u_{n+1}..u_{n+p+1} = C_{n-p+1}.
// Span j = [u_{p+j-1}, u_{p+j}] is shaped by P_{j-1}..P_{j+p-1} and knots u_j..u_{j+2p-1}.
// Each span is converted to a homogeneous cubic in a normalised parameter (exact for p <= 3) by
// evaluating it with de Boor's algorithm at four parameters and interpolating.
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/polynomial_span.hpp"
#include "interp/geometry/spline_builder.hpp"
#include "interp/geometry/spline_input_check.hpp"
#include "interp/geometry/spline_parametrisation.hpp"

namespace drycut::geometry {
namespace {

using Vec4 = Eigen::Vector4d;

// Inverse transpose of the Vandermonde matrix of the nodes 0, 1/3, 2/3, 1, so that
// coefficients (columns c0..c3) = values (columns at the nodes) * kFit.
const Eigen::Matrix4d& fit_matrix() {
  static const Eigen::Matrix4d m = [] {
    Eigen::Matrix4d v;
    for (int i = 0; i < 4; ++i) {
      const double t = i / 3.0;
      v.row(i) << 1.0, t, t * t, t * t * t;
    }
    return Eigen::Matrix4d(v.transpose().inverse());
  }();
  return m;
}

class NurbsBuilder final : public SplineBuilder {
 public:
  explicit NurbsBuilder(int degree) : degree_(degree) {
    if (degree != 2 && degree != 3) throw_spline_value_alarm("SD=" + std::to_string(degree) + " (2 or 3 allowed)");
  }

  void add_point(const Vec3& p, double weight, double knot_span) override {
    if (finished_) throw std::logic_error("SplineBuilder::add_point after finish");
    check_spline_point(p);
    if (!(weight >= 0.0 && weight <= 3.0)) throw_spline_value_alarm("PW=" + std::to_string(weight) + " outside [0, 3]");
    if (!std::isfinite(knot_span)) throw_spline_value_alarm("PL not finite");
    Node node{p, weight, 0.0};
    if (count() > 0) node.cumulative = nodes_.back().cumulative + bspline_knot_span(nodes_.back().point, p, knot_span);
    nodes_.push_back(node);
    // Span j needs the knots up to u_{j+2p-1}, which are interior knots once n >= j+2p-2.
    const size_t n = count() - 1;
    while (n + 2 >= next_span_ + 2 * static_cast<size_t>(degree_)) emit_span(n, degree_, false);
    prune();
  }

  void finish(const SplineEnd& /*ignored: B splines always start and end along the polygon*/) override {
    if (finished_) return;
    finished_ = true;
    if (count() < 2) return;
    const size_t n = count() - 1;
    const int p = std::min<int>(degree_, static_cast<int>(n));
    if (p == 1) {
      ready_.push_back({std::make_shared<LineCurve>(node(0).point, node(1).point), 1});
      return;
    }
    while (next_span_ <= n - static_cast<size_t>(p) + 1) emit_span(n, p, true);
    prune();
  }

  bool pop_span(SplineSpan& out) override {
    if (ready_.empty()) return false;
    out = std::move(ready_.front());
    ready_.pop_front();
    return true;
  }

 private:
  struct Node {
    Vec3 point;
    double weight;
    double cumulative;  // C_k
  };

  static constexpr size_t kMaxDegree = 3;  // SD=2 or 3 (constructor)
  using Knots = std::array<double, 2 * kMaxDegree>;
  using Controls = std::array<Vec4, kMaxDegree + 1>;

  size_t count() const { return first_ + nodes_.size(); }
  const Node& node(size_t i) const { return nodes_[i - first_]; }

  // Knot u_i; n is only needed (and only trusted) for the clamped end once finished.
  double knot(size_t i, size_t n, int p, bool clamp_end) const {
    const size_t up = static_cast<size_t>(p);
    if (i <= up) return 0.0;
    if (clamp_end && i > n + 1) return node(n - up + 1).cumulative;
    return node(i - up).cumulative;
  }

  void emit_span(size_t n, int p, bool clamp_end) {
    const size_t j = next_span_++;
    const size_t up = static_cast<size_t>(p);
    // Fixed arrays (p <= kMaxDegree): six heap blocks per span were 2.4 % of a BSPLINE run.
    Knots u{};  // u_j .. u_{j+2p-1}
    for (size_t i = 0; i < 2 * up; ++i) u[i] = knot(j + i, n, p, clamp_end);
    const double a = u[up - 1], b = u[up];  // span [u_{p+j-1}, u_{p+j}]
    // Equal positive weights (PW not programmed, or the same PW on every point) cancel in
    // P = (Σ w N_i P_i) / (Σ w N_i): the span is the polynomial B spline of the points, written
    // with w == 1 exactly. De Boor's affine steps would leave w = 1 ± a few ulps, and the
    // rational formulas (the quotient rule in every speed evaluation of the arc-length table
    // and its inversions) would run on every span.
    bool equal_weights = node(j - 1).weight > 0.0;
    for (size_t i = 1; i <= up; ++i) equal_weights = equal_weights && node(j - 1 + i).weight == node(j - 1).weight;
    Controls ctrl;
    for (size_t i = 0; i <= up; ++i) {
      const Node& q = node(j - 1 + i);
      if (equal_weights) {
        ctrl[i] << q.point, 1.0;
      } else {
        ctrl[i] << q.weight * q.point, q.weight;
      }
    }
    Eigen::Matrix4d values;
    for (int k = 0; k < 4; ++k) values.col(k) = de_boor(ctrl, u, up, a + (b - a) * k / 3.0);
    if (!(values(3, 0) > 0.0 && values(3, 3) > 0.0)) {
      throw_spline_value_alarm("PW=0 leaves the B spline undefined at block " + std::to_string(j));
    }
    Eigen::Matrix4d coefficients = values * fit_matrix();
    if (equal_weights) coefficients.row(3) << 1.0, 0.0, 0.0, 0.0;
    // Rounding must not invent a cubic term in a degree-2 span.
    if (p == 2) coefficients.col(3).setZero();
    auto span = std::make_shared<PolynomialSpan>(coefficients, 1.0);
    span->length();  // the table now, on the interpreting thread: a B-spline's planner is the longer one
    ready_.push_back({std::move(span), j});
  }

  // de Boor on the local control points d_0..d_p with local knots t_0..t_{2p-1}
  // (t_{p-1} <= x <= t_p).
  static Vec4 de_boor(Controls d, const Knots& t, size_t p, double x) {
    for (size_t r = 1; r <= p; ++r) {
      for (size_t i = p; i >= r; --i) {
        const double left = t[i - 1];
        const double right = t[i + p - r];
        const double alpha = right > left ? (x - left) / (right - left) : 0.0;
        d[i] = (1.0 - alpha) * d[i - 1] + alpha * d[i];
      }
    }
    return d[p];
  }

  void prune() {
    // Span j reads nodes from j-p (knot u_j = C_{j-p}) and j-1 (first control point).
    const size_t up = static_cast<size_t>(degree_);
    const size_t keep = next_span_ > up ? next_span_ - up : 0;
    while (first_ < keep && !nodes_.empty()) {
      nodes_.pop_front();
      ++first_;
    }
  }

  int degree_;
  std::deque<Node> nodes_;
  size_t first_ = 0;
  size_t next_span_ = 1;
  bool finished_ = false;
  std::deque<SplineSpan> ready_;
};

}  // namespace

std::unique_ptr<SplineBuilder> make_nurbs_builder(int degree) { return std::make_unique<NurbsBuilder>(degree); }

}  // namespace drycut::geometry
