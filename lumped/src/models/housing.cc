// The housing carrying the outer ring (housing.h): the bearing model evaluated at the rings'
// relative position, its force on the inner ring plus the ring loads, its reaction on the
// support's DOFs (the resonator's x_h, y_h, or the structure's modal coordinates η_k).
//
// The support, either way: M uncoupled DOFs p_k of mass m_k, stiffness k_k and damping c_k that
// move the seat by S p (S: 2 × M, the seat's x, y motion per unit p_k). The resonator: M = 2,
// m = m_h, k = k_h, c = c_h, S = I. The modes: m = 1, k = ω_k², c = 2 ζ_k ω_k, S = (s_k,x; s_k,y).
// Each DOF is driven by the bearing's reaction −f_b,xy projected on its seat motion, Sᵀ(−f_b,xy).
//
// Jacobian. With f_b(q_r, v_r), q_r = q − P p (P: n × M, S in the ring's x, y rows, 0 below)
// and B = the x, y rows of the bearing's ∂f_b/∂q_r (n columns), B_xy its x, y columns:
//     ring:    ∂f/∂q = ∂f_b/∂q_r,         ∂f/∂p = −(∂f_b/∂q_r) P
//     support: ∂f_p/∂q = −Sᵀ B,           ∂f_p/∂p = Sᵀ B_xy S − diag(k)
// and the same for v with c. With S = I these are the resonator's.

#include "bearing/models/housing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/limits.h"
#include "housed_model.h"

namespace bearing {

double Housing::stiffness() const {
  const double w = two_pi * frequency;
  return mass * w * w;
}

double Housing::damping() const {
  return 2.0 * damping_ratio * mass * two_pi * frequency;
}

double Housing::mode_damping_ratio(int k) const {
  return damping_ratios.empty() ? damping_ratio : damping_ratios.at(static_cast<std::size_t>(k));
}

std::vector<const StructureSensor*> Housing::written_sensors() const {
  std::vector<const StructureSensor*> out;
  if (!modes) return out;
  for (const StructureSensor& s : modes->sensors)
    if (sensors.empty() || std::find(sensors.begin(), sensors.end(), s.name) != sensors.end())
      out.push_back(&s);
  return out;
}

int Housing::support_dofs() const {
  return modes ? modes->count() : 2;
}

void check_housing(const Housing& h) {
  if (!h.modes) {
    limits::housing_mass.check(h.mass);
    limits::housing_frequency.check(h.frequency);
    limits::housing_damping_ratio.check(h.damping_ratio);
    return;
  }
  const StructureModes& m = *h.modes;
  const std::string file = "housing.modes = \"" + h.modes_file + "\"";
  if (m.free)
    throw InputError(file +
                     ": the structure is free-free (no surface held), so it cannot carry the "
                     "bearing: its rigid-body motion is not in the file, and the bearing's load "
                     "would drive it away; compute the modes with [boundary] fixed = [...]");
  limits::housing_damping_ratio.check(h.damping_ratio);
  if (!h.damping_ratios.empty() && h.damping_ratios.size() != static_cast<std::size_t>(m.count()))
    throw InputError("housing.damping_ratio has " + std::to_string(h.damping_ratios.size()) +
                     " entries: give one for all modes, or one per mode (" + file + " has " +
                     std::to_string(m.count()) + ")");
  for (std::size_t k = 0; k < h.damping_ratios.size(); ++k)
    if (!limits::housing_damping_ratio.contains(h.damping_ratios[k]))
      throw InputError("housing.damping_ratio[" + std::to_string(k) +
                       "] = " + format_number(h.damping_ratios[k]) + ": " +
                       limits::housing_damping_ratio.allowed);
  if (m.sensor("seat"))
    throw InputError(file +
                     ": a sensor is named \"seat\", which names the seat's own channels (x_seat, "
                     "y_seat, the outer ring's motion); rename it in the structure file");
  for (const std::string& name : h.sensors)
    if (!m.sensor(name)) {
      std::string known;
      for (const StructureSensor& s : m.sensors) known += (known.empty() ? "" : ", ") + s.name;
      throw InputError("housing.sensors: \"" + name + "\" is not a sensor of " + file +
                       (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
    }
}

namespace detail {

namespace {

Support resonator(const Housing& h) {
  Support s;
  s.dofs = 2;
  s.mass = {h.mass, h.mass};
  s.stiffness = {h.stiffness(), h.stiffness()};
  s.damping = {h.damping(), h.damping()};
  s.sx = {1.0, 0.0};
  s.sy = {0.0, 1.0};
  s.names = {"x_housing", "y_housing"};
  return s;
}

Support structure_modes(const Housing& h) {
  const StructureModes& m = *h.modes;
  Support s;
  s.dofs = m.count();
  // Unit modal masses; k and c in the resonator's association with m = 1 (Housing::stiffness,
  // ::damping), so a modes file of the resonator's two modes gives its bits for a mass of a
  // power of two (test_housing_modes.cc).
  for (int k = 0; k < s.dofs; ++k) {
    const double f = m.frequencies[static_cast<std::size_t>(k)], w = two_pi * f;
    s.mass.push_back(1.0);
    s.stiffness.push_back(w * w);
    s.damping.push_back(2.0 * h.mode_damping_ratio(k) * two_pi * f);
  }
  s.sx = m.seat[0];
  s.sy = m.seat[1];
  // The seat's own motion, the outer ring's (x_seat, y_seat: the orbit relative to it), then the
  // sensors'.
  for (const auto& [name, shape] : {std::pair{"x_seat", &s.sx}, std::pair{"y_seat", &s.sy}}) {
    SensorRow row{name, {}};
    for (int k = 0; k < s.dofs; ++k) row.terms.emplace_back(k, (*shape)[k]);
    s.sensors.push_back(std::move(row));
  }
  static const char* const kAxes[] = {"x", "y", "z"};
  for (const StructureSensor* sensor : h.written_sensors())
    for (int a = 0; a < 3; ++a) {
      SensorRow row{std::string(kAxes[a]) + "_" + sensor->name, {}};
      for (int k = 0; k < s.dofs; ++k)
        row.terms.emplace_back(k, sensor->shape[static_cast<std::size_t>(a)][k]);
      s.sensors.push_back(std::move(row));
    }
  return s;
}

}  // namespace

Support make_support(const Housing& housing, ContactLoop loop) {
  check_housing(housing);
  Support s = housing.modal() ? structure_modes(housing) : resonator(housing);
  s.kernels = support_kernels(loop);
  const std::size_t blocks = (static_cast<std::size_t>(s.dofs) + 7) / 8;
  s.sx.resize(8 * blocks, 0.0);
  s.sy.resize(8 * blocks, 0.0);
  return s;
}

}  // namespace detail

std::vector<HousingMode> housing_modes(const BearingModel& model, int support_dofs) {
  const int n = model.dofs();
  const std::vector<double> q = model.initial_displacement();
  const std::vector<double> v(static_cast<std::size_t>(n), 0.0);
  std::vector<double> dfdq(static_cast<std::size_t>(n * n)), dfdv(dfdq.size()), m(q.size());
  model.force_jacobian(0.0, q.data(), v.data(), dfdq.data(), dfdv.data());
  model.mass(m.data());
  Eigen::MatrixXd K(n, n), M = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    M(i, i) = m[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j)
      K(i, j) = -0.5 * (dfdq[static_cast<std::size_t>(i * n + j)] +
                        dfdq[static_cast<std::size_t>(j * n + i)]);
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  std::vector<HousingMode> modes;
  for (int k = 0; k < n; ++k) {
    const Eigen::VectorXd phi = eig.eigenvectors().col(k);  // φᵀ M φ = 1
    HousingMode mode;
    mode.frequency = std::sqrt(std::max(eig.eigenvalues()(k), 0.0)) / two_pi;
    for (int i = n - support_dofs; i < n; ++i) mode.housing_share += M(i, i) * phi(i) * phi(i);
    modes.push_back(mode);
  }
  return modes;
}

std::unique_ptr<BearingModel> make_housing_model(std::unique_ptr<BearingModel> bearing,
                                                 const RingLoad& load, const Housing& housing,
                                                 std::vector<double> start) {
  return std::make_unique<detail::HousedModel<BearingModel>>(
      std::move(bearing), load, detail::make_support(housing, ContactLoop::simd), std::move(start));
}

}  // namespace bearing
