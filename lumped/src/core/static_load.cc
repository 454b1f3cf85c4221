// Static load distribution of a radial ball bearing with clearance (docs/model.md §1 and §4).
//
// The equilibrium Σ_j K [δ_j]_+^n e_j = F, δ_j = u·e_j − γ, e_j = (cos θ_j, sin θ_j), is the
// stationarity condition of the convex potential
//     Φ(u) = Σ_j K/(n+1) [δ_j(u)]_+^{n+1} − F·u,
// which is coercive for Z ≥ 3 evenly spaced balls (in every direction some ball closes). So the
// equilibrium exists, and minimising Φ by a descent method converges from anywhere. Plain Newton
// from u = 0 does not: with clearance no ball is loaded there and the Jacobian is zero.
//
// The solver works in the dimensionless variables
//     u = u_ref + L v,  L = (|F|/K)^{1/n},  so that  Σ_j [β̃_j + v·e_j]_+^n e_j = F/|F|,
// in a frame whose x axis points at the ball nearest to F (ball angles in it are exact
// multiples of 2π/Z). u_ref is the rigid-body contact point of the zero-load limit: the point of
// the clearance polygon {u·e_j ≤ γ} furthest along F, a vertex where two balls touch, or the
// middle of an edge when F points at a ball; β̃_j = (u_ref·e_j − γ)/L ≤ 0 is known in closed
// form, exactly 0 for the touching balls. This keeps the approaches accurate for loads so small
// that δ_j ≪ γ (forming u·e_j − γ from u would cancel almost all digits) and makes the
// iteration independent of the scale of F, K and γ. The steps are
//   1. a safeguarded scalar solve (bracket, then Newton–bisection) along F/|F| from v = 0;
//   2. Newton on the 2-D gradient g = ∇Φ̃ with a Levenberg term μ = |g|² for a nearly singular
//      Hessian H, and a line search that minimises Φ̃ along the step (convex on the ray). When
//      H is singular (one ball loaded), the flat direction is searched separately.
// The relative force residual |Σ Q_j e_j − F| / |F| is |g|.

#include "bearing/static_load.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/numerics/newton.h"
#include "bearing/numerics/roots.h"
#include "bearing/units.h"

namespace bearing {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

void validate(int balls, double K, double gap, const Eigen::Vector2d& load,
              const StaticLoadOptions& o) {
  const std::string where = "solve_static_load: ";
  if (balls < 3)
    throw InputError(where + "number of balls " + std::to_string(balls) + " must be at least 3");
  if (!(std::isfinite(K) && K > 0))
    throw InputError(where + "load-deflection constant K = " + format_number(K) +
                     " N/m^n must be positive and finite");
  if (!(std::isfinite(gap) && gap >= 0))
    throw InputError(where + "ball gap = " + format_number(gap) + " m must be finite and >= 0");
  if (!load.allFinite())
    throw InputError(where + "load (" + format_number(load.x()) + ", " + format_number(load.y()) +
                     ") N must be finite");
  if (!std::isfinite(o.phase))
    throw InputError(where + "phase = " + format_number(o.phase) + " rad must be finite");
  if (!(std::isfinite(o.exponent) && o.exponent >= 1.0))
    throw InputError(where + "load-deflection exponent n = " + format_number(o.exponent) +
                     " must be finite and >= 1");
  if (!(o.tolerance > 0 && o.tolerance < 1))
    throw InputError(where + "tolerance = " + format_number(o.tolerance) + " must lie in (0, 1)");
  if (o.max_iterations < 1)
    throw InputError(where + "max_iterations = " + std::to_string(o.max_iterations) +
                     " must be at least 1");
}

// The dimensionless problem: balls e_j, offsets β̃_j ≤ 0, exponent n, unit load direction w.
class Problem {
 public:
  Problem(std::vector<double> c, std::vector<double> s, std::vector<double> beta, double n,
          Eigen::Vector2d w)
      : c_(std::move(c)), s_(std::move(s)), beta_(std::move(beta)), n_(n), w_(w) {}

  // Φ̃(v), ∇Φ̃ = Σ p^n e − w, ∇²Φ̃ = Σ n p^{n−1} e eᵀ, and Σ p^n (the scale of the rounding in g).
  struct Eval : numerics::PotentialPoint<2> {
    double load_sum = 0;
  };

  Eval eval(const Eigen::Vector2d& v) const {
    Eval r;
    r.gradient = -w_;
    double energy = 0;
    for (std::size_t j = 0; j < c_.size(); ++j) {
      const double p = beta_[j] + v.x() * c_[j] + v.y() * s_[j];
      if (p <= 0) continue;
      const double pn1 = std::pow(p, n_ - 1.0);
      const double pn = pn1 * p;
      energy += pn * p;
      r.load_sum += pn;
      r.gradient.x() += pn * c_[j];
      r.gradient.y() += pn * s_[j];
      const double h = n_ * pn1;
      r.hessian(0, 0) += h * c_[j] * c_[j];
      r.hessian(0, 1) += h * c_[j] * s_[j];
      r.hessian(1, 1) += h * s_[j] * s_[j];
    }
    r.hessian(1, 0) = r.hessian(0, 1);
    r.value = energy / (n_ + 1.0) - w_.dot(v);
    return r;
  }

  // Along the load direction, v = t w: h(t) = w·∇Φ̃ = Σ p^n (w·e) − 1 and h'(t).
  void along(double t, double& h, double& dh) const {
    h = -1.0;
    dh = 0.0;
    for (std::size_t j = 0; j < c_.size(); ++j) {
      const double we = w_.x() * c_[j] + w_.y() * s_[j];
      const double p = beta_[j] + t * we;
      if (p <= 0) continue;
      const double pn1 = std::pow(p, n_ - 1.0);
      h += pn1 * p * we;
      dh += n_ * pn1 * we * we;
    }
  }

 private:
  std::vector<double> c_, s_, beta_;
  double n_;
  Eigen::Vector2d w_;
};

// Step 1: t > 0 with h(t) = 0. h(0) = −1 (all β̃ ≤ 0) and h is nondecreasing and unbounded, so a
// bracket exists; Newton steps are taken when they stay inside it, bisection otherwise.
double solve_along_load(const Problem& prob) {
  double h = 0, dh = 0;
  const auto beyond = [&](double t) {
    prob.along(t, h, dh);
    return h < 0;
  };
  const numerics::Bracket b = numerics::grow_bracket(0.0, 1.0, beyond, 2100);
  if (!(h >= 0)) return b.lo;  // cannot happen for Z ≥ 3; the 2-D iteration still converges
  return numerics::newton_bisection([&](double t, double& f, double& df) { prob.along(t, f, df); },
                                    b.lo, b.hi, 200);
}

// Step 2 by numerics::newton_minimize. Its line search minimises Φ̃ along the step, convex on
// the ray, to |φ'(α)| ≤ 0.1 |φ'(0)|: α = 1 first (the Newton step, accepted near the solution),
// then doubling while φ' < 0 or Illinois regula falsi on φ' inside the bracket (kept 1 % of it
// from either end), and the bracket's lower end if it collapses to rounding; Φ̃ must not rise
// above its rounding. The Levenberg term μ = |g|² + 1e-12 tr H keeps a nearly singular H (nearly
// parallel balls for large Z) invertible and vanishes like |g|², so the local rate stays
// quadratic; a singular H (one ball loaded, or none) is stepped one eigen-direction at a time.
numerics::NewtonOptions newton_options(const StaticLoadOptions& o) {
  numerics::NewtonOptions n;
  n.tolerance = o.tolerance;
  n.max_iterations = o.max_iterations;
  n.gradient_damping = 1;
  n.split_singular = true;
  n.line_search.max_expansions = 1100;
  n.line_search.zoom.max_iterations = 200;
  n.line_search.zoom.margin = 0.01;
  n.line_search.fallback_to_lower_end = true;
  return n;
}

}  // namespace

StaticLoadResult solve_static_load(int balls, double K, double gap, const Eigen::Vector2d& load,
                                   const StaticLoadOptions& options) {
  validate(balls, K, gap, load, options);
  const int Z = balls;
  const double n = options.exponent;
  const double pitch = two_pi / Z;

  StaticLoadResult res;
  res.ball_angles.resize(Z);
  for (int j = 0; j < Z; ++j) res.ball_angles[j] = options.phase + pitch * j;

  const double F = std::hypot(load.x(), load.y());
  if (F == 0) {
    res.ball_approach.assign(Z, -gap);
    res.ball_loads.assign(Z, 0.0);
    return res;
  }

  // Length scale, formed in logarithms so that F/K cannot underflow.
  const double L = std::exp((std::log(F) - std::log(K)) / n);
  if (!(L > 0 && std::isfinite(L) && std::isfinite(gap / L)))
    throw SolverError("solve_static_load: load " + format_number(F) +
                      " N and K = " + format_number(K) +
                      " N/m^n give a deflection scale (F/K)^(1/n) = " + format_number(L) +
                      " m that double precision cannot represent");

  // Local frame: x' along the ball jn nearest to the load direction. Ball angles in it are
  // (j − jn)·2π/Z, exact up to one rounding, so small projections v·e_j are products, not
  // differences of large numbers.
  const double psi = std::atan2(load.y(), load.x());
  const long nearest = std::lround(std::remainder(psi - options.phase, two_pi) / pitch);
  const int jn = static_cast<int>(((nearest % Z) + Z) % Z);
  const double frame = res.ball_angles[jn];
  const double delta = std::remainder(psi - frame, two_pi);  // load angle in the frame
  auto offset = [&](int j) {                                 // j − jn wrapped to (−Z/2, Z/2]
    int dj = ((j - jn) % Z + Z) % Z;
    return dj > Z / 2 ? dj - Z : dj;
  };
  std::vector<double> c(Z), s(Z);
  for (int j = 0; j < Z; ++j) {
    c[j] = std::cos(pitch * offset(j));
    s[j] = std::sin(pitch * offset(j));
  }
  const Eigen::Vector2d w(std::cos(delta), std::sin(delta));

  // Zero-load contact point u_ref (local frame) and the offsets β_j = u_ref·e_j − γ ≤ 0 [m],
  // in closed form so that the touching balls get exactly 0. If F points at ball jn to within
  // the tolerance (its tangential part |sin Δ| is below what the residual test resolves), the
  // ring stays on that ball's edge of the clearance polygon; otherwise it slides to the vertex
  // shared with the neighbour on F's side.
  Eigen::Vector2d u_ref = Eigen::Vector2d::Zero();
  std::vector<double> beta(Z, 0.0);
  if (gap > 0) {
    const bool on_ball = std::abs(std::sin(delta)) <= 0.125 * options.tolerance;
    const int side = delta >= 0 ? 1 : -1;
    const double half = pi / Z;
    const double ref_angle = on_ball ? 0.0 : side * half;
    const double ref_radius = on_ball ? gap : gap / std::cos(half);
    u_ref = ref_radius * Eigen::Vector2d(std::cos(ref_angle), std::sin(ref_angle));
    for (int j = 0; j < Z; ++j) {
      const int dj = offset(j);
      const bool touching = dj == 0 || (!on_ball && dj == side);
      const double rel = half * (2 * dj - (on_ball ? 0 : side));  // θ_j − ref_angle
      beta[j] = touching ? 0.0 : ref_radius * std::cos(rel) - gap;
    }
  }
  std::vector<double> beta_scaled(Z);
  for (int j = 0; j < Z; ++j) beta_scaled[j] = beta[j] / L;

  const Problem prob(c, s, beta_scaled, n, w);

  // Step 1: along the load.
  Eigen::Vector2d v = solve_along_load(prob) * w;

  // Step 2: regularised Newton with a line search on Φ̃ (newton_options).
  Problem::Eval cur = prob.eval(v);
  const double tol = options.tolerance;
  const auto not_higher = [&](const Problem::Eval& e, const Problem::Eval& at,
                              const Eigen::Vector2d& x) {
    return e.value <= at.value + 64 * kEps * (std::abs(at.value) + std::abs(w.dot(x)));
  };
  const numerics::NewtonResult newton = numerics::newton_minimize(
      v, cur, [&](const Eigen::Vector2d& x) { return prob.eval(x); }, not_higher,
      newton_options(options));

  // Physical results: δ_j = β_j + L v·e_j and Q_j = F p_j^n (= K δ_j^n, since K L^n = F); the
  // deflection rotated back to the fixed frame.
  const Eigen::Rotation2Dd to_fixed(frame);
  res.deflection = to_fixed * (u_ref + L * v);
  res.ball_approach.resize(Z);
  res.ball_loads.resize(Z);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int j = 0; j < Z; ++j) {
    const double proj = v.x() * c[j] + v.y() * s[j];
    const double p = beta_scaled[j] + proj;
    res.ball_approach[j] = beta[j] + L * proj;
    res.ball_loads[j] = p > 0 ? F * std::pow(p, n) : 0.0;
    sum += res.ball_loads[j] *
           Eigen::Vector2d(std::cos(res.ball_angles[j]), std::sin(res.ball_angles[j]));
    res.q_max = std::max(res.q_max, res.ball_loads[j]);
  }
  res.residual = (sum - load).norm() / F;
  res.iterations = newton.iterations;

  // Converged, or stopped at the rounding floor of the force sum: each p_j carries an error of
  // a few ε|v|, which reaches g through H, and the sum itself rounds at ε Σ p^n.
  const double gnorm = cur.gradient.norm();
  const double floor = 16 * kEps * (1.0 + cur.load_sum + v.norm() * cur.hessian.trace());
  if (gnorm <= tol || gnorm <= floor) return res;
  std::ostringstream msg;
  msg << "solve_static_load: no equilibrium after " << newton.iterations << " Newton iterations"
      << (newton.stalled ? " (the line search could not reduce the potential any further)" : "")
      << ": relative force residual " << format_number(gnorm) << " > tolerance "
      << format_number(tol) << " (Z = " << Z << ", K = " << format_number(K)
      << " N/m^n, gap = " << format_number(gap) << " m, load = (" << format_number(load.x()) << ", "
      << format_number(load.y()) << ") N); raise max_iterations or the tolerance";
  throw SolverError(msg.str());
}

}  // namespace bearing
