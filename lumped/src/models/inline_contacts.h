#pragma once
// Private to the lumped models (not installed): the scalar twins of two contact kernels
// (contact_kernels.h) as inline functions, for the kinds' own RK4 (static_rk4.h), which compiles
// them into its loop: no call through a kernel pointer per evaluation, and the branch per ball
// does only the loaded balls' work. Why that is faster there: RK4's stages are one chain of
// dependent operations, so what counts is its latency, not the lanes (issue 42, bench/README.md).
// contact_kernels.cc's scalar kernels are these functions, so both give the same bits as the
// SIMD kernels (the same IEEE operations per ball, summed in ball order, no fused multiply–add:
// the baseline x86-64 has none).

#include <cmath>

namespace bearing::detail {

/// RotateBalls (contact_kernels.h), one ball at a time.
[[gnu::always_inline]] inline void rotate_balls_inline(const double* base_cos,
                                                       const double* base_sin, double cos_phi,
                                                       double sin_phi, int Z, double* cos_theta,
                                                       double* sin_theta) {
  for (int j = 0; j < Z; ++j) {
    cos_theta[j] = base_cos[j] * cos_phi - base_sin[j] * sin_phi;
    sin_theta[j] = base_sin[j] * cos_phi + base_cos[j] * sin_phi;
  }
}

/// RadialContacts (contact_kernels.h), one ball at a time.
[[gnu::always_inline]] inline void radial_contacts_inline(
    const double* cos_theta, const double* sin_theta, const double* excitation,
    const double* stiffness, int Z, double x, double y, double gap, double* fx, double* fy) {
  double sx = *fx, sy = *fy;
  for (int j = 0; j < Z; ++j) {
    const double c = cos_theta[j], s = sin_theta[j];
    const double delta = x * c + y * s - gap + excitation[j];
    if (delta <= 0) continue;
    const double q = stiffness[j] * delta * std::sqrt(delta);
    sx -= q * c;
    sy -= q * s;
  }
  *fx = sx;
  *fy = sy;
}

}  // namespace bearing::detail
