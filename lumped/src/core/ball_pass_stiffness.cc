// The stiffness over one ball pass (ball_pass_stiffness.h).

#include "bearing/ball_pass_stiffness.h"

#include <complex>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"

namespace bearing {

BallPassStiffness ball_pass_stiffness(const FiveDofBearing& b, const Vector5& load, int samples,
                                      const HeldDofs& held) {
  if (samples < 4)
    throw InputError("ball-pass samples = " + std::to_string(samples) +
                     ": allowed at least 4 (the harmonics need two a period)");
  BallPassStiffness r;
  const double pitch = two_pi / b.balls;
  for (int k = 0; k < samples; ++k) {
    FiveDofBearing at = b;
    at.phase = b.phase + pitch * k / samples;
    r.cage_angles.push_back(at.phase);
    const FiveDofSolution sol = solve_five_dof(at, load, held);
    r.samples.push_back(sol.at.stiffness);
    r.damping_samples.push_back(sol.at.damping);
  }
  for (const Matrix5& C : r.damping_samples) r.damping_mean += C / samples;
  r.min = r.max = r.samples[0];
  for (const Matrix5& K : r.samples) {
    r.mean += K / samples;
    r.min = r.min.cwiseMin(K);
    r.max = r.max.cwiseMax(K);
  }
  // The DFT of each entry's samples, harmonic by harmonic (N is small: 32 by default; at most
  // 4096 from bearing-sim, O(N²)): each factor e^{−2πi m k/N} computed once for the 25 entries.
  for (int m = 1; 2 * m < samples; ++m) {
    Eigen::Matrix<std::complex<double>, 5, 5> sum =
        Eigen::Matrix<std::complex<double>, 5, 5>::Zero();
    for (int k = 0; k < samples; ++k)
      sum += r.samples[k].cast<std::complex<double>>() * std::polar(1.0, -two_pi * m * k / samples);
    r.harmonics.push_back(2.0 / samples * sum.cwiseAbs());
  }
  return r;
}

}  // namespace bearing
