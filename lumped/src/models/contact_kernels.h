#pragma once
// Private to the lumped models (not installed): the per-ball work of a force evaluation that is
// the same for every ball, as kernels over the ball arrays of a frame (ball_set.h). Two
// implementations give the same bits: `simd` (Highway, the instruction set chosen once at run
// time, so a binary built for any x86-64 uses AVX-512 or AVX2 where the CPU has them) and
// `scalar` (one ball at a time, kept for checking). Same bits because each ball's arithmetic is
// the same sequence of IEEE operations in both (no fused multiply–add: the kernels' file is built
// with -ffp-contract=off), and the ring force is summed in one order fixed by the kernel, never
// by a lane-width-dependent reduction (the radial contacts: the loaded balls in ball order; the
// planar balls: four lane sums, then the lanes, the scalar loop mirroring the lanes); so a run is
// also bit-reproducible across CPUs.

#include <string>
#include <vector>

#include "bearing/contact_loop.h"

namespace bearing::detail {

/// Every array a kernel reads or writes must have room for the balls rounded up to a multiple of
/// kKernelPad (the widest vector: 8 doubles); what lies past the last ball is never used.
inline constexpr int kKernelPad = 8;

/// (cos θ_j, sin θ_j) = (b_c cos φ − b_s sin φ, b_s cos φ + b_c sin φ) for j < Z: the base angles
/// (b_c, b_s) rotated by one angle φ given as (cos φ, sin φ).
using RotateBalls = void (*)(const double* base_cos, const double* base_sin, double cos_phi,
                             double sin_phi, int Z, double* cos_theta, double* sin_theta);

/// Radial Hertz contacts on the ring at (x, y) [m]: δ_j = x c_j + y s_j − γ + e_j [m] and, for
/// δ_j > 0, Q_j = K_j δ_j^{3/2} [N] (K_j [N/m^1.5]); subtracts Q_j c_j from *fx and Q_j s_j from
/// *fy [N], in ball order.
using RadialContacts = void (*)(const double* cos_theta, const double* sin_theta,
                                const double* excitation, const double* stiffness, int Z, double x,
                                double y, double gap, double* fx, double* fy);

/// The planar ball-DOF model's balls (ball_dofs.h, both exponents 3/2, no axial load): each ball
/// j with its DOF s_j between the races. Frame arrays as above (kKernelPad room); the ball arrays
/// (s_j, ṡ_j, ω_b,j, and the outputs) need room for Z only.
struct PlanarBalls {
  const double* cos_theta;
  const double* sin_theta;
  const double* inner_excitation;           ///< e_i,j [m]
  const double* outer_excitation;           ///< e_o,j [m]
  const double* inner_stiffness;            ///< K_i,j [N/m^1.5]
  const double* outer_stiffness;            ///< K_o,j [N/m^1.5]
  const double* position;                   ///< s_j [m]
  const double* speed;                      ///< ṡ_j [m/s]
  const double* spin;                       ///< ω_b,j [rad/s]
  int balls = 0;                            ///< Z
  double vx = 0, vy = 0;                    ///< ring velocity [m/s]
  double gap = 0;                           ///< γ [m]
  double centrifugal = 0;                   ///< F_c along the DOF [N]
  double ball_damping = 0;                  ///< c_b [N s/m]
  double lever = 0;                         ///< L_s [m]
  double drive_inner = 0, drive_outer = 0;  ///< A_i, A_o [m/s]
  double traction_gain = 0;                 ///< μ_m/Δv_m [s/m]; with friction
  double traction_cap = 0;                  ///< μ_m [-]
  bool friction = false;
  double fx = 0, fy = 0;  ///< the ring force without the balls [N]
};

/// For each ball: δ_o = s_j + e_o,j, δ_i = x c_j + y s_j − s_j − γ + e_i,j, Q = K [δ]_+^{3/2};
/// radial[j] = Q_i − Q_o + F_c − c_b ṡ_j [N]; with friction μ = clamp(μ_m/Δv_m Δv, ±μ_m) at
/// Δv_i = A_i − L_s ω_b + (v_y c − v_x s) and Δv_o = A_o − L_s ω_b, torque[j] = L_s (μ_i Q_i +
/// μ_o Q_o) [N m] (0 without). ring[0], ring[1]: (in.fx, in.fy) minus Σ Q_i (c_j, s_j) plus
/// Σ μ_i Q_i (s_j, −c_j), summed in lanes of kPlanarLanes (contact_kernels.cc) and written as one
/// pair, so that a caller's vector load of both forwards from the store.
/// The ring's position (x, y) [m] comes as arguments, in registers: it is the last input known
/// (the end of the previous stage's ring sums), and a trip through memory would lengthen the
/// chain.
using PlanarBallForces = void (*)(const PlanarBalls& in, double x, double y, double* ring,
                                  double* radial, double* torque);

/// (cos θ_i, sin θ_i) of n angles θ_i [rad], each with phasor()'s bits (phasor.h: the same
/// operations lane by lane, the table entry gathered). Arrays with room for n rounded up to a
/// multiple of kKernelPad; what lies past n is computed from whatever is there and not used.
using Phasors = void (*)(const double* theta, int n, double* cos_theta, double* sin_theta);

struct ContactKernels {
  RotateBalls rotate;
  RadialContacts radial;
  PlanarBallForces planar_balls;
  Phasors phasors;
};

/// The kernels of `loop` for Z = `balls` (simd: the best instruction set of this CPU, found on the
/// first call).
ContactKernels contact_kernels(ContactLoop loop, int balls);

/// The planar balls' vectors hold at most this many balls (fewer balls: the scalar loop).
inline constexpr int kPlanarLanes = 4;

/// The kernels of every instruction set this build holds that this CPU can run, named ("AVX3",
/// "AVX2", "SSE4", "EMU128", ...), for tests that check each against the scalar loop. Switches
/// Highway's dispatch while it runs: not to be called while other threads run models.
struct NamedKernels {
  std::string target;
  ContactKernels kernels;
};
std::vector<NamedKernels> kernels_per_target();

/// Z rounded up to a multiple of kKernelPad.
constexpr int padded_balls(int Z) {
  return (Z + kKernelPad - 1) / kKernelPad * kKernelPad;
}

}  // namespace bearing::detail
