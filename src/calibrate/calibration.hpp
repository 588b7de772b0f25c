#pragma once
// Calibration of profile fields against measured programs (`drycut calibrate`, docs/calibrate.md).
//
// ALGORITHM
// =========
// Residuals. For run i with measured time T_i and prediction t_i(p) (the run's span planned on the
// profile with the fields set to p): r = (t_i - T_i) / T_i. Where the run has a measured lowest
// feed V_i and feed_weight > 0, also r = feed_weight · ln(v_i(p) / V_i) (a display reading:
// a ratio, weighted down). The fit is robust_fit.hpp (log/logistic bounds, LM, Huber IRLS,
// multi-start) over these residuals.
// Starts (fixed, so the output is deterministic): the profile's own values, then for every field
// at once the geometric points 1/4, 1/2 and 3/4 of the way between its bounds in log space; with
// several fields also each field alone at 1/4 and 3/4, the others at the profile's values (a limit
// that does not bind has no gradient: a joint start can miss what one field alone reaches).
// Identifiability, before fitting: the sensitivity S_ij = d t_i / d ln p_j (central differences,
// ln p ± 0.05, clamped to the bounds) at every start. A field whose largest |S_ij| over all runs
// and starts is below `min_sensitivity_s` moves no time measurably: refused. After the fit, S at
// the optimum: a field without effect there (the fit ran to where it does not act) is refused; with
// the columns scaled to unit length, a smallest singular value below `min_singular` means two
// fields act alike (rank-deficient Jacobian): refused, naming the fields of the null direction.
// Leave-one-out: for every run, the fit without it (two starts: the full fit's optimum and the
// base profile's values), then its time predicted with those values; the LOO error is that
// prediction's relative error.
// Each evaluation plans every run, spread over `jobs` threads (a run on one thread at a time).
#include <optional>
#include <string>
#include <vector>

#include "calibrate/measurements.hpp"
#include "calibrate/profile_fields.hpp"
#include "calibrate/program_replay.hpp"
#include "calibrate/robust_fit.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::calibrate {

struct CalibrationOptions {
  double feed_weight = 0.1;
  double min_sensitivity_s = 0.01;  // s of time per unit of ln(field)
  double min_singular = 0.02;
  bool leave_one_out = true;
  unsigned jobs = 1;
  RobustFitOptions fit;
};

// A field the data cannot identify, or a fit that cannot run: the message says which and why.
class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOutcome {
  std::string name;
  double measured_s = 0;
  std::optional<double> measured_feed;
  Prediction start;  // with the profile's own values
  Prediction fitted;
  std::optional<double> loo_s;  // predicted without this run in the fit
  std::vector<double> sensitivity;  // d t / d ln p_j at the optimum, per field
};

struct FieldOutcome {
  const ProfileField* field = nullptr;
  double start = 0;
  double fitted = 0;
  bool at_bound = false;  // within 1 % (in log space) of a bound
};

struct CalibrationReport {
  std::vector<FieldOutcome> fields;
  std::vector<RunOutcome> runs;
  machine::MachineProfile profile;  // the base profile with the fitted values
  double mape_start = 0, mape_fitted = 0;  // mean |relative time error|, %
  std::optional<double> mape_loo;          // %
  double huber_cost = 0;
  size_t start_index = 0;
  int evaluations = 0;
};

class Calibration {
 public:
  Calibration(const Measurements& measurements, std::vector<RecordedProgram> programs,
              machine::MachineProfile base, std::vector<const ProfileField*> fields, CalibrationOptions options);

  // Throws CalibrationError for an unidentifiable field.
  CalibrationReport run();

  // Predictions of the runs `which` (all when empty) with the fields set to `values`.
  std::vector<Prediction> predict_all(const std::vector<double>& values, const std::vector<size_t>& which = {}) const;

 private:
  machine::MachineProfile with_values(const std::vector<double>& values) const;
  Eigen::VectorXd residuals(const std::vector<double>& values, const std::vector<size_t>& which) const;
  Eigen::MatrixXd sensitivity(const std::vector<double>& values) const;
  void check_sensitive(const std::vector<std::vector<double>>& starts) const;
  void check_rank(const Eigen::MatrixXd& s, const std::vector<double>& values) const;
  std::string values_text(const std::vector<double>& values) const;
  std::vector<std::vector<double>> starts() const;

  const Measurements& measurements_;
  std::vector<RecordedProgram> programs_;
  machine::MachineProfile base_;
  std::vector<const ProfileField*> fields_;
  std::vector<Bounds> bounds_;
  CalibrationOptions options_;
};

}  // namespace drycut::calibrate
