#pragma once
// Private to the lumped models (not installed): the ball set at one instant — each ball's angle,
// its excitation e_j (waviness on both races and its size error) and its contact constant K_j —
// evaluated without allocation and without one sin() per ball or per harmonic.
//
// Ball angles (MODEL.md §1): θ_j(t) = φ₀ + 2πj/Z + ω_c t, j = 0…Z−1. (cos θ_j, sin θ_j) is the
// precomputed (cos, sin) of φ₀ + 2πj/Z rotated by the one (cos, sin) of ω_c t per instant.
//
// Waviness (MODEL.md §5): Π(φ) = Σ_s A_s sin(N_s φ + ψ_s) at the race-fixed contact angle,
// φ_j = θ_j on the outer race and θ_j − ω_i t on the inner race. Written per order n as
//     Π(φ) = Σ_n a_n sin nφ + b_n cos nφ,   a_n = Σ_{N_s = n} A_s cos ψ_s,  b_n = Σ A_s sin ψ_s.
// The balls are evenly spaced on each race, φ_j = φ_ref + 2πj/Z, so with β_nj = 2π n j / Z
//     a_n sin(nφ_j) + b_n cos(nφ_j) = P_n cos β_nj + Q_n sin β_nj,
//     P_n = a_n sin nφ_ref + b_n cos nφ_ref,   Q_n = a_n cos nφ_ref − b_n sin nφ_ref,
// and β_nj depends on n only through k = n mod Z. Hence, per instant,
//   1. sin nφ_ref, cos nφ_ref for n = 1…N_max by the Chebyshev recurrence
//      sin((n+1)φ) = 2 cos φ sin(nφ) − sin((n−1)φ) (likewise cos) from the one (cos, sin) of φ_ref
//      (run as Z independent chains of step Zφ, one per bin: RaceExcitation);
//   2. fold the orders into Z bins, U_k = Σ_{n≡k} P_n, V_k = Σ_{n≡k} Q_n;
//   3. Π(φ_j) = Σ_k U_k cos(2πkj/Z) + V_k sin(2πkj/Z) with a precomputed Z×Z table.
// That is ~8 flops per order plus 4 per (ball, bin), instead of one recurrence per ball (for the
// 6308 with seed 003's 97 orders: ~1000 instead of ~5000 flops). It is also the physics of
// waviness seen by Z balls: orders N and N ± Z act alike on the ball set.
//
// TVDS (seed 002, MODEL.md §3): the waviness also changes the raceway curvature in the rolling
// direction. For a race of radius R whose surface sits at R + ε(φ) from the race centre, the
// curvature of the polar curve r(φ) = R + ε is
//     κ = (r² + 2r'² − r r'') / (r² + r'²)^{3/2} = 1/R − (ε + ε'')/R² + O(ε²),
// (first order: numerator R² + 2Rε − Rε'', denominator R³(1 + 3ε/R)). With Harris's signs
// (convex positive) and Π positive toward the ball:
//   - inner race (convex, the ball outside it): ε = +Π_i, ρ_II1 = +κ = 1/R_i − (Π_i + Π_i'')/R_i²;
//   - outer race (concave, the ball inside it): ε = −Π_o, ρ_II1 = −κ = −1/R_o − (Π_o + Π_o'')/R_o².
// So on both races Δρ_II1 = −(Π + Π'')/R², which for Π = A sin(Nφ) is +A(N²−1) sin(Nφ)/R²: a
// crest makes the inner race more convex and the outer race less concave (N = 1, a shifted
// circle, changes nothing). R = d_i/2, d_o/2 (exact for α = 0; for α ≠ 0 the same first-order
// change is added to Harris's ρ_II1). Per contact, with Δ = Δρ_II1, Σρ = Σρ₀ + Δ and
// F = (ρ_II1 − ρ_II2)/Σρ = (num₀ + Δ)/(Σρ₀ + Δ) (the ball terms cancel in the numerator), and
// K = 2^{5/2} / (3η δ*^{3/2} Σρ^{1/2}) gives
//     K^{−2/3} = K₀^{−2/3} · g(Δ),   g(Δ) = [δ*(F(Δ))/δ*(F₀)] · (1 + Δ/Σρ₀)^{1/3},
// scaled from the race's own constant K₀ so that zero waviness reproduces TVD exactly (and a
// calibrated K₀ keeps its calibration). g depends on Δ alone: it is tabulated once, with the
// case's Hertz method, over every Δ the waviness can reach (|Π + Π''| ≤ Σ A_s |N_s² − 1|), so
// the hot loop does one table lookup per race contact — no root finding, no cbrt. The ball
// between both races: K_j = (K_i^{−2/3} + K_o^{−2/3})^{−3/2}.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include "phasor.h"

#include <atomic>
#include <cstdint>

#include "bearing/bearing.h"
#include "bearing/constants.h"
#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/excitation.h"
#include "bearing/hertz.h"
#include "bearing/models/model_inputs.h"
#include "bearing/units.h"
#include "max_balls.h"
#include "model_input_checks.h"

namespace bearing::detail {

/// The ball set at one instant (filled by BallSet::evaluate; lives on the caller's stack).
struct BallFrame {
  double cos_theta[kMaxBalls];
  double sin_theta[kMaxBalls];
  double excitation[kMaxBalls];  ///< e_j = Π_i(θ_j − ω_i t) + Π_o(θ_j) − ΔD_j [m]
  double stiffness[kMaxBalls];   ///< K_j [N/m^n] (all equal to K unless TVDS)
  double cos_shaft = 1;          ///< cos ω_i t
  double sin_shaft = 0;          ///< sin ω_i t
};

/// The ball set at one instant with the two races kept apart (BallSet::evaluate), for the
/// ball-DOF model, where each ball has a contact of its own on each race.
struct RaceFrame {
  double cos_theta[kMaxBalls];
  double sin_theta[kMaxBalls];
  double inner_excitation[kMaxBalls];  ///< e_i,j = Π_i(θ_j − ω_i t) − ΔD_j/2 [m]
  double outer_excitation[kMaxBalls];  ///< e_o,j = Π_o(θ_j) − ΔD_j/2 [m]
  double inner_stiffness[kMaxBalls];   ///< K_i,j [N/m^n_i] (all K_i unless TVDS)
  double outer_stiffness[kMaxBalls];   ///< K_o,j [N/m^n_o] (all K_o unless TVDS)
  double cos_shaft = 1;                ///< cos ω_i t
  double sin_shaft = 0;                ///< sin ω_i t
};

/// Q = K δ^n for δ > 0 (fast path for n = 3/2).
inline double contact_load(double K, double n, double delta) {
  return n == 1.5 ? K * delta * std::sqrt(delta) : K * std::pow(delta, n);
}

/// The relative compliance g(Δ) = K(Δ)^{−2/3} / K₀^{−2/3} = [δ*(F(Δ))/δ*(F₀)] · (1 + Δ/Σρ₀)^{1/3}
/// of one race contact whose rolling-direction curvature changed by Δ [1/m], with
/// F(Δ) = (num₀ + Δ)/(Σρ₀ + Δ): a function of Δ alone, tabulated once on a uniform grid through
/// Δ = 0 (where it is exactly 1) and interpolated by cubic Hermite with fourth-order difference
/// slopes, so the hot loop needs neither root finding nor cbrt.
class CurvatureComplianceTable {
 public:
  CurvatureComplianceTable() = default;
  CurvatureComplianceTable(const HertzSolution& method, double num0, double sum0, double bound,
                           const std::string& key) {
    // 32 intervals on each side of Δ = 0 up to ±bound (a floor on h for bound → 0).
    h_ = std::max(bound / 32.0, 1e-9 * sum0);
    const int side = static_cast<int>(std::ceil(bound / h_)) + 1;
    const int ghost = 2;  // extra nodes for the difference slopes at the ends
    const int nodes = 2 * (side + ghost) + 1;
    std::vector<double> g(nodes);
    const double f0 = num0 / sum0;
    const double ds0 = method.shape(f0).delta_star;
    for (int k = 0; k < nodes; ++k) {
      const int i = k - side - ghost;
      if (i == 0) {
        g[k] = 1.0;
        continue;
      }
      const double d = i * h_;
      const double sum = sum0 + d, f = (num0 + d) / sum;
      if (!(sum > 0 && f >= 0 && f < 1))
        throw InputError(key +
                         " with model.waviness_stiffness (TVDS): the waviness changes the "
                         "raceway curvature by up to " +
                         format_number(bound) +
                         " 1/m, which takes the contact's curvature sum to " + format_number(sum) +
                         " 1/m and F(rho) to " + format_number(f) +
                         ": too large for the first-order curvature model");
      g[k] = method.shape(f).delta_star / ds0 * std::cbrt(sum / sum0);
    }
    first_ = -side * h_;
    const int n = 2 * side + 1;
    y_.resize(n);
    m_.resize(n);
    for (int i = 0; i < n; ++i) {
      const int k = i + ghost;
      y_[i] = g[k];
      m_[i] = (g[k - 2] - 8.0 * g[k - 1] + 8.0 * g[k + 1] - g[k + 2]) / 12.0;  // dg/du, u = Δ/h
    }
  }

  /// dg/dΔ [m], the derivative of the same cubic Hermite interpolant.
  double derivative(double d) const {
    const double u = (d - first_) / h_;
    const int last = static_cast<int>(y_.size()) - 2;
    int i = static_cast<int>(std::floor(u));
    i = std::min(std::max(i, 0), last);
    const double t = u - i;
    const double t2 = t * t;
    return ((6 * t2 - 6 * t) * y_[i] + (3 * t2 - 4 * t + 1) * m_[i] +
            (-6 * t2 + 6 * t) * y_[i + 1] + (3 * t2 - 2 * t) * m_[i + 1]) /
           h_;
  }

  /// g(Δ); exact at the nodes (1 at Δ = 0).
  double operator()(double d) const {
    const double u = (d - first_) / h_;
    const int last = static_cast<int>(y_.size()) - 2;
    int i = static_cast<int>(std::floor(u));
    i = std::min(std::max(i, 0), last);
    const double t = u - i;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * m_[i] +
           (-2 * t3 + 3 * t2) * y_[i + 1] + (t3 - t2) * m_[i + 1];
  }

 private:
  double first_ = 0, h_ = 1;
  std::vector<double> y_, m_;
};

/// One race's waviness, folded by order mod Z (see the header comment), for all balls at once.
///
/// Layout: order n = mZ + k sits in row m, column k (k = 0…Z−1, m = 0…rows−1); the columns are the
/// bins. Column k is one Chebyshev chain with step Zφ,
///     sin((n+Z)φ) = 2 cos(Zφ) sin(nφ) − sin((n−Z)φ)   (likewise cos),
/// started from sin(kφ) and sin((k−Z)φ) = −sin((Z−k)φ), which come from the step-φ recurrence
/// over the first Z orders. Each row is then a loop over contiguous arrays with no dependence
/// between columns (it vectorises), and each column accumulates its own bin. When N_max < Z there
/// is one row of N_max + 1 columns and no chain step.
class RaceExcitation {
 public:
  RaceExcitation() = default;
  RaceExcitation(const Waviness& w, int balls, bool curvature) : balls_(balls) {
    const int order_max = w.max_order();
    if (order_max == 0) return;
    rows_ = order_max / balls + 1;
    width_ = rows_ == 1 ? order_max + 1 : balls;
    a_.assign(rows_ * width_, 0.0);
    b_.assign(rows_ * width_, 0.0);
    for (const WavinessHarmonic& h : w.harmonics) {
      const int i = (h.order / balls) * width_ + h.order % balls;
      a_[i] += h.amplitude * std::cos(h.phase);
      b_[i] += h.amplitude * std::sin(h.phase);
    }
    curvature_ = curvature;
    if (curvature) {
      weight_.resize(rows_ * width_);
      for (int m = 0; m < rows_; ++m)
        for (int k = 0; k < width_; ++k) {
          const double n = double(m) * balls + k;
          weight_[m * width_ + k] = 1.0 - n * n;
        }
    }
  }

  bool empty() const { return rows_ == 0; }

  /// Adds Π(φ_ref + 2πj/Z) to profile[j] and, with curvature, writes (Π + Π'')(φ_j) to
  /// curv[j]; (c, s) = (cos φ_ref, sin φ_ref); table[j*Z + k] = (cos, sin)(2πkj/Z).
  void evaluate(double c, double s, const double* table_cos, const double* table_sin,
                double* profile, double* curv) const {
    if (rows_ == 0) return;
    if (curvature_)
      evaluate_impl<true>(c, s, table_cos, table_sin, profile, curv);
    else
      evaluate_impl<false>(c, s, table_cos, table_sin, profile, curv);
  }

 private:
  template <bool kCurvature>
  void evaluate_impl(double c, double s, const double* table_cos, const double* table_sin,
                     double* profile, double* curv) const {
    const int Z = balls_, W = width_;
    // sin(kφ), cos(kφ) for k = 0…W−1 (the chains' first row), and for k = Z if rows follow.
    double sn[kMaxBalls], cn[kMaxBalls], sp[kMaxBalls], cp[kMaxBalls];
    sn[0] = 0.0, cn[0] = 1.0;
    if (W > 1) sn[1] = s, cn[1] = c;
    const double two_c = 2.0 * c;
    for (int k = 2; k < W; ++k) {
      sn[k] = two_c * sn[k - 1] - sn[k - 2];
      cn[k] = two_c * cn[k - 1] - cn[k - 2];
    }
    double two_cz = 0.0;
    if (rows_ > 1) {  // W == Z: the previous row, orders k − Z, and cos Zφ
      const double sz = two_c * sn[Z - 1] - (Z >= 2 ? sn[Z - 2] : 0.0);
      const double cz = two_c * cn[Z - 1] - (Z >= 2 ? cn[Z - 2] : 1.0);
      sp[0] = -sz, cp[0] = cz;
      for (int k = 1; k < Z; ++k) sp[k] = -sn[Z - k], cp[k] = cn[Z - k];
      two_cz = 2.0 * cz;
    }
    double U[kMaxBalls], V[kMaxBalls], U2[kMaxBalls], V2[kMaxBalls];
    std::fill(U, U + W, 0.0);
    std::fill(V, V + W, 0.0);
    if (kCurvature) {
      std::fill(U2, U2 + W, 0.0);
      std::fill(V2, V2 + W, 0.0);
    }
    for (int m = 0; m < rows_; ++m) {
      const double* a = a_.data() + m * W;
      const double* b = b_.data() + m * W;
      const double* wt = kCurvature ? weight_.data() + m * W : nullptr;
      for (int k = 0; k < W; ++k) {
        const double p = a[k] * sn[k] + b[k] * cn[k];
        const double q = a[k] * cn[k] - b[k] * sn[k];
        U[k] += p;
        V[k] += q;
        if (kCurvature) {
          U2[k] += wt[k] * p;
          V2[k] += wt[k] * q;
        }
      }
      if (m + 1 == rows_) break;
      for (int k = 0; k < W; ++k) {
        const double s_next = two_cz * sn[k] - sp[k];
        const double c_next = two_cz * cn[k] - cp[k];
        sp[k] = sn[k], cp[k] = cn[k];
        sn[k] = s_next, cn[k] = c_next;
      }
    }
    for (int j = 0; j < Z; ++j) {
      const double* tc = table_cos + j * Z;
      const double* ts = table_sin + j * Z;
      double sum = 0.0;
      for (int k = 0; k < W; ++k) sum += U[k] * tc[k] + V[k] * ts[k];
      profile[j] += sum;
      if (kCurvature) {
        double sum2 = 0.0;
        for (int k = 0; k < W; ++k) sum2 += U2[k] * tc[k] + V2[k] * ts[k];
        curv[j] = sum2;
      }
    }
  }

  int balls_ = 0;
  int rows_ = 0;   // 0: no waviness
  int width_ = 0;  // columns per row: Z, or N_max + 1 < Z for a single row
  bool curvature_ = false;
  std::vector<double> a_, b_, weight_;  // row-major, rows_ × width_
};

/// Per-race TVDS constants: K^{−2/3} = k0 · g(Δ), Δ = −(Π + Π'')/R².
struct RaceStiffness {
  bool varies = false;
  double k0 = 0;            ///< K₀^{−2/3}
  double minus_inv_r2 = 0;  ///< −1/R² [1/m²]
  CurvatureComplianceTable table;

  double compliance(double pi_plus_pi2) const { return k0 * table(pi_plus_pi2 * minus_inv_r2); }
  /// d(K^{−2/3})/dt for d(Π + Π'')/dt = `rate`.
  double compliance_rate(double pi_plus_pi2, double rate) const {
    return k0 * table.derivative(pi_plus_pi2 * minus_inv_r2) * rate * minus_inv_r2;
  }
};

/// Π, Π', Π + Π'' and Π' + Π''' of one race at the race-fixed angle φ, by direct sums over the
/// harmonics (for output instants; the hot loop uses RaceExcitation).
struct ProfileDerivatives {
  double profile = 0;     ///< Π [m]
  double slope = 0;       ///< dΠ/dφ [m/rad]
  double curv = 0;        ///< Π + Π'' [m] (TVDS curvature term)
  double curv_slope = 0;  ///< Π' + Π''' [m/rad]
};

inline ProfileDerivatives profile_derivatives(const Waviness& w, double phi) {
  ProfileDerivatives d;
  for (const WavinessHarmonic& h : w.harmonics) {
    const double N = h.order, a = N * phi + h.phase;
    const double s = h.amplitude * std::sin(a), c = h.amplitude * std::cos(a);
    d.profile += s;
    d.slope += N * c;
    d.curv += (1.0 - N * N) * s;
    d.curv_slope += N * (1.0 - N * N) * c;
  }
  return d;
}

/// Time derivatives of the ball set at one instant and the outer race's share of it, for the
/// output instants (libm per ball and harmonic: never in the hot loop).
struct BallRates {
  double excitation_rate[kMaxBalls];       ///< de_j/dt [m/s]
  double stiffness_rate[kMaxBalls];        ///< dK_j/dt [N/(m^n s)] (0 unless TVDS)
  double outer_profile[kMaxBalls];         ///< Π_o(θ_j) [m]
  double outer_profile_rate[kMaxBalls];    ///< dΠ_o(θ_j)/dt [m/s]
  double outer_stiffness[kMaxBalls];       ///< K_o,j of the ball on the outer race [N/m^n_o]
  double outer_stiffness_rate[kMaxBalls];  ///< dK_o,j/dt (0 unless TVDS)
};

/// The ball centre's radial displacement from the pitch radius, r = δ_o − Π_o + ΔD/2 [m], and
/// its rate [m/s], from the ball's load Q = K δ^n and its rate (see bearing_model.h for the
/// definition): δ_o = (Q/K_o)^{1/n_o}, dδ_o/dt = δ_o/n_o · (dQ/dt / Q − dK_o/dt / K_o).
inline void outer_ball_motion(double load, double load_rate, const BallRates& br, int j,
                              double outer_exponent, double size_error, double& r, double& vr) {
  double d_o = 0, d_o_rate = 0;
  if (load > 0) {
    const double Ko = br.outer_stiffness[j];
    d_o = std::pow(load / Ko, 1.0 / outer_exponent);
    d_o_rate = d_o / outer_exponent * (load_rate / load - br.outer_stiffness_rate[j] / Ko);
  }
  r = d_o - br.outer_profile[j] + 0.5 * size_error;
  vr = d_o_rate - br.outer_profile_rate[j];
}

/// Geometry, excitation and contact constants of the ball set, evaluated per instant.
class BallSet {
 public:
  /// `cage_speed` ω_c [rad/s]; the inputs must have passed validate_common_inputs.
  BallSet(const ModelInputs& in, double cage_speed)
      : balls_(in.bearing.balls),
        cage_speed_(cage_speed),
        inner_speed_(in.inner_speed),
        // Only the inner-race waviness and the unbalance turn with the shaft.
        needs_shaft_(!in.inner_waviness.empty() || in.unbalance != 0.0),
        K_(in.contact.K),
        exponent_(in.contact.exponent),
        cage_phase_(in.cage_phase),
        inner_K_(in.contact.inner.K),
        outer_K_(in.contact.outer.K),
        outer_exponent_(in.contact.outer.exponent),
        inner_waviness_(in.inner_waviness),
        outer_waviness_(in.outer_waviness) {
    const int Z = balls_;
    base_cos_.resize(Z);
    base_sin_.resize(Z);
    for (int j = 0; j < Z; ++j) {
      base_cos_[j] = std::cos(in.cage_phase + two_pi * j / Z);
      base_sin_[j] = std::sin(in.cage_phase + two_pi * j / Z);
    }
    size_error_.assign(Z, 0.0);
    if (!in.ball_size_errors.empty()) size_error_ = in.ball_size_errors;

    const bool tvds = in.waviness_stiffness;
    inner_ = RaceExcitation(in.inner_waviness, Z, tvds);
    outer_ = RaceExcitation(in.outer_waviness, Z, tvds);
    if (!inner_.empty() || !outer_.empty()) {
      table_cos_.resize(Z * Z);
      table_sin_.resize(Z * Z);
      for (int j = 0; j < Z; ++j)
        for (int k = 0; k < Z; ++k) {
          const int m = (k * j) % Z;  // 2πkj/Z reduced exactly
          table_cos_[j * Z + k] = std::cos(two_pi * m / Z);
          table_sin_[j * Z + k] = std::sin(two_pi * m / Z);
        }
    }
    if (tvds && (!inner_.empty() || !outer_.empty())) setup_tvds(in);
  }

  int balls() const { return balls_; }
  double cage_speed() const { return cage_speed_; }
  double K() const { return K_; }
  double exponent() const { return exponent_; }
  bool tvds() const { return inner_stiffness_.varies || outer_stiffness_.varies; }
  /// Load–deflection exponent n_o of a ball on the outer race [-].
  double outer_exponent() const { return outer_exponent_; }
  /// ΔD_j = D − D_j [m].
  double size_error(int j) const { return size_error_[j]; }

  /// Fills `br` for time t [s]: with φ_o = θ_j (dφ_o/dt = ω_c) and φ_i = θ_j − ω_i t
  /// (dφ_i/dt = ω_c − ω_i), de_j/dt = Π_i'(φ_i)(ω_c − ω_i) + Π_o'(φ_o) ω_c; with TVDS,
  /// K_j = (c_i + c_o)^{−3/2} (c = K_race^{−2/3}) gives dK_j/dt = −(3/2) K_j (ċ_i + ċ_o)/(c_i +
  /// c_o).
  void rates(double t, BallRates& br) const {
    const double wo = cage_speed_, wi = cage_speed_ - inner_speed_;
    for (int j = 0; j < balls_; ++j) {
      const double theta = cage_phase_ + two_pi * j / balls_ + cage_speed_ * t;
      const ProfileDerivatives o = profile_derivatives(outer_waviness_, theta);
      const ProfileDerivatives i = profile_derivatives(inner_waviness_, theta - inner_speed_ * t);
      br.excitation_rate[j] = i.slope * wi + o.slope * wo;
      br.outer_profile[j] = o.profile;
      br.outer_profile_rate[j] = o.slope * wo;
      br.stiffness_rate[j] = 0.0;
      br.outer_stiffness[j] = outer_K_;
      br.outer_stiffness_rate[j] = 0.0;
      if (!tvds()) continue;
      const RaceStiffness &ri = inner_stiffness_, &ro = outer_stiffness_;
      const double ci = ri.varies ? ri.compliance(i.curv) : ri.k0;
      const double co = ro.varies ? ro.compliance(o.curv) : ro.k0;
      const double ci_rate = ri.varies ? ri.compliance_rate(i.curv, i.curv_slope * wi) : 0.0;
      const double co_rate = ro.varies ? ro.compliance_rate(o.curv, o.curv_slope * wo) : 0.0;
      const double K = 1.0 / ((ci + co) * std::sqrt(ci + co));
      br.stiffness_rate[j] = -1.5 * K * (ci_rate + co_rate) / (ci + co);
      br.outer_stiffness[j] = 1.0 / (co * std::sqrt(co));
      br.outer_stiffness_rate[j] = -1.5 * br.outer_stiffness[j] * co_rate / co;
    }
  }

  /// The frame at time t [s], memoised per thread for the last (ball set, t). RK4 evaluates twice
  /// at t + h/2 and starts each step at the previous step's end time, so half its force calls
  /// reuse the frame. The memo is keyed by a per-object id, never by address, and each thread
  /// has its own, so force() stays const and thread-safe. The reference is valid until the next
  /// call of frame() on this thread.
  const BallFrame& frame(double t) const { return memoised<BallFrame>(t); }

  /// Each ball's load Q_j = K_j [δ_j]_+^n at time t [N], with δ_j = approach(j, frame) [m] the
  /// model's own geometry (shared by the models' ball_loads()).
  template <class Approach>
  void ball_loads(double t, const Approach& approach, double* loads) const {
    BallFrame fr;
    evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) {
      const double delta = approach(j, fr);
      loads[j] = delta > 0 ? contact_load(fr.stiffness[j], exponent_, delta) : 0.0;
    }
  }

  /// Each ball's approach δ_j = approach(j, frame) at time t [m], signed (negative: the gap left
  /// to contact), the δ_j of ball_loads().
  template <class Approach>
  void ball_approaches(double t, const Approach& approach, double* out) const {
    BallFrame fr;
    evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) out[j] = approach(j, fr);
  }

  /// The contact potential Σ_j K_j/(n+1) [δ_j]_+^{n+1} at time t [J], δ_j as in ball_loads().
  template <class Approach>
  double potential_energy(double t, const Approach& approach) const {
    BallFrame fr;
    evaluate(t, fr);
    double energy = 0;
    for (int j = 0; j < balls_; ++j) {
      const double delta = approach(j, fr);
      if (delta > 0)
        energy += fr.stiffness[j] / (exponent_ + 1.0) * std::pow(delta, exponent_ + 1.0);
    }
    return energy;
  }

  /// Fills `fr` for time t [s].
  void evaluate(double t, BallFrame& fr) const {
    const int Z = balls_;
    angles(t, fr);
    for (int j = 0; j < Z; ++j) fr.excitation[j] = -size_error_[j];
    double curv_i[kMaxBalls], curv_o[kMaxBalls];
    add_waviness(fr, fr.excitation, fr.excitation, curv_i, curv_o);

    if (!tvds()) {
      std::fill(fr.stiffness, fr.stiffness + Z, K_);
      return;
    }
    for (int j = 0; j < Z; ++j) {
      const double s = inner_compliance(curv_i[j]) + outer_compliance(curv_o[j]);  // K_j^{−2/3}
      fr.stiffness[j] = 1.0 / (s * std::sqrt(s));
    }
  }

  /// Fills `fr` for time t [s] with each race's excitation and constant apart; a ball-size error
  /// ΔD_j takes ΔD_j/2 from each contact.
  void evaluate(double t, RaceFrame& fr) const {
    const int Z = balls_;
    angles(t, fr);
    for (int j = 0; j < Z; ++j)
      fr.inner_excitation[j] = fr.outer_excitation[j] = -0.5 * size_error_[j];
    double curv_i[kMaxBalls], curv_o[kMaxBalls];
    add_waviness(fr, fr.inner_excitation, fr.outer_excitation, curv_i, curv_o);
    if (!tvds()) {
      std::fill(fr.inner_stiffness, fr.inner_stiffness + Z, inner_K_);
      std::fill(fr.outer_stiffness, fr.outer_stiffness + Z, outer_K_);
      return;
    }
    for (int j = 0; j < Z; ++j) {
      const double ki = inner_compliance(curv_i[j]), ko = outer_compliance(curv_o[j]);
      fr.inner_stiffness[j] = 1.0 / (ki * std::sqrt(ki));
      fr.outer_stiffness[j] = 1.0 / (ko * std::sqrt(ko));
    }
  }

  /// The races' frame at t (evaluate(t, RaceFrame&)), memoised per thread like frame().
  const RaceFrame& race_frame(double t) const { return memoised<RaceFrame>(t); }

 private:
  // One memo per thread and frame type (BallFrame, RaceFrame); see frame().
  template <class Frame>
  const Frame& memoised(double t) const {
    thread_local struct {
      std::uint64_t owner = 0;
      double t = 0.0;
      Frame frame;
    } memo;
    if (memo.owner != id_ || memo.t != t) {
      evaluate(t, memo.frame);
      memo.owner = id_;
      memo.t = t;
    }
    return memo.frame;
  }

  // θ_j and the shaft angle at t: the precomputed (cos, sin) of φ₀ + 2πj/Z rotated by the one
  // phasor of ω_c t (Frame: BallFrame or RaceFrame).
  template <class Frame>
  void angles(double t, Frame& fr) const {
    const Phasor cage = phasor(cage_speed_ * t);  // by rotation, not libm (phasor.h)
    const double cc = cage.c, sc = cage.s;
    const Phasor shaft = needs_shaft_ ? phasor(inner_speed_ * t) : Phasor{1.0, 0.0};
    fr.cos_shaft = shaft.c;
    fr.sin_shaft = shaft.s;
    for (int j = 0; j < balls_; ++j) {
      fr.cos_theta[j] = base_cos_[j] * cc - base_sin_[j] * sc;
      fr.sin_theta[j] = base_sin_[j] * cc + base_cos_[j] * sc;
    }
  }

  // Adds each race's waviness at the balls of `fr` (angles set) to `inner` and `outer` (one array
  // for the combined excitation) and writes Π + Π'' per race (TVDS). Outer race: φ_j = θ_j,
  // reference θ_0; inner race: φ_j = θ_j − ω_i t.
  template <class Frame>
  void add_waviness(const Frame& fr, double* inner, double* outer, double* curv_i,
                    double* curv_o) const {
    const double c0 = fr.cos_theta[0], s0 = fr.sin_theta[0];
    outer_.evaluate(c0, s0, table_cos_.data(), table_sin_.data(), outer, curv_o);
    const double ci = c0 * fr.cos_shaft + s0 * fr.sin_shaft;
    const double si = s0 * fr.cos_shaft - c0 * fr.sin_shaft;
    inner_.evaluate(ci, si, table_cos_.data(), table_sin_.data(), inner, curv_i);
  }

  // K^{−2/3} of a ball on each race with TVDS, from the race's Π + Π'' at the contact.
  double inner_compliance(double curv) const {
    return inner_stiffness_.varies ? inner_stiffness_.compliance(curv) : inner_stiffness_.k0;
  }
  double outer_compliance(double curv) const {
    return outer_stiffness_.varies ? outer_stiffness_.compliance(curv) : outer_stiffness_.k0;
  }

  void setup_tvds(const ModelInputs& in) {
    validate_tvds_contact(in);
    const std::unique_ptr<HertzSolution> method = make_hertz_solution(in.hertz_method);
    setup_race(in, Race::inner, in.inner_waviness, *method, inner_stiffness_);
    setup_race(in, Race::outer, in.outer_waviness, *method, outer_stiffness_);
  }

  static void setup_race(const ModelInputs& in, Race race, const Waviness& w,
                         const HertzSolution& method, RaceStiffness& rs) {
    const RaceContact& rc = race == Race::inner ? in.contact.inner : in.contact.outer;
    rs.k0 = std::pow(rc.K, -2.0 / 3.0);
    if (w.empty()) return;
    const Curvatures cv = race_curvatures(in.bearing, race);
    const double R = 0.5 * (race == Race::inner ? in.bearing.inner_raceway_diameter()
                                                : in.bearing.outer_raceway_diameter());
    rs.minus_inv_r2 = -1.0 / (R * R);
    // |Π + Π''| ≤ Σ_s A_s |N_s² − 1| bounds the curvature change.
    double bound = 0;
    for (const WavinessHarmonic& h : w.harmonics)
      bound += h.amplitude * std::abs(double(h.order) * h.order - 1.0);
    bound /= R * R;
    const double num0 = (cv.ball_1 - cv.ball_2) + (cv.race_1 - cv.race_2);
    rs.table = CurvatureComplianceTable(method, num0, cv.sum(), bound,
                                        race == Race::inner ? "waviness.inner" : "waviness.outer");
    rs.varies = true;
  }

  static std::uint64_t next_id() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
  }

  std::uint64_t id_ = next_id();  ///< identifies this ball set in the per-thread frame memo
  int balls_;
  double cage_speed_;
  double inner_speed_;
  bool needs_shaft_;
  double K_;
  double exponent_;
  double cage_phase_;
  double inner_K_;
  double outer_K_;
  double outer_exponent_;
  Waviness inner_waviness_, outer_waviness_;  // for rates(): direct sums
  std::vector<double> base_cos_, base_sin_, size_error_;
  std::vector<double> table_cos_, table_sin_;
  RaceExcitation inner_, outer_;
  RaceStiffness inner_stiffness_, outer_stiffness_;
};

/// The radial ball motion (bearing_model.h) of the 2-DOF geometry, δ_j = x cos θ_j + y sin θ_j −
/// γ + e_j, at (t, q = (x, y), v = (ẋ, ẏ)): dδ_j/dt = v·(cos θ_j, sin θ_j) + ω_c (−x sin θ_j +
/// y cos θ_j) + de_j/dt, dQ_j/dt = n K_j δ_j^{n−1} dδ_j/dt + dK_j/dt δ_j^n.
inline void radial_ball_motion(const BallSet& set, double gap, double t, const double* q,
                               const double* v, double* r, double* vr) {
  BallFrame fr;
  set.evaluate(t, fr);
  BallRates br;
  set.rates(t, br);
  const double n = set.exponent(), wc = set.cage_speed();
  for (int j = 0; j < set.balls(); ++j) {
    const double c = fr.cos_theta[j], s = fr.sin_theta[j];
    const double delta = q[0] * c + q[1] * s - gap + fr.excitation[j];
    double Q = 0, Q_rate = 0;
    if (delta > 0) {
      const double rate = v[0] * c + v[1] * s + wc * (q[1] * c - q[0] * s) + br.excitation_rate[j];
      Q = contact_load(fr.stiffness[j], n, delta);
      Q_rate = n * Q / delta * rate + br.stiffness_rate[j] * std::pow(delta, n);
    }
    outer_ball_motion(Q, Q_rate, br, j, set.outer_exponent(), set.size_error(j), r[j], vr[j]);
  }
}

}  // namespace bearing::detail
