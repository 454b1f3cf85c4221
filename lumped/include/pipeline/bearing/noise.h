#pragma once
// The bearing's sound at its microphones (docs/model.md §8, seed 000): the inner ring as an
// infinite cylinder translating with the ring centre's velocity (vx, vy), each ball as a sphere
// driven by its centre's radial velocity vr_j, their pressures filtered in the time domain
// (acoustics/pressure.h) and summed per microphone.
//
// What moves and what does not:
// - The ring source sits at the ring centre's mean position over the analysis window (the centre
//   moves by micrometres against millimetres to a microphone); its velocity is the run's (vx, vy)
//   (a 3-DOF run's axial vz does not drive a transverse cylinder and is not used).
// - Ball j's centre is at (d_m/2 + r_j(t)) e(θ_j), θ_j = 2πj/Z + ω_c t (the run's cage speed:
//   pure rolling at the loaded contact angle), and it is driven by vr_j along e(θ_j) — the ball's
//   vibration. The rigid orbit of the ball set at constant ω_c is not a source: a ball turning
//   steadily with the cage radiates only at the cage frequency and its harmonics (a few hertz,
//   inaudible), and its hydrodynamic near field is not sound.
// - The record is the analysis window [transient, duration) of the run, taken as periodic; the
//   band is 1/(duration − transient) … 0.8 · output_rate/2 (acoustics/pressure.h says why).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/bearing.h"
#include "bearing/kinematics.h"
#include "bearing/response.h"

namespace bearing {

/// Levels at one microphone.
struct MicrophoneLevels {
  Microphone microphone;                               ///< as given: r [m], angle [rad]
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< (x, y) [m]
  double p_rms = 0;                                    ///< RMS of the summed pressure [Pa]
  double p_rms_ring = 0;   ///< the ring's alone [Pa] (0 if ring_source = "none")
  double p_rms_balls = 0;  ///< the balls' together, under the summation [Pa] (0 if "none")
  /// 20 log10(p_rms / 20 µPa) [dB re 20 µPa]; empty where that source is "none" or silent
  /// (p_rms = 0, a level of −∞).
  std::optional<double> spl_total, spl_ring, spl_balls;
  /// Smallest gap between the microphone and a ball's surface during the window [m] (ball
  /// sources only).
  std::optional<double> nearest_ball_surface;
};

struct BearingNoise {
  std::vector<double> time;                   ///< the analysis window's sample times [s]
  std::vector<std::vector<double>> pressure;  ///< per microphone, the sum under `summation` [Pa]
  std::vector<MicrophoneLevels> microphones;
  double band_low = 0, band_high = 0;                     ///< resolved band [Hz]
  Eigen::Vector2d ring_centre = Eigen::Vector2d::Zero();  ///< the ring source's position [m]
};

/// The sound of a run at every microphone of `acoustics` (which must be enabled). `response`
/// must hold vx, vy and, with a ball source, r1…rZ, vr1…vrZ; the balls turn at
/// kinematics.cage_speed, the run's. Throws InputError if a microphone lies inside the ring or
/// inside a ball at some instant (naming acoustics.microphones[i]).
BearingNoise radiate(const Response& response, const AcousticsOptions& acoustics,
                     const Bearing& bearing, const RunKinematics& kinematics);

}  // namespace bearing
