// The default Jacobian of a MechanicalSystem: central differences of force(); and the default
// force_with(), which keeps nothing.
//
// Column j of ∂f/∂q is (f(q + h_j e_j) − f(q − h_j e_j)) / (2 h_j), and likewise for ∂f/∂v. The
// central difference has truncation error ~h²|f'''|/6 and rounding error ~ε|f|/h, balanced by
// h ~ ε^{1/3} times the length over which f varies. The step is scaled per component,
//     h_j = ε^{1/3} max(|q_j|, 1 µm)        for displacements,
//     h_j = ε^{1/3} max(|v_j|, 1 mm/s)      for velocities,
// (ε^{1/3} ≈ 6e-6): relative to the component itself where it is large, and to a floor where it
// is near zero. 1 µm is the scale of a Hertz approach and of a bearing clearance, the length over
// which contact forces change; 1 mm/s is the velocity of a 1 µm vibration at a few hundred Hz. So
// h ≈ 6 pm at rest: far inside the smooth range of a loaded contact, yet large enough that a
// force of any magnitude keeps ~10 significant digits in the difference. Each step is rounded to
// a representable increment ((x + h) − x) so the divisor is the step actually taken.
//
// Costs 4n force evaluations. Work arrays for up to kStackDofs DOFs live on the stack, so the
// default allocates nothing for the lumped models; larger systems use one heap block per call.

#include "bearing/solvers/mechanical_system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace bearing {

namespace {

constexpr double kDisplacementScale = 1e-6;  // [m]
constexpr double kVelocityScale = 1e-3;      // [m/s]
constexpr int kStackDofs = 16;

// One block of partial derivatives: d/dx_j of f for x = q (dfdx = dfdq) or x = v.
template <typename Force>
void central_differences(int n, double* x, double scale, double* fp, double* fm, double* dfdx,
                         const Force& force) {
  const double root = std::cbrt(std::numeric_limits<double>::epsilon());
  for (int j = 0; j < n; ++j) {
    const double xj = x[j];
    const double step = root * std::max(std::abs(xj), scale);
    const double up = xj + step;
    const double down = xj - step;
    x[j] = up;
    force(fp);
    x[j] = down;
    force(fm);
    x[j] = xj;
    const double inv = 1.0 / (up - down);
    for (int i = 0; i < n; ++i) dfdx[i * n + j] = (fp[i] - fm[i]) * inv;
  }
}

}  // namespace

// Out of line: visible in the integrators, the default would invite a speculative
// devirtualisation of every force_with() call (a compare and branch per call on the hot path).
std::unique_ptr<MechanicalSystem::Workspace> MechanicalSystem::make_workspace() const {
  return nullptr;
}

void MechanicalSystem::force_with(Workspace* /*workspace*/, double t, const double* q,
                                  const double* v, double* f) const {
  force(t, q, v, f);
}

void MechanicalSystem::force_jacobian(double t, const double* q, const double* v, double* dfdq,
                                      double* dfdv) const {
  const int n = dofs();
  double stack[4 * kStackDofs];
  std::vector<double> heap;
  double* work = stack;
  if (n > kStackDofs) {
    heap.resize(4 * static_cast<std::size_t>(n));
    work = heap.data();
  }
  double* qw = work;
  double* vw = work + n;
  double* fp = work + 2 * n;
  double* fm = work + 3 * n;
  std::copy(q, q + n, qw);
  std::copy(v, v + n, vw);
  const auto f = [&](double* out) { force(t, qw, vw, out); };
  central_differences(n, qw, kDisplacementScale, fp, fm, dfdq, f);
  central_differences(n, vw, kVelocityScale, fp, fm, dfdv, f);
}

}  // namespace bearing
