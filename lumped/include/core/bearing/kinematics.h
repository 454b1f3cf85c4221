#pragma once
// Bearing defect frequencies from rolling kinematics (docs/model.md §2), outer ring fixed by
// default.

#include "bearing/bearing.h"

namespace bearing {

struct BearingFrequencies {
  double shaft = 0;  ///< inner-ring rotation frequency f_i (relative to the outer ring) [Hz]
  double ftf = 0;    ///< fundamental train (cage) frequency [Hz]
  double bpfo = 0;   ///< ball-pass frequency, outer race [Hz]
  double bpfi = 0;   ///< ball-pass frequency, inner race [Hz]
  double bsf = 0;    ///< ball spin frequency (relative to the cage) [Hz]
};

/// The kinematics a run turns at: its bearing frequencies, and the cage speed and contact angle of
/// its model (with cage slip and under an axial load, not the free pure-rolling ones).
struct RunKinematics {
  BearingFrequencies frequencies;  ///< [Hz]
  double cage_speed = 0;           ///< ω_ca, as the model's balls turn [rad/s]
  double contact_angle = 0;        ///< [rad]
};

/// Cage angular speed for pure rolling [rad/s]:
/// ω_c = ½ ω_i (1 − D cos α / d_m) + ½ ω_o (1 + D cos α / d_m).
double cage_speed(const Bearing& b, double inner_speed, double outer_speed = 0.0);

/// Frequencies for inner-ring speed `inner_speed` and outer-ring speed `outer_speed` [rad/s] and
/// cage slip s_c ∈ [0, 1) (seed 004: ω_ca = (1 − s_c) ω_c). With slip, every cage-driven
/// frequency uses ω_ca; BSF assumes the ball rolls on the outer race relative to the cage.
BearingFrequencies bearing_frequencies(const Bearing& b, double inner_speed,
                                       double outer_speed = 0.0, double cage_slip = 0.0);

}  // namespace bearing
