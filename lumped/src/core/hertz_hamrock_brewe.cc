// Hamrock–Brewe closed-form approximations of the Hertz point-contact solution:
//   B. J. Hamrock and D. E. Brewe, "Simplified solution for stresses and deformations",
//   J. Lubr. Technol. 105 (1983) 171–177.
// They are curve fits in the radius ratio R_y/R_x (1 ≤ R_y/R_x ≤ 100 in the paper); with
// R_x, R_y the effective radii in the rolling and transverse directions,
// R_y/R_x = (1 + F(ρ)) / (1 − F(ρ)). Note they do not reduce to κ = 1 at F = 0 (κ = 1.0339).

#include <cmath>
#include <memory>
#include <string_view>

#include "bearing/hertz.h"
#include "hertz_internal.h"

namespace bearing {

namespace {

class HamrockBreweHertz final : public HertzSolution {
 public:
  HertzShape shape(double f_rho) const override {
    detail::require_curvature_difference(f_rho, name());
    const double ratio = (1.0 + f_rho) / (1.0 - f_rho);  // R_y / R_x ≥ 1
    const double kappa = 1.0339 * std::pow(ratio, 0.6360);
    const double E = 1.0003 + 0.5968 / ratio;
    const double K = 1.5277 + 0.6023 * std::log(ratio);
    return hertz_shape_from(kappa, K, E);
  }
  HertzMethod method() const override { return HertzMethod::hamrock_brewe; }
};

}  // namespace

std::unique_ptr<HertzSolution> make_hamrock_brewe_hertz() {
  return std::make_unique<HamrockBreweHertz>();
}

}  // namespace bearing
