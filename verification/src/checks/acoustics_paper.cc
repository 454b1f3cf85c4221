// Seed 000's source forms (docs/model.md §8, sources.h): the ring's eq. (19) as derived and the
// ball's eq. (23), against the forms written in acoustics_reference.cc. Their agreement with the
// exact fields at low ka is checked in acoustics.cc (acoustics.low-ka.cylinder-dipole-paper); here
// their departure at high ka is the checked value itself, so the report shows its size.

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "../context.h"
#include "../families.h"
#include "acoustics_reference.h"
#include "acoustics_shared.h"
#include "bearing/constants.h"

namespace bearing::verify {

namespace {

namespace ref = acoustic_reference;
using cd = std::complex<double>;

// The one-third-octave centres of the audible band, 100 Hz – 20 kHz.
const double kBand[] = {100,  125,  160,  200,  250,  315,  400,  500,  630,   800,   1000,  1250,
                        1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000, 12500, 16000, 20000};
constexpr double kPointA = 0.01;  // seed 000's point A, 10 mm from the centre [m]
constexpr double kFar = 1.0;      // [m]
constexpr double kAngle = pi / 6;

// Level of the paper ring form over the exact one [dB], both the toolkit's, at f and r.
double toolkit_departure(const Context& ctx, double f, double r) {
  const double a = seed000_ring_radius();
  const auto paper = make_source("cylinder-dipole-paper", a, ctx.air());
  const auto exact = make_source("cylinder-dipole", a, ctx.air());
  const Microphone m = ctx.microphone(r, kAngle);
  const double w = 2 * pi * f, c = std::cos(kAngle);
  return tone_level(paper->transfer(w, m.radius, c)) - tone_level(exact->transfer(w, m.radius, c));
}

double reference_departure(double f, double r) {
  const double a = seed000_ring_radius(), ka = 2 * pi * f * a / ref::kSoundSpeed;
  const double c = std::cos(kAngle);
  return tone_level(ref::paper_cylinder_dipole(ka, ka * r / a, c)) -
         tone_level(ref::cylinder_field(1, ka, ka * r / a, c));
}

Figure departure_figure(const Context& ctx) {
  Figure fig;
  fig.name = "acoustics-paper-ring-departure";
  fig.title = "Seed 000 eq. (19) against the exact cylinder dipole (608 ring, ψ = 30°)";
  fig.x_label = "frequency f [Hz]";
  fig.y_label = "L_paper − L_exact [dB]";
  fig.log_x = true;
  Series near{"at 10 mm (point A), toolkit", {}, {}, "line+marker"};
  Series far{"at 1 m, toolkit", {}, {}, "line+marker"};
  for (double f : kBand) {
    near.x.push_back(f);
    near.y.push_back(toolkit_departure(ctx, f, kPointA));
    far.x.push_back(f);
    far.y.push_back(toolkit_departure(ctx, f, kFar));
  }
  fig.series = {near, far};
  const double kr_one = ref::kSoundSpeed / (2 * pi * kPointA);
  fig.markers = {{kr_one, "kr = 1 at 10 mm"},
                 {ref::kSoundSpeed / (2 * pi * seed000_ring_radius()), "ka = 1"}};
  return fig;
}

Check ring_departure() {
  Check c;
  c.id = "acoustics.paper.cylinder-dipole-departure";
  c.family = "acoustics";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: L_paper − L_exact [dB] of the toolkit's seed 000 eq. (19) ring form against its "
      "exact cylinder dipole (608 ring, a = 5.79 mm) at point A (10 mm, 30°) and 20 kHz (ka = "
      "2.1, kr = 3.7); reference: the same difference from the forms written in the check "
      "(small-argument Hankel functions against Bessel's and Schläfli's integrals)";
  c.quantity = "ΔL at 20 kHz";
  c.unit = "dB";
  c.tolerance = absolute(1e-7,
                         "the reference's fields are good to 1e-9 relative (the bound of "
                         "acoustics.exact.*): ≤ 1e-8 dB on a difference of two levels, rounded "
                         "up to 1e-7 dB");
  c.level = Level::quick;
  c.cost = 0.1;
  c.catches = {"sound-speed-x1.02", "microphone-distance-x1.05"};
  c.measure = [](const Context& ctx) {
    const double f = 20000;
    Outcome o{toolkit_departure(ctx, f, kPointA), reference_departure(f, kPointA), "", {}};
    o.detail = "The paper's form departs from the exact field by " + fmt(o.value) +
               " dB at 10 mm and " + fmt(toolkit_departure(ctx, f, kFar)) +
               " dB at 1 m (20 kHz); at 1 m it is already " +
               fmt(toolkit_departure(ctx, 1000, kFar)) +
               " dB at 1 kHz: its H₁(kr) ≈ kr/2 grows with distance (docs/model.md §8: it needs "
               "kr ≪ 1)";
    o.figures.push_back(departure_figure(ctx));
    return o;
  };
  return c;
}

// The ball's eq. (23) over the grid of ka and distances, through transfer() and series().
Check ball_eq23() {
  Check c;
  c.id = "acoustics.paper.pulsating-sphere-eq23";
  c.family = "acoustics";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: |H/H_ref − 1|, H the toolkit's pulsating-sphere-paper (608 ball, a = 1.98 mm) at "
      "ka = 1e-3 … 5, r = a … 1 m; reference: 0, H_ref seed 000 eq. (23) as printed, ρ₀c₀ k a² "
      "e^{iθ}/(r √(1 + (ka)²)), θ = arctan(1/(ka))";
  c.quantity = "max |H/H_ref − 1|";
  c.unit = "-";
  c.tolerance = absolute(1e-12,
                         "both sides are elementary closed forms in double precision: round-off "
                         "of ~10 operations, a few 1e-16 each");
  c.level = Level::quick;
  c.cost = 0.01;
  c.catches = {"sound-speed-x1.02", "microphone-distance-x1.05"};
  c.measure = [](const Context& ctx) {
    const double a = seed000_ball_radius();
    const auto paper = make_series_source("pulsating-sphere-paper", a, ctx.air());
    const double ka_grid[] = {1e-3, 1e-2, 0.1, 0.3, 1.0, 2.0, 5.0};
    const double r_grid[] = {a, 0.01, 0.1, 1.0};
    double worst = 0;
    for (double ka : ka_grid)
      for (double r : r_grid) {
        const double w = omega_of(ka, a), rm = ctx.microphone(r, 0).radius;
        const cd h_ref = ref::paper_pulsating_sphere(ka, r / a);
        worst = std::max({worst, std::abs(paper->transfer(w, rm, 1) / h_ref - 1.0),
                          std::abs(paper->series(w, rm, 1) / h_ref - 1.0)});
      }
    // What the form leaves out: the exact pulsating sphere's delay e^{−ik(r−a)}.
    const double ka = 2 * pi * 20000 * a / ref::kSoundSpeed;
    const cd ratio = ref::paper_pulsating_sphere(ka, 1 / a) / ref::sphere_field(0, ka, ka / a, 1);
    return Outcome{std::isfinite(worst) ? worst : 1e300,
                   0.0,
                   "against the exact pulsating sphere at 20 kHz, 1 m: modulus ratio − 1 = " +
                       fmt(std::abs(ratio) - 1) + ", phase " + fmt(std::arg(ratio)) +
                       " rad (k(r − a) mod 2π: eq. (23) has no propagation delay)",
                   {}};
  };
  return c;
}

}  // namespace

std::vector<Check> acoustics_paper_checks() {
  return {ring_departure(), ball_eq23()};
}

}  // namespace bearing::verify
