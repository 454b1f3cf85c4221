#pragma once
// Private to the solvers (not installed): the step-size control of rk8pd-events
// (event_adaptive.cc), in its own header so that its acceptance rule is tested directly.

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace bearing::solvers_detail {

// PI step-size control (Gustafsson) on the error ratio of gsl_odeiv2_control_scaled,
//     r = max_i |err_i| / (atol s_i + rtol |y_i|),
// accepted for r ≤ 1. The next step after an accepted one is h S r^(−α) r_prev^β (S = 0.9,
// α = 0.7/p, β = 0.4/p, p = 8 the order of the error estimate's leading term), between 0.2 h
// and 5 h; after a rejection h S r^(−1/p), at least 0.2 h, and no growth on the step after it.
// The integral part alone (β = 0: GSL's control) lets the step grow until it fails, then
// shrinks it, and repeats; the proportional part damps that cycle, which cost rk8pd a rejected
// attempt for every ~3 accepted steps on the default case.
class StepControl {
 public:
  StepControl(std::size_t dim, double atol, double rtol, const double* scale)
      : dim_(dim), atol_(atol), rtol_(rtol), scale_(scale) {}

  /// Whether the step from y to y1 with error estimate err is accepted; h becomes the next
  /// attempt's length.
  bool adjust(const double* y1, const double* err, double& h) {
    double r = 0.0;
    for (std::size_t i = 0; i < dim_; ++i)
      r = std::max(r, std::abs(err[i]) / (atol_ * scale_[i] + rtol_ * std::abs(y1[i])));
    if (!(r <= 1.0)) {
      h *= std::max(0.2, kSafety * std::pow(r, -1.0 / kOrder));
      rejected_ = true;
      return false;
    }
    r = std::max(r, 1e-10);
    double factor = kSafety * std::pow(r, -0.7 / kOrder) * std::pow(r_prev_, 0.4 / kOrder);
    factor = std::clamp(factor, 0.2, rejected_ ? 1.0 : 5.0);
    h *= factor;
    r_prev_ = r;
    rejected_ = false;
    return true;
  }

 private:
  static constexpr double kSafety = 0.9;
  static constexpr double kOrder = 8.0;
  std::size_t dim_;
  double atol_, rtol_;
  const double* scale_;
  double r_prev_ = 1e-4;
  bool rejected_ = false;
};

}  // namespace bearing::solvers_detail
