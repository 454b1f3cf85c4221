#pragma once
// Private to the lumped models (not installed): one race's contact constant under TVDS,
// K^{−2/3} = K₀^{−2/3} · g(Δ) with Δ from the waviness at the contact.
//
// TVDS (seed 002, docs/model.md §3): the waviness also changes the raceway curvature in the rolling
// direction. For a race of radius R whose surface sits at R + ε(φ) from the race centre, the
// curvature of the polar curve r(φ) = R + ε is
//     κ = (r² + 2r'² − r r'') / (r² + r'²)^{3/2} = 1/R − (ε + ε'')/R² + O(ε²),
// (first order: numerator R² + 2Rε − Rε'', denominator R³(1 + 3ε/R)). With Harris's signs
// (convex positive) and Π positive toward the ball:
//   - inner race (convex, the ball outside it): ε = +Π_i, ρ_II1 = +κ = 1/R_i − (Π_i + Π_i'')/R_i²;
//   - outer race (concave, the ball inside it): ε = −Π_o, ρ_II1 = −κ = −1/R_o − (Π_o + Π_o'')/R_o².
// So on both races Δρ_II1 = −(Π + Π'')/R², which for Π = A sin(Nφ) is +A(N²−1) sin(Nφ)/R²: a
// crest makes the inner race more convex and the outer race less concave (N = 1, a shifted
// circle, changes nothing). R = d_i/2, d_o/2 (exact for α = 0; for α ≠ 0 the same first-order
// change is added to Harris's ρ_II1). What this Δ does to K: curvature_compliance_table.h.

#include <cmath>

#include "bearing/contact.h"
#include "bearing/excitation.h"
#include "bearing/hertz.h"
#include "bearing/models/model_inputs.h"
#include "curvature_compliance_table.h"

namespace bearing::detail {

/// Per-race TVDS constants: K^{−2/3} = k0 · g(Δ), Δ = −(Π + Π'')/R².
struct RaceStiffness {
  bool varies = false;
  double k0 = 0;            ///< K₀^{−2/3}
  double minus_inv_r2 = 0;  ///< −1/R² [1/m²]
  CurvatureComplianceTable table;

  double compliance(double pi_plus_pi2) const { return k0 * table(pi_plus_pi2 * minus_inv_r2); }
  /// d(K^{−2/3})/dt for d(Π + Π'')/dt = `rate`.
  double compliance_rate(double pi_plus_pi2, double rate) const {
    return k0 * table.derivative(pi_plus_pi2 * minus_inv_r2) * rate * minus_inv_r2;
  }
};

/// The TVDS constants of one race with waviness `w`: K₀^{−2/3} alone (constant) without waviness,
/// else also the table of g(Δ) over the curvature change the waviness can reach.
inline RaceStiffness race_stiffness(const ModelInputs& in, Race race, const Waviness& w,
                                    const HertzSolution& method) {
  RaceStiffness rs;
  const RaceContact& rc = race == Race::inner ? in.contact.inner : in.contact.outer;
  rs.k0 = std::pow(rc.K, -2.0 / 3.0);
  if (w.empty()) return rs;
  const Curvatures cv = race_curvatures(in.bearing, race);
  const double R = 0.5 * (race == Race::inner ? in.bearing.inner_raceway_diameter()
                                              : in.bearing.outer_raceway_diameter());
  rs.minus_inv_r2 = -1.0 / (R * R);
  // |Π + Π''| ≤ Σ_s A_s |N_s² − 1| bounds the curvature change.
  double bound = 0;
  for (const WavinessHarmonic& h : w.harmonics)
    bound += h.amplitude * std::abs(double(h.order) * h.order - 1.0);
  bound /= R * R;
  const double num0 = (cv.ball_1 - cv.ball_2) + (cv.race_1 - cv.race_2);
  rs.table = CurvatureComplianceTable(method, num0, cv.sum(), bound,
                                      race == Race::inner ? "waviness.inner" : "waviness.outer");
  rs.varies = true;
  return rs;
}

}  // namespace bearing::detail
