#pragma once
// What the outputs read from a model at an output instant: the names of the ring's DOFs, the
// cage speed the model runs at, and each ball's state. The dynamic models (BearingModel) and the
// quasi-static model provide it alike, so one recorder serves every model kind (response.h).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace bearing {

/// One per-ball quantity a model can report; output flags select them (response.h).
enum class BallField : unsigned {
  load = 1u << 0,             ///< Q_j, the (inner-race) contact load [N]
  approach = 1u << 1,         ///< δ_j, signed approach [m]
  radial = 1u << 2,           ///< r_j, the ball centre's radial displacement [m]
  radial_velocity = 1u << 3,  ///< dr_j/dt [m/s]
  spin = 1u << 4,             ///< ω_b,j relative to the cage [rad/s] (ball DOFs only)
  outer_load = 1u << 5,       ///< Q_o,j [N] (ball DOFs only)
  friction_inner = 1u << 6,   ///< tangential force on the ball at the inner contact [N]
  friction_outer = 1u << 7,   ///< and at the outer contact [N]
  film_inner = 1u << 8,       ///< h_c at the inner contact [m] (lubricated only)
  film_outer = 1u << 9,       ///< h_c at the outer contact [m] (lubricated only)
};

/// A set of BallField bits.
using BallFields = unsigned;
constexpr BallFields operator|(BallField a, BallField b) {
  return static_cast<unsigned>(a) | static_cast<unsigned>(b);
}
constexpr BallFields operator|(BallFields a, BallField b) {
  return a | static_cast<unsigned>(b);
}
constexpr bool has(BallFields set, BallField f) {
  return (set & static_cast<unsigned>(f)) != 0;
}

/// Every ball's state at one instant, a field per array (Z entries each; unused fields are left
/// as they were).
struct BallState {
  explicit BallState(int balls)
      : values(10, std::vector<double>(static_cast<std::size_t>(balls))) {}
  std::vector<double>& operator[](BallField f) { return values[index(f)]; }
  const std::vector<double>& operator[](BallField f) const { return values[index(f)]; }

 private:
  static std::size_t index(BallField f) {
    std::size_t i = 0;
    for (unsigned bits = static_cast<unsigned>(f); bits > 1; bits >>= 1) ++i;
    return i;
  }
  std::vector<std::vector<double>> values;
};

/// A linear output of the state beyond the named DOFs: Σ weight × state[dof] over its terms (a
/// sensor's displacement on a modal housing, housing.h). Its velocity and acceleration are the
/// same sums of the velocities and accelerations.
struct SensorRow {
  std::string name;                           ///< channel stem, e.g. "y_top" (then vy_top, ay_top)
  std::vector<std::pair<int, double>> terms;  ///< (DOF index, weight [output unit per DOF unit])
};

class ModelOutputs {
 public:
  virtual ~ModelOutputs() = default;

  /// Names of the ring's DOFs, the first dof_names().size() entries of q: {"x", "y"} or
  /// {"x", "y", "z"}, followed by "x_housing", "y_housing" with the housing (housing.h); the
  /// output channel stems.
  virtual std::vector<std::string> dof_names() const = 0;

  /// The linear outputs beyond the named DOFs, written after them (response.h): none but on a
  /// modal housing.
  virtual std::vector<SensorRow> sensor_rows() const { return {}; }

  /// Number of balls Z.
  virtual int balls() const = 0;

  /// The cage speed the model's balls turn at, ω_ca [rad/s] (pure rolling at the model's contact
  /// angle, times 1 − s_c with cage slip).
  virtual double cage_speed() const = 0;

  /// Whether the cage slips randomly (random_slip.h): its angle is then ω_ca t + φ(t).
  virtual bool has_cage_slip() const { return false; }
  /// φ(t), the random slip's error of the cage angle [rad] (0 without).
  virtual double cage_slip_angle(double /*t*/) const { return 0.0; }

  /// Whether the model has ball DOFs, and so the spin, outer-load and friction fields.
  virtual bool has_ball_dofs() const { return false; }

  /// Fills the `fields` of `state` at the output instant (t, q, v) [SI]. Not for the hot loop.
  virtual void ball_state(double t, const double* q, const double* v, BallFields fields,
                          BallState& state) const = 0;
};

}  // namespace bearing
