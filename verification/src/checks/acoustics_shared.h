#pragma once
// Small helpers shared by the acoustics check files (acoustics*.cc).

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>

#include "acoustics_reference.h"
#include "bearing/presets.h"

namespace bearing::verify {

/// Seed 000's 608 (the true preset, not through the Context): the inner ring as a cylinder of
/// the inner raceway's radius (d_m − D)/2 = 5.79 mm, the ball of radius D/2 = 1.98 mm.
inline double seed000_ring_radius() {
  const Bearing b = preset("608");
  return 0.5 * (b.pitch_diameter - b.ball_diameter);
}
inline double seed000_ball_radius() {
  return 0.5 * preset("608").ball_diameter;
}

/// The angular frequency [rad/s] at which a body of radius a has the given ka in the true air.
inline double omega_of(double ka, double radius) {
  return ka * acoustic_reference::kSoundSpeed / radius;
}

/// SPL [dB re 20 µPa] of a tone whose pressure amplitude is |p| [Pa].
inline double tone_level(std::complex<double> p) {
  return 20.0 * std::log10(std::abs(p) / std::sqrt(2.0) / 20e-6);
}

/// A number in a detail line: 4 significant digits.
inline std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace bearing::verify
