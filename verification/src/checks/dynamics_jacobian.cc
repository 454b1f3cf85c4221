// The 2-DOF model's force Jacobian (what Newmark's and BDF's Newton iterations and the implicit
// methods' step use) against the closed-form contact stiffness ∇∇U of the ring on its Hertz
// contacts and the viscous damping. The runs cannot see it: a wrong Jacobian only slows Newton
// down, the converged step is set by the force, so code mutants of two_dof.cc's force_jacobian
// survived every run-based check (issue 30).

#include <algorithm>
#include <array>
#include <cmath>

#include "../families.h"
#include "bearing/models/model_registry.h"
#include "bearing/presets.h"
#include "dynamics_closed_forms.h"
#include "dynamics_runs.h"

namespace bearing::verify {

namespace {

using namespace dynamics;
namespace cf = closed_form;

constexpr double kDamping = 200.0;  // [N s/m], the case's
constexpr double kShift = 0.5e-6;   // x off the symmetric state, so that k_xy ≠ 0 [m]

// max over the entries of |J_model − J_closed-form| / k_yy, with J = [∂f/∂q, ∂f/∂v].
Outcome jacobian_2dof(const Context& ctx) {
  const ModelInputs in =
      ctx.perturbed(case_inputs(ctx, {"bearing.preset=6308", "operation.speed=0rpm",
                                      "operation.load=[0, -300]", "rotor.damping=200"}));
  const auto model = make_dynamic_model(ModelKind::two_dof, in);
  const Bearing b = preset("6308");
  const cf::RingContacts ring = cf::ring_contacts(b, cf::ball_constant(b), kBottom);
  // The static state of the perfect bearing under F_y = −300 N, then shifted along x.
  const auto q0 = ring.equilibrium(0.0, -300.0, 0.0, -std::pow(300.0 / ring.K[0], 2.0 / 3.0));
  const double q[2] = {q0[0] + kShift, q0[1]}, v[2] = {0.0, 0.0};
  double dfdq[4], dfdv[4];
  model->force_jacobian(0.0, q, v, dfdq, dfdv);
  std::array<double, 2> f;
  std::array<double, 3> k;
  ring.force(q[0], q[1], f, k);
  const double ref_q[4] = {-k[0], -k[1], -k[1], -k[2]};
  const double ref_v[4] = {-kDamping, 0.0, 0.0, -kDamping};
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    worst = std::max(worst, std::abs(dfdq[i] - ref_q[i]) / k[2]);
    worst = std::max(worst, std::abs(dfdv[i] - ref_v[i]) / kDamping);
  }
  Outcome o{worst, 0.0, "", {}};
  o.detail = fmt(-dfdq[0], 9) + ", " + fmt(-dfdq[1], 9) + ", " + fmt(-dfdq[3], 9) +
             " N/m (k_xx, k_xy, k_yy) vs " + fmt(k[0], 9) + ", " + fmt(k[1], 9) + ", " +
             fmt(k[2], 9) + "; damping " + fmt(-dfdv[0], 6) + " N s/m";
  return o;
}

}  // namespace

std::vector<Check> dynamics_jacobian_checks() {
  Check c;
  c.id = "dynamics.jacobian.2dof.6308";
  c.family = "dynamics";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: max over the entries of the 2-DOF model's force Jacobian [df/dq, df/dv] of "
      "|model - closed form| (df/dq over k_yy, df/dv over c), the 6308 at rest at its static "
      "state under F_y = -300 N shifted 0.5 um along x; reference: 0, the closed form being "
      "-sum 1.5 K delta_j^0.5 e_j e_j^T (closed-form Hertz K) and -c I";
  c.quantity = "Jacobian error";
  c.unit = "-";
  c.tolerance = absolute(1e-9,
                         "the same sums of K delta^0.5 with K equal to the root tolerances "
                         "(1e-12, dynamics.static-limit) and the balls' angles to round-off: "
                         "~1e-12, so 1e-9 is round-off with a margin");
  c.level = Level::quick;
  c.cost = 0.01;
  c.catches = {"contact-constant-x1.03", "contact-exponent+0.05", "damping-x2",
               "pitch-diameter-x1.01"};
  c.measure = jacobian_2dof;
  return {c};
}

}  // namespace bearing::verify
