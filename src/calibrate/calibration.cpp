#include "calibrate/calibration.hpp"

#include <spdlog/spdlog.h>

#include <atomic>
#include <cstdio>
#include <sstream>
#include <cmath>
#include <thread>

namespace drycut::calibrate {
namespace {

constexpr double kSensitivityStep = 0.05;  // in ln(field)

std::string fmt_matrix(const Eigen::MatrixXd& m) {
  std::ostringstream out;
  out << m;
  return out.str();
}

double mape(const std::vector<RunOutcome>& runs, bool fitted) {
  double sum = 0;
  for (const RunOutcome& r : runs) {
    const Prediction& p = fitted ? r.fitted : r.start;
    sum += std::abs(*p.time_s - r.measured_s) / r.measured_s;
  }
  return 100.0 * sum / static_cast<double>(runs.size());
}

}  // namespace

std::string Calibration::values_text(const std::vector<double>& values) const {
  std::string out;
  for (size_t j = 0; j < fields_.size(); ++j) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s %.4g", out.empty() ? "" : ", ", fields_[j]->name.c_str(), values[j]);
    out += buf;
  }
  return out;
}

Calibration::Calibration(const Measurements& measurements, std::vector<RecordedProgram> programs,
                         machine::MachineProfile base, std::vector<const ProfileField*> fields,
                         CalibrationOptions options)
    : measurements_(measurements),
      programs_(std::move(programs)),
      base_(std::move(base)),
      fields_(std::move(fields)),
      options_(options) {
  if (programs_.size() != measurements_.runs.size()) throw std::logic_error("Calibration: one program per run");
  if (fields_.empty()) throw CalibrationError("no field to fit");
  for (const ProfileField* f : fields_) bounds_.push_back(Bounds{f->lower, f->upper});
  if (options_.jobs == 0) options_.jobs = 1;
}

machine::MachineProfile Calibration::with_values(const std::vector<double>& values) const {
  machine::MachineProfile p = base_;
  for (size_t j = 0; j < fields_.size(); ++j) fields_[j]->set(p, values[j]);
  return p;
}

std::vector<Prediction> Calibration::predict_all(const std::vector<double>& values,
                                                 const std::vector<size_t>& which) const {
  std::vector<size_t> runs = which;
  if (runs.empty())
    for (size_t i = 0; i < programs_.size(); ++i) runs.push_back(i);
  const machine::MachineProfile profile = with_values(values);
  std::vector<Prediction> out(runs.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k = next++; k < runs.size(); k = next++) {
      const MeasuredRun& m = measurements_.runs[runs[k]];
      out[k] = predict(programs_[runs[k]], profile, m.span, measurements_.feed_window);
    }
  };
  const unsigned threads = std::min<unsigned>(options_.jobs, static_cast<unsigned>(runs.size()));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  for (size_t k = 0; k < runs.size(); ++k)
    if (!out[k].time_s)
      throw CalibrationError(measurements_.runs[runs[k]].name + ": the run does not reach its span's events");
  return out;
}

Eigen::VectorXd Calibration::residuals(const std::vector<double>& values, const std::vector<size_t>& which) const {
  const std::vector<Prediction> p = predict_all(values, which);
  std::vector<double> r;
  for (size_t k = 0; k < p.size(); ++k) {
    const MeasuredRun& m = measurements_.runs[which.empty() ? k : which[k]];
    r.push_back((*p[k].time_s - m.time_s) / m.time_s);
    if (options_.feed_weight > 0 && m.min_feed_mm_min) {
      // No motion in the window reads as standstill; 1 mm/min keeps the logarithm finite.
      const double v = std::max(p[k].min_feed_mm_min.value_or(0.0), 1.0);
      r.push_back(options_.feed_weight * std::log(v / *m.min_feed_mm_min));
    }
  }
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

Eigen::MatrixXd Calibration::sensitivity(const std::vector<double>& values) const {
  Eigen::MatrixXd s(programs_.size(), fields_.size());
  for (size_t j = 0; j < fields_.size(); ++j) {
    std::vector<double> up = values, down = values;
    up[j] = std::min(values[j] * std::exp(kSensitivityStep), bounds_[j].upper);
    down[j] = std::max(values[j] * std::exp(-kSensitivityStep), bounds_[j].lower);
    const auto a = predict_all(up), b = predict_all(down);
    const double dln = std::log(up[j] / down[j]);
    for (size_t i = 0; i < programs_.size(); ++i) s(i, j) = (*a[i].time_s - *b[i].time_s) / dln;
  }
  return s;
}

std::vector<std::vector<double>> Calibration::starts() const {
  std::vector<std::vector<double>> out;
  std::vector<double> own;
  for (size_t j = 0; j < fields_.size(); ++j)
    own.push_back(std::clamp(fields_[j]->get(base_), bounds_[j].lower, bounds_[j].upper));
  out.push_back(own);
  for (double share : {0.25, 0.5, 0.75}) {
    std::vector<double> s;
    for (const Bounds& b : bounds_) s.push_back(std::exp(std::log(b.lower) + share * std::log(b.upper / b.lower)));
    out.push_back(s);
  }
  // With several fields, each one also alone at 1/4 and 3/4 while the others keep the profile's
  // values: a limit that does not bind at a start has no gradient there (a plateau), so a joint
  // start can miss an optimum a single field reaches.
  if (fields_.size() > 1) {
    for (size_t j = 0; j < fields_.size(); ++j)
      for (double share : {0.25, 0.75}) {
        std::vector<double> s = own;
        s[j] = std::exp(std::log(bounds_[j].lower) + share * std::log(bounds_[j].upper / bounds_[j].lower));
        out.push_back(s);
      }
  }
  return out;
}

void Calibration::check_sensitive(const std::vector<std::vector<double>>& starts) const {
  std::vector<double> largest(fields_.size(), 0.0);
  for (const auto& start : starts) {
    const Eigen::MatrixXd s = sensitivity(start);
    for (size_t j = 0; j < fields_.size(); ++j) largest[j] = std::max(largest[j], s.col(j).cwiseAbs().maxCoeff());
  }
  for (size_t j = 0; j < fields_.size(); ++j) {
    spdlog::debug("calibrate: {} largest |dt/dln| over the starts {:.4f} s", fields_[j]->name, largest[j]);
    if (largest[j] < options_.min_sensitivity_s)
      throw CalibrationError("cannot identify " + fields_[j]->name + " (" + fields_[j]->machine_data +
                             "): no measured run's time changes with it (largest |d time / d ln " + fields_[j]->name +
                             "| " + std::to_string(largest[j]) + " s over the starts, below " +
                             std::to_string(options_.min_sensitivity_s) + " s)");
  }
}

void Calibration::check_rank(const Eigen::MatrixXd& s, const std::vector<double>& values) const {
  for (size_t j = 0; j < fields_.size(); ++j)
    if (s.col(static_cast<Eigen::Index>(j)).cwiseAbs().maxCoeff() < options_.min_sensitivity_s)
      throw CalibrationError("cannot identify " + fields_[j]->name + " (" + fields_[j]->machine_data +
                             "): at the fitted values (" + values_text(values) +
                             ") no measured run's time changes with it (the fit ran to where it has no effect)");
  if (fields_.size() < 2) return;
  Eigen::MatrixXd scaled = s;
  for (Eigen::Index j = 0; j < s.cols(); ++j) scaled.col(j) /= std::max(s.col(j).norm(), 1e-300);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const double smallest = svd.singularValues().minCoeff();
  if (smallest < options_.min_singular) {
    // The right singular vector of the smallest value names the fields that act alike.
    const Eigen::VectorXd v = svd.matrixV().col(svd.singularValues().size() - 1);
    std::string names;
    const double largest = v.cwiseAbs().maxCoeff();
    for (Eigen::Index j = 0; j < v.size(); ++j)
      if (std::abs(v[j]) >= 0.3 * largest) names += (names.empty() ? "" : ", ") + fields_[j]->name;
    spdlog::debug("calibrate: scaled sensitivities\n{}\nnull direction {}", fmt_matrix(scaled), fmt_matrix(v.transpose()));
    throw CalibrationError("cannot identify " + names + " together: their effects on the measured times are "
                           "(nearly) proportional (smallest singular value of the scaled Jacobian " +
                           std::to_string(smallest) + " at " + values_text(values) + "); fit fewer fields");
  }
}

CalibrationReport Calibration::run() {
  const auto start_list = starts();
  check_sensitive(start_list);
  std::vector<size_t> all;
  for (size_t i = 0; i < programs_.size(); ++i) all.push_back(i);
  ResidualFunction f = [&](const std::vector<double>& v) { return residuals(v, {}); };
  const RobustFitResult fit = robust_fit(f, bounds_, start_list, options_.fit);
  const Eigen::MatrixXd s = sensitivity(fit.values);
  spdlog::debug("calibrate: sensitivities at the optimum (start {}, Huber cost {})\n{}", fit.start_index, fit.cost,
                fmt_matrix(s));
  check_rank(s, fit.values);

  CalibrationReport report;
  report.profile = with_values(fit.values);
  report.huber_cost = fit.cost;
  report.start_index = fit.start_index;
  report.evaluations = fit.evaluations;
  for (size_t j = 0; j < fields_.size(); ++j) {
    const double width = std::log(bounds_[j].upper / bounds_[j].lower);
    const double pos = std::log(fit.values[j] / bounds_[j].lower) / width;
    report.fields.push_back({fields_[j], start_list[0][j], fit.values[j], pos < 0.01 || pos > 0.99});
  }
  const auto start_pred = predict_all(start_list[0]);
  const auto fitted_pred = predict_all(fit.values);
  for (size_t i = 0; i < programs_.size(); ++i) {
    const MeasuredRun& m = measurements_.runs[i];
    RunOutcome r{m.name, m.time_s, m.min_feed_mm_min, start_pred[i], fitted_pred[i], std::nullopt, {}};
    for (Eigen::Index j = 0; j < s.cols(); ++j) r.sensitivity.push_back(s(i, j));
    report.runs.push_back(std::move(r));
  }
  report.mape_start = mape(report.runs, false);
  report.mape_fitted = mape(report.runs, true);
  if (options_.leave_one_out && programs_.size() > fields_.size()) {
    double sum = 0;
    for (size_t left = 0; left < programs_.size(); ++left) {
      std::vector<size_t> kept;
      for (size_t i : all)
        if (i != left) kept.push_back(i);
      ResidualFunction g = [&](const std::vector<double>& v) { return residuals(v, kept); };
      const RobustFitResult refit = robust_fit(g, bounds_, {fit.values, start_list[0]}, options_.fit);
      const double t = *predict_all(refit.values, {left})[0].time_s;
      report.runs[left].loo_s = t;
      sum += std::abs(t - measurements_.runs[left].time_s) / measurements_.runs[left].time_s;
      report.evaluations += refit.evaluations;
    }
    report.mape_loo = 100.0 * sum / static_cast<double>(programs_.size());
  }
  return report;
}

}  // namespace drycut::calibrate
