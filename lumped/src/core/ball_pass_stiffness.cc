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
    r.samples.push_back(solve_five_dof(at, load, held).at.stiffness);
  }
  r.min = r.max = r.samples[0];
  for (const Matrix5& K : r.samples) {
    r.mean += K / samples;
    r.min = r.min.cwiseMin(K);
    r.max = r.max.cwiseMax(K);
  }
  // The DFT of each entry's samples, harmonic by harmonic (N is small: 32 by default).
  for (int m = 1; 2 * m < samples; ++m) {
    Matrix5 amplitude;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        std::complex<double> sum = 0;
        for (int k = 0; k < samples; ++k)
          sum += r.samples[k](i, j) * std::polar(1.0, -two_pi * m * k / samples);
        amplitude(i, j) = 2.0 / samples * std::abs(sum);
      }
    r.harmonics.push_back(amplitude);
  }
  return r;
}

}  // namespace bearing
