// Acoustics, lumped side (docs/model.md §8): every source model of acoustics/sources.h against its
// closed form written in acoustics_reference.cc, the low-ka limits, seed 000's forms (their
// agreement at low ka), the time-domain filter on a tone. The toolkit's sources are built in the
// Context's air and evaluated at the Context's microphone distances, so a wrong sound speed or
// microphone placement shows; the frequencies are set from the true sound speed. Seed 000's forms:
// acoustics_paper.cc; decay with distance: acoustics_decay.cc.

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "../context.h"
#include "../families.h"
#include "acoustics_reference.h"
#include "acoustics_shared.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/constants.h"
#include "bearing/signal/fft.h"

namespace bearing::verify {

namespace {

namespace ref = acoustic_reference;
using cd = std::complex<double>;

// The grid of the exact-form checks: ka from the bearing's lowest frequencies to well above its
// band (the 608's ring has ka = 2.1 at 20 kHz), distances from the surface to 1 m, and two
// directions (a dipole's field changes sign across 90°).
const double kKa[] = {1e-3, 1e-2, 0.1, 0.3, 1.0, 2.0, 5.0};
const double kDistance[] = {0.0 /* on the surface */, 0.01, 0.1, 1.0};
const double kAngleDeg[] = {30.0, 120.0};

// The toolkit's transfer function at (ka, r, ψ) of the true air, through the Context.
cd toolkit_transfer(const Context& ctx, const AcousticSource& s, double ka, double r,
                    double angle) {
  const Microphone m = ctx.microphone(r, angle);
  return s.transfer(omega_of(ka, s.radius()), m.radius, std::cos(angle));
}

struct Worst {
  double deviation = 0;
  std::string where;
  void add(cd value, cd reference, double ka, double r, double angle_deg) {
    const double d = std::abs(value / reference - 1.0);
    if (!(d <= deviation)) {  // a NaN is kept as the worst, and fails the check
      deviation = d;
      where = "ka = " + fmt(ka) + ", r = " + fmt(r) + " m, ψ = " + fmt(angle_deg) + "°";
    }
  }
  Outcome outcome(const std::string& what) const {
    return {std::isfinite(deviation) ? deviation : 1e300, 0.0,
            what + "; largest |H/H_ref − 1| at " + where};
  }
};

// One exact source over the grid; spheres through both transfer() and series() (the form the
// moving-ball filter uses).
Check exact_source(const std::string& name, bool cylinder, int order, double radius,
                   const std::string& body, Tolerance tolerance) {
  Check c;
  c.id = "acoustics.exact." + name;
  c.family = "acoustics";
  c.reference = ReferenceKind::closed_form;
  c.compares = "value: |H/H_ref − 1|, H the toolkit's " + name +
               " transfer function (a = " + fmt(radius * 1e3) + " mm, " + body +
               ") at ka = 1e-3 … 5, r = a … 1 m" + (order == 1 ? ", ψ = 30°, 120°" : "") +
               "; reference: 0, H_ref = −iρ₀c₀Θ h(kr)/h'(ka)" +
               (cylinder ? " with H_n⁽²⁾ from Bessel's and Schläfli's integrals"
                         : " with the elementary spherical Hankel functions");
  c.quantity = "max |H/H_ref − 1|";
  c.unit = "-";
  c.tolerance = std::move(tolerance);
  c.level = Level::quick;
  c.cost = cylinder ? 0.3 : 0.01;
  c.catches = {"sound-speed-x1.02", "microphone-distance-x1.05"};
  c.measure = [=](const Context& ctx) {
    const auto source = make_source(name, radius, ctx.air());
    std::unique_ptr<RadialSeriesSource> series;
    if (!cylinder) series = make_series_source(name, radius, ctx.air());
    Worst worst;
    for (double ka : kKa)
      for (double d : kDistance)
        for (double deg : kAngleDeg) {
          if (order == 0 && deg != kAngleDeg[0]) continue;
          const double r = std::max(d, radius), psi = deg * pi / 180;
          const cd h_ref = cylinder ? ref::cylinder_field(order, ka, ka * r / radius, std::cos(psi))
                                    : ref::sphere_field(order, ka, ka * r / radius, std::cos(psi));
          worst.add(toolkit_transfer(ctx, *source, ka, r, psi), h_ref, ka, r, deg);
          if (series) {
            const Microphone m = ctx.microphone(r, psi);
            worst.add(series->series(omega_of(ka, radius), m.radius, std::cos(psi)), h_ref, ka, r,
                      deg);
          }
        }
    return worst.outcome(series ? "transfer() and series()" : "transfer()");
  };
  return c;
}

std::vector<Check> exact_sources() {
  const Tolerance quadrature = absolute(
      1e-9,
      "the reference's Hankel values are quadratures to 1e-12 (GSL QAG, absolute on [0, π]; "
      "QAGIU, relative on Schläfli's tail): ≤ 3e-13/|H_n| ≤ 1.2e-11 relative at kr ≤ 863 "
      "(|H_n| ≥ 0.027), ≤ 5e-11 over the ratio's four values; 1e-9 leaves a factor 20 because "
      "GSL's error estimate is an estimate, not a guarantee; GSL's Bessel functions (the "
      "toolkit's) are good to a few 1e-16");
  const Tolerance rounding =
      absolute(1e-12,
               "both sides are closed forms in double precision (GSL's j_n, y_n against e^{−ix} "
               "polynomials in 1/x): round-off, a few 1e-16 per operation, ≤ 1e-13 over the ~20 "
               "operations of a ratio; 1e-12 allows for GSL's 2 DBL_EPSILON per Bessel value");
  return {
      exact_source("cylinder-monopole", true, 0, seed000_ring_radius(), "the 608's inner ring",
                   quadrature),
      exact_source("cylinder-dipole", true, 1, seed000_ring_radius(), "the 608's inner ring",
                   quadrature),
      exact_source("pulsating-sphere", false, 0, seed000_ball_radius(), "the 608's ball", rounding),
      exact_source("oscillating-sphere", false, 1, seed000_ball_radius(), "the 608's ball",
                   rounding),
  };
}

// --- low-ka limits ---------------------------------------------------------------------------

struct Probe {
  double r_over_a;
  double angle_deg;
};

// The toolkit's source `name` against a limit form at one ka and a few distances: the largest
// |H/H_lim − 1|.
Outcome limit_deviation(const Context& ctx, const std::string& name, double radius, double ka,
                        const std::vector<Probe>& probes,
                        cd (*limit)(double ka, double r_over_a, double cos_angle)) {
  const auto source = make_source(name, radius, ctx.air());
  Worst worst;
  for (const Probe& p : probes) {
    const double psi = p.angle_deg * pi / 180;
    worst.add(toolkit_transfer(ctx, *source, ka, p.r_over_a * radius, psi),
              limit(ka, p.r_over_a, std::cos(psi)), ka, p.r_over_a * radius, p.angle_deg);
  }
  return worst.outcome(name + " at ka = " + fmt(ka));
}

// |H/H_lim − 1| against ka at r = 10a (kr = 10 ka): the exact dipole against its leading order,
// seed 000's form against the exact one, and the truncation bound; slope 2 (× a logarithm).
Figure low_ka_figure(const Context& ctx) {
  const double a = seed000_ring_radius();
  const auto exact = make_source("cylinder-dipole", a, ctx.air());
  const auto paper = make_source("cylinder-dipole-paper", a, ctx.air());
  Figure fig;
  fig.name = "acoustics-low-ka-cylinder";
  fig.title = "Cylinder dipole (608 ring) at r = 10a, ψ = 30°: approach to the low-ka forms";
  fig.x_label = "ka [-]";
  fig.y_label = "relative difference [-]";
  fig.log_x = fig.log_y = true;
  Series limit{"toolkit exact vs (π/2)ρ₀c₀(ka)² cos ψ H₁(kr)", {}, {}, "line+marker"};
  Series eq19{"toolkit eq. (19) vs toolkit exact", {}, {}, "line+marker"};
  Series bound{"bound (x²/2)(|ln(x/2)| + 2) at x = ka", {}, {}, "line"};
  const double c = std::cos(pi / 6);
  for (double ka = 1e-4; ka < 1.01; ka *= std::sqrt(10.0)) {
    const double w = omega_of(ka, a), r = ctx.microphone(10 * a, pi / 6).radius;
    const cd h = exact->transfer(w, r, c);
    limit.x.push_back(ka);
    limit.y.push_back(std::abs(h / ref::cylinder_dipole_low_ka(ka, 10 * ka, c) - 1.0));
    eq19.x.push_back(ka);
    eq19.y.push_back(std::abs(paper->transfer(w, r, c) / h - 1.0));
    bound.x.push_back(ka);
    bound.y.push_back(ref::leading_order_bound(ka));
  }
  fig.series = {limit, eq19, bound};
  return fig;
}

Check limit_check(const std::string& id, const std::string& compares, Tolerance tolerance,
                  std::vector<std::string> catches, std::function<Outcome(const Context&)> m) {
  Check c;
  c.id = id;
  c.family = "acoustics";
  c.reference = ReferenceKind::limit;
  c.compares = compares;
  c.quantity = "max |H/H_lim − 1|";
  c.unit = "-";
  c.tolerance = std::move(tolerance);
  c.level = Level::quick;
  c.cost = 0.05;
  c.catches = std::move(catches);
  c.measure = std::move(m);
  return c;
}

constexpr double kCylinderLowKa = 1e-3;  // 608 ring: 9.4 Hz
constexpr double kSphereLowKa = 1e-2;    // 608 ball: 275 Hz

std::vector<Check> low_ka_limits() {
  std::vector<Check> out;
  // kr = 0.01 (near field) and kr = 1 (where the sound speed matters).
  const std::vector<Probe> cylinder_probes = {{10, 30}, {1000, 120}};
  out.push_back(limit_check(
      "acoustics.low-ka.cylinder-dipole",
      "value: |H/H_lim − 1|, H the toolkit's exact cylinder dipole (608 ring) at ka = 1e-3, kr = "
      "0.01 and 1; reference: 0, H_lim = (π/2)ρ₀c₀(ka)² cos ψ H₁⁽²⁾(kr), the leading order in ka",
      absolute(ref::leading_order_bound(kCylinderLowKa),
               "the next term of H₁'(ka) beyond −2i/(πx²) (A&S 9.1.11): (x²/2)(|ln(x/2)| "
               "+ 2) at x = ka = 1e-3"),
      {"sound-speed-x1.02", "microphone-distance-x1.05"}, [=](const Context& ctx) {
        Outcome o = limit_deviation(ctx, "cylinder-dipole", seed000_ring_radius(), kCylinderLowKa,
                                    cylinder_probes, [](double ka, double ra, double c) {
                                      return ref::cylinder_dipole_low_ka(ka, ka * ra, c);
                                    });
        o.figures.push_back(low_ka_figure(ctx));
        return o;
      }));
  // kr = 0.05 (near field, the 1/r² term) and kr = 3.
  const std::vector<Probe> sphere_probes = {{5, 30}, {300, 120}};
  out.push_back(limit_check(
      "acoustics.low-ka.oscillating-sphere",
      "value: |H/H_lim − 1|, H the toolkit's oscillating sphere (608 ball) at ka = 0.01, kr = "
      "0.05 and 3; reference: 0, H_lim = −(ρ₀c₀(ka)²(a/r)/2) cos ψ (1 − i/(kr)) e^{−ikr}",
      absolute(std::pow(kSphereLowKa, 3) / 6 + 1e-12,
               "exact H/H_lim = e^{ika}/(1 + ika − (ka)²/2), so |H/H_lim − 1| ≤ (ka)³/6 "
               "(the remainder of e^{ix} after three terms) = 1.67e-7, plus 1e-12 round-off"),
      {"sound-speed-x1.02", "microphone-distance-x1.05"}, [=](const Context& ctx) {
        return limit_deviation(ctx, "oscillating-sphere", seed000_ball_radius(), kSphereLowKa,
                               sphere_probes, [](double ka, double ra, double c) {
                                 return ref::sphere_dipole_low_ka(ka, ka * ra, ra, c);
                               });
      }));
  // Seed 000's ring form needs kr ≪ 1 as well: kr = 0.01.
  const double kr = 0.01;
  out.push_back(limit_check(
      "acoustics.low-ka.cylinder-dipole-paper",
      "value: |H_paper/H − 1|, H_paper the toolkit's seed 000 eq. (19) form (608 ring) at ka = "
      "1e-3, kr = 0.01; reference: 0, H the exact cylinder dipole (Hankel integrals): the paper's "
      "form is its leading order in ka and kr",
      absolute(ref::small_argument_bound(kCylinderLowKa) + ref::small_argument_bound(kr),
               "the small-argument H₁ and H₁' are each relatively wrong by ≤ (x²/2)(|ln(x/2)| "
               "+ 1) (A&S 9.1.11), at x = ka = 1e-3 and x = kr = 0.01"),
      {"microphone-distance-x1.05"}, [=](const Context& ctx) {
        return limit_deviation(ctx, "cylinder-dipole-paper", seed000_ring_radius(), kCylinderLowKa,
                               {{kr / kCylinderLowKa, 30}}, [](double ka, double ra, double c) {
                                 return ref::cylinder_field(1, ka, ka * ra, c);
                               });
      }));
  return out;
}

// --- the time-domain filter ------------------------------------------------------------------

// Two tones of the ring's velocity on DFT bins, filtered by radiate_fixed (the path every
// microphone pressure takes): a periodic record's DFT is exact, so p_rms² = Σ |H(ω_i)|² U_i²/2.
Check time_domain_tone() {
  constexpr double kRate = 20000.0;  // Hz
  constexpr std::size_t kSamples = 1000;
  const double tones[2][2] = {{1000.0, 1e-3}, {5000.0, 4e-4}};  // f [Hz], U [m/s]
  constexpr double kR = 0.01, kAngle = 0.5235987755982988;      // point at 10 mm, 30°
  Check c;
  c.id = "acoustics.time-domain.ring-tones";
  c.family = "acoustics";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: p_rms of radiate_fixed (FFT → H → inverse FFT) for the 608 ring's cylinder dipole "
      "driven by 1 mm/s at 1 kHz + 0.4 mm/s at 5 kHz (bins of 1000 samples at 20 kHz), at 10 mm, "
      "30°; reference: sqrt(Σ |H_ref(ω_i)|² U_i²/2), H_ref the exact dipole from Hankel integrals";
  c.quantity = "p_rms";
  c.unit = "Pa";
  c.tolerance = relative(1e-9,
                         "the DFT of whole periods is exact up to FFT round-off (~1e-15 log N); "
                         "the reference's field is good to 1e-9 (the bound of acoustics.exact.*)");
  c.level = Level::quick;
  c.cost = 0.05;
  c.catches = {"sound-speed-x1.02", "microphone-distance-x1.05"};
  c.measure = [=](const Context& ctx) {
    const double a = seed000_ring_radius();
    const auto source = make_source("cylinder-dipole", a, ctx.air());
    std::vector<double> u(kSamples + 1, 0.0);  // the record and the sample after it
    double reference = 0;
    for (const auto& t : tones) {
      for (std::size_t n = 0; n <= kSamples; ++n)
        u[n] += t[1] * std::cos(2 * pi * t[0] * static_cast<double>(n) / kRate);
      const double ka = 2 * pi * t[0] * a / ref::kSoundSpeed;
      reference +=
          std::norm(ref::cylinder_field(1, ka, ka * kR / a, std::cos(kAngle))) * t[1] * t[1] / 2;
    }
    RealFft fft(kSamples);
    const Microphone m = ctx.microphone(kR, kAngle);
    const auto p = radiate_fixed(*source, u, kRate, m.radius, std::cos(kAngle), fft);
    return Outcome{root_mean_square(p), std::sqrt(reference), "N = 1000, f_s = 20 kHz", {}};
  };
  return c;
}

}  // namespace

std::vector<Check> acoustics_checks() {
  std::vector<Check> all = exact_sources();
  for (auto& c : low_ka_limits()) all.push_back(std::move(c));
  all.push_back(time_domain_tone());
  return all;
}

}  // namespace bearing::verify
