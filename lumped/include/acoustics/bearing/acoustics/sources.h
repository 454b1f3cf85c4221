#pragma once
// Sound sources of a bearing (docs/model.md §8): transfer functions from a body's surface velocity
// to the sound pressure at a point, exact in ka, and seed 000's approximate forms as labelled
// options.
//
// Time dependence e^{iωt}, k = ω/c₀. A body of radius a whose surface moves with normal velocity
// u·Θ(angle) (Θ = 1 for a breathing body, cos ψ for a rigid body translating with velocity u,
// ψ measured from the direction of motion) radiates the outgoing field
//     p(r, ψ) = −i ρ₀c₀ u Θ(ψ) h(kr) / h'(ka),
// with h the outgoing (second-kind) Hankel function of the pattern's order: H₀⁽²⁾, H₁⁽²⁾ for an
// infinite cylinder (2-D), spherical h₀⁽²⁾, h₁⁽²⁾ for a sphere. Derivation: the radial momentum
// equation iωρ₀ v_r = −∂p/∂r at r = a, where v_r = u Θ, fixes the amplitude A of p = A Θ h(kr):
// iωρ₀ u = −A k h'(ka). Derivatives: H₀' = −H₁, H₁'(x) = H₀(x) − H₁(x)/x, h₀' = −h₁,
// h₁'(x) = h₀(x) − 2h₁(x)/x. The Bessel functions are GSL's.
//
// The spheres' fields are finite sums of radial terms, because h₀⁽²⁾(x) = i e^{−ix}/x and
// h₁⁽²⁾(x) = e^{−ix}(i − x)/x²:
//     pulsating:   p = ρ₀c₀ u (a/r) · ika/(1 + ika) · e^{−ik(r−a)}
//     oscillating: p = cos ψ · e^{−ik(r−a)} · C(ka) [ −(a/r)/(ka) + i (a/r)²/(ka)² ] u,
//                  C(x) = −iρ₀c₀ x³ / (2x + i(x² − 2)),
// i.e. H(ω; r, ψ) = Θ(ψ) e^{−iω(r−a)/c₀} Σ_m (a/r)^m F_m(ω). That form lets a moving ball be
// filtered once (the F_m) and then delayed and weighted sample by sample (pressure.h).
//
// Low-ka limits (the tests' independent references):
//   cylinder dipole   p → (π/2) ρ₀c₀ (ka)² u cos ψ H₁⁽²⁾(kr)             (H₁'(x) → −2i/(πx²))
//   sphere dipole     p → −(ρ₀c₀ k² a³ u cos ψ / 2r)(1 − i/(kr)) e^{−ikr}   (h₁'(x) → −2i/x³)
//
// Seed 000's forms ("paper"):
// - Ring, its eq. (19): the cylinder dipole with the small-argument Hankel functions
//   H₁(x) ≈ x/2 + 2i/(πx) and H₁'(x) ≈ 1/2 − 2i/(πx²) for both ka and kr. Expanded, its real part
//   carries kr/4 − 4/(π²k³a²r), the paper's first bracket exactly; the imaginary part is
//   r/(πka²) + 1/(πkr), where the paper prints 4/(π²k³a²r) + r/(πka²) (a garbled copy of the
//   first bracket's term, docs/model.md §8). This is the form as derived, not as printed. It needs
//   kr ≪ 1 as well as ka ≪ 1 (at 10 mm, kr = 1 at 5.5 kHz).
// - Ball, its eq. (23): p = ρ₀c₀ k a² u / (r √(1 + (ka)²)) · e^{iθ}, θ = arctan(1/(ka)). That is
//   the pulsating sphere's exact modulus and phase factor ika/(1 + ika), without the propagation
//   delay e^{−ik(r−a)}: equal SPL for one ball, different phases between balls and the ring.
//   (Its eq. (25) is inconsistent with eq. (23) and is not used.)

#include <complex>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// The medium. Defaults: air at 20 °C and 1 atm.
struct Air {
  double density = 1.204;                                     ///< ρ₀ [kg/m^3]
  double sound_speed = 343.2;                                 ///< c₀ [m/s]
  double impedance() const { return density * sound_speed; }  ///< ρ₀c₀ [Pa s/m]
};

/// How the surface velocity is distributed over the body.
enum class Pattern {
  breathing,    ///< u on the whole surface (monopole): Θ = 1
  translating,  ///< rigid-body motion with velocity u (dipole): Θ = cos ψ
};

/// A radiating body: pressure per unit velocity amplitude.
class AcousticSource {
 public:
  AcousticSource(std::string name, double radius, const Air& air)
      : name_(std::move(name)), radius_(radius), air_(air) {}
  virtual ~AcousticSource() = default;

  /// The name the case file and bearing-fem use ("cylinder-dipole", "pulsating-sphere", …).
  std::string_view name() const { return name_; }
  /// Radius a of the body [m].
  double radius() const { return radius_; }
  /// The medium it radiates into.
  const Air& air() const { return air_; }
  /// Wavenumber k = ω/c₀ [1/m] of an angular frequency ω [rad/s].
  double wavenumber(double omega) const { return omega / air_.sound_speed; }

  /// Whether the field is a cylinder's (2-D, per unit length) or a sphere's.
  virtual bool cylindrical() const = 0;
  virtual Pattern pattern() const = 0;

  /// p/u [Pa/(m/s)] at angular frequency ω ≥ 0 [rad/s], distance r ≥ a from the body's centre
  /// [m], and cos ψ (the direction to the point against the direction of motion; ignored for a
  /// breathing body). Zero at ω = 0 (no body radiates a steady velocity). Throws InputError for
  /// ω < 0, r < a or non-finite arguments.
  virtual std::complex<double> transfer(double omega, double r, double cos_angle) const = 0;

  /// transfer(ω, r[i], cos_angle[i]) for several points at one ω, into out[i] (resized): the same
  /// values, bit for bit. A body whose field divides by a function of ka alone (the cylinders'
  /// H'(ka)) evaluates it once for all the points. Throws as transfer().
  virtual void transfer(double omega, const std::vector<double>& r,
                        const std::vector<double>& cos_angle,
                        std::vector<std::complex<double>>& out) const;

  /// The steady pressure of a velocity ramp u = βt, per unit β [Pa/(m/s²)]: lim_{ω→0} H/(iω),
  /// real because the impulse response is (H(−ω) = conj H(ω)). Every source here but the
  /// breathing cylinder has one (its 2-D field grows like ln t: 0 is returned there). Evaluated
  /// at ka = 1e-7, where the next term of H is smaller by (ka)², or (ka)² ln(ka) for a cylinder.
  virtual double ramp_pressure(double r, double cos_angle) const;

 private:
  std::string name_;
  double radius_;
  Air air_;
};

/// A source whose transfer function is a finite sum of radial terms (the spheres and seed 000's
/// ball form): H = Θ(ψ) · D(ω, r) · Σ_m (a/r)^m F_m(ω), with D = e^{−iω(r−a)/c₀} (or 1 for a
/// form without propagation delay). What the moving-source filter (pressure.h) needs.
class RadialSeriesSource : public AcousticSource {
 public:
  using AcousticSource::AcousticSource;
  /// The powers m of (a/r) present, ascending (e.g. {1} pulsating, {1, 2} oscillating).
  virtual std::vector<int> powers() const = 0;
  /// F_m(ω) for the i-th power of powers() [Pa/(m/s)]; zero at ω = 0.
  virtual std::complex<double> factor(std::size_t i, double omega) const = 0;
  /// Whether the field carries the delay e^{−iω(r−a)/c₀}.
  virtual bool delayed() const = 0;
  /// lim_{ω→0} F_m(ω)/(iω) for the i-th power [Pa/(m/s²)]: the term's ramp response.
  double ramp_factor(std::size_t i) const;
  /// The sum evaluated at one (ω, r, cos ψ): the same value as transfer() to rounding, but from
  /// the elementary closed form rather than GSL's Bessel functions.
  std::complex<double> series(double omega, double r, double cos_angle) const;
};

/// Names accepted by make_source: "cylinder-monopole", "cylinder-dipole", "cylinder-dipole-paper"
/// (seed 000 eq. 19 as derived), "pulsating-sphere", "oscillating-sphere",
/// "pulsating-sphere-paper" (seed 000 eq. 23); "sphere-monopole" and "sphere-dipole" are the
/// spheres' other names.
std::vector<std::string> source_names();

/// The source called `name`, of radius a > 0 [m], in `air`. Throws InputError naming `key` for an
/// unknown name (with the allowed ones) or a radius / air property that is not positive and
/// finite.
std::unique_ptr<AcousticSource> make_source(std::string_view name, double radius, const Air& air,
                                            const std::string& key = "source");

/// The same for the spheres' series forms ("pulsating-sphere", "oscillating-sphere",
/// "pulsating-sphere-paper" and their aliases); InputError for a cylinder.
std::unique_ptr<RadialSeriesSource> make_series_source(std::string_view name, double radius,
                                                       const Air& air,
                                                       const std::string& key = "source");

/// Sound pressure level of an RMS pressure: 20 log10(p_rms / 20 µPa) [dB re 20 µPa]. p_rms must
/// be positive and finite (InputError otherwise: a silent signal has no finite level).
double sound_pressure_level(double p_rms);

/// The reference pressure of sound_pressure_level, 20 µPa [Pa].
constexpr double kReferencePressure = 20e-6;

}  // namespace bearing
