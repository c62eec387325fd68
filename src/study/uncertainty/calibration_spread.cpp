// The calibration's step 3, the fit's spread (calibration_steps.h).
#include "study/uncertainty/calibration_steps.h"

#include <algorithm>
#include <cmath>

namespace twb {

namespace {

// Below this ratio of its smallest to largest singular value the scaled Jacobian is
// singular to the predictions' own accuracy (about 1e-8 relative: the solver's tolerance
// and the second-order differences of F_p): the data cannot tell the combination apart.
constexpr double kSingular = 1e-6;
// A combination of the scaled inputs (each by its start, or a thousandth of its range
// where that is larger) whose standard deviation exceeds a tenth of them is determined,
// but poorly.
constexpr double kPoorly = 0.1;

}  // namespace

// The inputs a bound holds are not free: they take no part in the covariance, nor in
// the degrees of freedom.
void CalibrationSteps::spread() {
  value_.resize(n_);
  at_bound_.resize(n_);
  for (std::size_t j = 0; j < n_; ++j) {
    const FittedInput& f = study_.fitted[j];
    value_[j] = std::clamp(x_[j] * scale_[j], f.lower, f.upper);
    const double tolerance = 1e-9 * (f.upper - f.lower);
    if (value_[j] <= f.lower + tolerance) at_bound_[j] = "lower";
    if (value_[j] >= f.upper - tolerance) at_bound_[j] = "upper";
    if (at_bound_[j].empty()) free_.push_back(j);
  }
  nf_ = free_.size();
  Eigen::MatrixXd J(static_cast<long>(m_), static_cast<long>(nf_));
  for (std::size_t k = 0; k < m_; ++k)
    for (std::size_t c = 0; c < nf_; ++c) J(long(k), long(c)) = jacobian_[k * n_ + free_[c]];
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  for (double r : residuals_) squares_ += r * r;
  has_variance_ = !relative_ || m_ > nf_;
  variance_ = !relative_ ? 1.0 : m_ > nf_ ? squares_ / double(m_ - nf_) : 0.0;
  const double largest = s.size() > 0 ? s(0) : 0.0;
  auto over_all = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(long(n_));
    for (std::size_t c = 0; c < nf_; ++c) full(long(free_[c])) = v(long(c));
    return full;
  };
  for (long k = 0; k < long(nf_); ++k) {
    const double ratio = k < s.size() && largest > 0.0 ? s(k) / largest : 0.0;
    if (ratio < kSingular) {
      weak_.push_back({over_all(V.col(k)), ratio, std::nullopt});
    } else if (has_variance_ && std::sqrt(variance_) / s(k) > kPoorly) {
      weak_.push_back({over_all(V.col(k)), ratio, std::sqrt(variance_) / s(k)});
    }
  }
  // A combination the data cannot determine leaves every free input's variance
  // unbounded along it: no covariance at all then.
  singular_ = std::any_of(weak_.begin(), weak_.end(), [](const Weak& w) { return !w.sd; });
  if (!singular_ && has_variance_ && variance_ > 0.0 && nf_ > 0) {
    Eigen::MatrixXd cx = Eigen::MatrixXd::Zero(long(nf_), long(nf_));
    for (long k = 0; k < long(nf_); ++k) cx += V.col(k) * V.col(k).transpose() / (s(k) * s(k));
    cx *= variance_;
    covariance_ = Eigen::MatrixXd::Zero(long(n_), long(n_));
    for (std::size_t a = 0; a < nf_; ++a)
      for (std::size_t b = 0; b < nf_; ++b)
        (*covariance_)(long(free_[a]), long(free_[b])) = cx(long(a), long(b)) * scale_[free_[a]] * scale_[free_[b]];
  }
}

}  // namespace twb
