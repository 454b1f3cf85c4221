// Film family (issue 43): the EHL film of a ball–race contact (ehl_film.h) and the load–approach
// law with the film in series (film_law.h) against references written here — Hamrock & Dowson's
// central film from the geometry's definitions, the acceptance case (the 6205 at 1800
// rpm under 2 kN), the dry limit of a vanishing viscosity, the film's stiffness against Hertz's
// under heavy load, and the squeeze-film damping against Reynolds' sphere and a numerical solution
// of the squeeze Reynolds equation (squeeze_film_reference.h). The Hertz constants of the
// references are the checks' own exact solution (hertz_reference.h).

#include <cmath>
#include <stdexcept>
#include <string>

#include "../context.h"
#include "../families.h"
#include "bearing/ehl_film.h"
#include "bearing/film_law.h"
#include "bearing/lubricant.h"
#include "bearing/presets.h"
#include "check_util.h"
#include "hertz_reference.h"
#include "squeeze_film_reference.h"

namespace bearing::verify {

namespace {

using reference::exact_hertz;
using reference::HertzContact;
using reference::series_constant;

// The case: the 6205 at 1800 rpm, outer ring fixed, cage rolling purely; 0.02 Pa s,
// 2e-8 1/Pa, σ 0.1 µm; F_r = 2 kN along −y with a ball on the load line.
constexpr double kRpm = 1800.0, kEta = 0.02, kAlpha = 2e-8, kRadialLoad = 2000.0;
const char* const kBearing = "6205";

double omega() { return kRpm * 2.0 * M_PI / 60.0; }

Lubricant oil() {
  Lubricant l;
  l.viscosity = kEta;
  l.pressure_viscosity = kAlpha;
  l.roughness = 1e-7;
  return l;
}

Check row(std::string id, ReferenceKind kind, std::string compares, std::string quantity,
          std::string unit, Tolerance tol, std::vector<std::string> catches) {
  Check c;
  c.id = std::move(id);
  c.family = "film";
  c.reference = kind;
  c.compares = std::move(compares);
  c.quantity = std::move(quantity);
  c.unit = std::move(unit);
  c.tolerance = std::move(tol);
  c.catches = std::move(catches);
  return c;
}

// ---- the reference, by hand --------------------------------------------------------------

// A ball on `race` of the unperturbed preset, from the definitions: the ball's radius D/2, the
// race's (d_m ∓ D)/2 along the rolling direction (convex inner, concave outer), the groove's f D
// (concave); E' = 2/((1−ν_b²)/E_b + (1−ν_r²)/E_r); u = ω_i (d_m² − D²)/(4 d_m) (pure rolling,
// contact angle 0: the 6205's); k the checks' own exact Hertz ellipticity.
struct Hand {
  double rx, ry, e_prime, u, k, k_fit;
};

Hand hand(Race race) {
  const Bearing b = preset(kBearing);
  const double r = 0.5 * b.ball_diameter, dm = b.pitch_diameter, d = b.ball_diameter;
  Hand h{};
  h.rx = race == Race::inner ? 1.0 / (1.0 / r + 2.0 / (dm - d)) : 1.0 / (1.0 / r - 2.0 / (dm + d));
  const double f = race == Race::inner ? b.inner_conformity : b.outer_conformity;
  h.ry = 1.0 / (1.0 / r - 1.0 / (f * d));
  const auto c = [](const Material& m) { return (1 - m.poisson * m.poisson) / m.young; };
  h.e_prime = 2.0 / (c(b.ball) + c(b.rings));
  h.u = omega() * (dm * dm - d * d) / (4.0 * dm);
  h.k = exact_hertz(b, race).kappa;
  h.k_fit = 1.0339 * std::pow(h.ry / h.rx, 0.636);
  return h;
}

// Hamrock & Dowson (1977): h_c = R_x 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73 k}).
double hd_central(const Hand& h, double k, double eta, double q) {
  const double U = eta * h.u / (h.e_prime * h.rx), G = kAlpha * h.e_prime,
               W = q / (h.e_prime * h.rx * h.rx);
  return h.rx * 2.69 * std::pow(U, 0.67) * std::pow(G, 0.53) * std::pow(W, -0.067) *
         (1 - 0.61 * std::exp(-0.73 * k));
}

// The toolkit's films of the (perturbable) preset.
BallFilms toolkit_films(const Context& ctx) {
  const Bearing b = ctx.bearing(kBearing);
  const ContactConstants cc = ctx.contact(b, HertzMethod::exact);
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  return ball_films(b, cc, oil(), omega(), 0.5 * omega() * (1 - g));
}

// Q_max under 2 kN at zero clearance with a ball on the load line, Z balls: Q_max = F_r / Σ_j
// [cos ψ_j]_+^{5/2} exactly (independent of K) — Stribeck's 4.37 F_r/Z to 0.4 % for Z = 9.
double stribeck_q_max(int z) {
  double s = 0;
  for (int j = 0; j < z; ++j) {
    const double c = std::cos(2.0 * M_PI * j / z);
    if (c > 0) s += std::pow(c, 2.5);
  }
  return kRadialLoad / s;
}

// ---- (i) the film against Hamrock–Dowson -------------------------------------------------

Check hamrock_dowson(Race race) {
  const std::string name = to_string(race);
  Check c = row("film.hamrock-dowson.6205." + name, ReferenceKind::closed_form,
                "value: the lumped central film h_c of the 6205's " + name +
                    " contact at 1800 rpm, Q = 500 N, 0.02 Pa s, 2e-8 1/Pa; reference: Hamrock & "
                    "Dowson's R_x 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k)) with R_x, "
                    "R_y, E', u written from the geometry here and k the checks' exact Hertz "
                    "ellipticity",
                "h_c", "m",
                relative(1e-9,
                         "the same formula from the same inputs, except k: the checks' exact "
                         "Hertz ellipticity agrees with the library's to its root tolerance "
                         "(1e-10 relative), which moves the k factor by far less (its "
                         "derivative 0.45 e^(-0.73 k) k < 1e-2 at k > 7); the powers' round-off "
                         "1e-14"),
                {"pitch-diameter-x1.01"});
  c.measure = [race](const Context& ctx) {
    const BallFilms f = toolkit_films(ctx);
    const FilmContact& fc = race == Race::inner ? f.inner : f.outer;
    const Hand h = hand(race);
    const double q = 500.0;
    Outcome o{fc.central_thickness(q), hd_central(h, h.k, kEta, q), "", {}};
    o.detail = fmt("R_x %.5g m, R_y %.5g m, k %.4f, u %.4f m/s; h_min %.4g m; within the fit's "
                   "span (k 1-8, U, W, G of their runs): ",
                   h.rx, h.ry, h.k, h.u, fc.minimum_thickness(q)) +
               (fc.within_fit() ? "yes" : "no");
    return o;
  };
  return c;
}

// ---- (ii) the acceptance ---------------------------------------------------------

Check acceptance(Race race) {
  const std::string name = to_string(race);
  Check c = row(
      "film.acceptance.6205-1800rpm-2kn." + name, ReferenceKind::closed_form,
      "value: the lumped central film at the 6205's " + name +
          " contact of its most loaded ball (the toolkit's static solution, zero clearance, 2 kN "
          "radial, a ball on the load line), 1800 rpm, 0.02 Pa s, 2e-8 1/Pa; reference: "
          "Hamrock-Dowson by hand with their own fit k = 1.0339 (R_y/R_x)^0.636 and Q_max = "
          "F_r / sum cos^2.5 psi_j (Stribeck's 4.37 F_r/Z to 0.4 %)",
      "h_c", "m",
      relative(1e-3,
               "the issue asks 5 %; the only difference is k (exact Hertz against the fit, "
               "which Hamrock & Dowson state within a few per cent: |dk/k| <= 3 %), which at "
               "k >= 7 moves the factor 1 - 0.61 e^(-0.73 k) by at most 0.45 e^(-5.1) x 0.03 "
               "x 9.5 < 8e-4; the static solution's force balance 1e-12"),
      {"pitch-diameter-x1.01"});
  c.measure = [race](const Context& ctx) {
    const Bearing b = ctx.bearing(kBearing);
    const ContactConstants cc = ctx.contact(b, HertzMethod::exact);
    const StaticLoadResult s =
        ctx.static_load(b.balls, cc, 0.0, Eigen::Vector2d(0, -kRadialLoad), -M_PI / 2);
    const BallFilms f = toolkit_films(ctx);
    const FilmContact& fc = race == Race::inner ? f.inner : f.outer;
    const Hand h = hand(race);
    const double q_ref = stribeck_q_max(preset(kBearing).balls);
    Outcome o{fc.central_thickness(s.q_max), hd_central(h, h.k_fit, kEta, q_ref), "", {}};
    o.detail = fmt("Q_max %.2f N (reference %.2f N, Stribeck 4.37 F_r/Z = %.2f N); k %.4f, fit "
                   "%.4f; h_min %.4g m",
                   s.q_max, q_ref, 4.37 * kRadialLoad / b.balls, fc.ellipticity, h.k_fit,
                   fc.minimum_thickness(s.q_max));
    return o;
  };
  return c;
}

// ---- (iii) vanishing viscosity: dry Hertz ------------------------------------------------

Check dry_limit() {
  Check c = row(
      "film.dry-limit.6205", ReferenceKind::limit,
      "value: the load of the film law (film_law.h) of one 6205 ball between both races at the "
      "approach 10 um with eta = 1e-10 Pa s (both films in series); reference: dry Hertz K "
      "delta^1.5 with the checks' exact K",
      "Q", "N",
      relative(1e-6,
               "Q = K (delta + h_c(Q))^n, so 0 <= Q/(K delta^n) - 1 <= n h/delta to first "
               "order, h = h_i + h_o; at 0.02 Pa s h_c < 0.25 um a race for Q >= 100 N "
               "(Hamrock-Dowson here: 0.16 and 0.19 um at 500 N, x 5^0.067 at 100 N), and it "
               "falls as eta^0.67: x (1e-10/0.02)^0.67 = 2.8e-6, so h < 1.4e-12 m and "
               "n h/delta < 2.1e-7 at delta = 10 um; the exact K's root tolerance 1e-10"),
      {"contact-constant-x1.03", "contact-exponent+0.05"});
  c.measure = [](const Context& ctx) {
    const Bearing b = ctx.bearing(kBearing);
    const ContactConstants cc = ctx.contact(b, HertzMethod::exact);
    // Below lubricant.viscosity's range (1e-6 Pa s): set on the films themselves.
    BallFilms f = toolkit_films(ctx);
    f.inner.viscosity = f.outer.viscosity = 1e-10;
    const FilmLaw law{cc.K, cc.exponent,
                      f.inner.central_coefficient() + f.outer.central_coefficient()};
    const Bearing ref = preset(kBearing);
    const double k = series_constant(exact_hertz(ref, Race::inner).K,
                                     exact_hertz(ref, Race::outer).K);
    const double delta = 10e-6;
    Outcome o{law.load(delta), k * std::pow(delta, 1.5), "", {}};
    const BallFilms oil_films = toolkit_films(ctx);
    const FilmLaw with_oil{cc.K, cc.exponent,
                           oil_films.inner.central_coefficient() +
                               oil_films.outer.central_coefficient()};
    o.detail = fmt("the two films at that load %.3g m; at 0.02 Pa s the load would be %.6g N",
                   law.film(o.value), with_oil.load(delta));
    return o;
  };
  return c;
}

// ---- (iv) heavy load: the film far stiffer than Hertz -------------------------------------

// k_f = Q/(0.067 h_c) ∝ Q^1.067 against k_H = n Q/δ_H ∝ Q^(1 − 1/n): the ratio grows as
// Q^(0.067 + 1/n), 0.7337 for Hertz.
Check stiffness_exponent() {
  Check c = row("film.stiffness-ratio-exponent.6205", ReferenceKind::closed_form,
                "value: d ln(k_f/k_H) / d ln Q of the 6205's inner contact between 400 N and 4 kN "
                "(k_f the film's stiffness, k_H = n Q/delta_H the toolkit's Hertz stiffness); "
                "reference: 0.067 + 1/1.5 = 0.7337 (Hamrock-Dowson's load exponent and Hertz's)",
                "exponent", "-",
                absolute(1e-10, "exact power laws: the slope over a decade is round-off only "
                                "(ulps of the logs, 1e-15, over ln 10)"),
                {"contact-exponent+0.05"});
  c.measure = [](const Context& ctx) {
    const Bearing b = ctx.bearing(kBearing);
    const RaceContact rc = ctx.race_contact(b, Race::inner, HertzMethod::exact);
    const FilmContact f = toolkit_films(ctx).inner;
    auto ratio = [&](double q) { return f.stiffness(q) / (rc.exponent * q / rc.approach(q)); };
    return Outcome{std::log(ratio(4000.0) / ratio(400.0)) / std::log(10.0), 0.067 + 1.0 / 1.5,
                   fmt("k_f/k_H %.3g at 400 N, %.3g at 4 kN", ratio(400.0), ratio(4000.0)), {}};
  };
  return c;
}

// At the ISO 76 pressure limit the film's stiffness against Hertz's, both by hand.
Check heavy_load() {
  Check c = row("film.heavy-load-stiffness.6205", ReferenceKind::limit,
                "value: k_f/k_H of the 6205's inner contact at the load of the ISO 76 limit "
                "p_max = 4.2 GPa (toolkit: k_f = Q/(0.067 h_c), k_H = n Q/delta_H); reference: "
                "the same ratio by hand, h_c by Hamrock-Dowson here and delta_H of the checks' "
                "exact Hertz solution; the ratio, ~2e3, is the heavy-load limit k_f >> k_H "
                "(the film law's tangent is Hertz's)",
                "k_f/k_H", "-",
                relative(1e-9,
                         "the same closed forms from independent code: the exact Hertz "
                         "solutions agree to their root tolerance 1e-10 (delta and kappa), the "
                         "powers to round-off"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [](const Context& ctx) {
    const Bearing b = ctx.bearing(kBearing);
    const RaceContact rc = ctx.race_contact(b, Race::inner, HertzMethod::exact);
    const FilmContact f = toolkit_films(ctx).inner;
    const HertzContact ref = exact_hertz(preset(kBearing), Race::inner);
    const double q = ref.load_at_peak_pressure(4.2e9);
    const Hand h = hand(Race::inner);
    const double value = f.stiffness(q) / (rc.exponent * q / rc.approach(q));
    const double reference =
        (q / (0.067 * hd_central(h, h.k, kEta, q))) / (1.5 * q / ref.approach(q));
    return Outcome{value, reference, fmt("Q = %.0f N at 4.2 GPa", q), {}};
  };
  return c;
}

// ---- (v) damping -------------------------------------------------------------------------

Check damping_sphere() {
  Check c = row("film.damping.reynolds-sphere", ReferenceKind::closed_form,
                "value: the squeeze-film damping of the 6205's inner film with R_y set to R_x "
                "(a sphere on a plane of radius R_x), Q = 500 N; reference: Reynolds' 6 pi eta "
                "R^2 / h with R = R_x by hand and h = h_c by Hamrock-Dowson here",
                "c", "N s/m",
                relative(1e-9, "12 pi eta R^3/(2 R h) is 6 pi eta R^2/h: round-off, and h_c "
                               "as in film.hamrock-dowson (1e-9)"),
                {"pitch-diameter-x1.01"});
  c.measure = [](const Context& ctx) {
    FilmContact f = toolkit_films(ctx).inner;
    f.ry = f.rx;
    const Hand h = hand(Race::inner);
    const double q = 500.0;
    const double hc = hd_central(h, h.k, kEta, q);
    return Outcome{f.damping(q), 6 * M_PI * kEta * h.rx * h.rx / hc, "", {}};
  };
  return c;
}

// The ellipsoid's damping against the numerical squeeze solution, Richardson-extrapolated.
Check damping_numerical(double ratio, const std::string& tag) {
  Check c = row(
      "film.damping.squeeze-reynolds." + tag, ReferenceKind::closed_form,
      "value: the squeeze-film damping 12 pi eta (R_x R_y)^1.5 / ((R_x + R_y) h_c) of the 6205's "
      "inner film (R_x, h_c by the toolkit; R_y = " +
          (ratio > 0 ? fmt("%.0f", ratio) + " R_x" : std::string("its own, ~33 R_x")) +
          "), Q = 900 N; reference: the squeeze Reynolds equation div(h^3 grad p) = 12 eta "
          "dh/dt solved by finite volumes on a stretched 128 x 128 grid of the quadrant of "
          "[-1000, 1000]^2 (scaled), p = 0 on its edge, Richardson-extrapolated from 64 and 128 "
          "(R_x by hand, h from Hamrock-Dowson here)",
      "c", "N s/m",
      relative(1e-4,
               "the reference's error: Richardson's extrapolation of the second-order scheme "
               "leaves O(h^4), bounded by the spread of the extrapolations from (32, 64) and "
               "(64, 128), which the check requires below 5e-5 (else it fails: the reference is "
               "under-resolved), and the finite domain's shortfall < 2/L^2 = 2e-6 "
               "(squeeze_film_reference.h); 1e-4 holds their sum"),
      {"pitch-diameter-x1.01"});
  c.cost = 0.4;
  c.measure = [ratio](const Context& ctx) {
    FilmContact f = toolkit_films(ctx).inner;
    const Hand h = hand(Race::inner);
    const double r = ratio > 0 ? ratio : h.ry / h.rx;
    f.ry = f.rx * r;
    const double q = 900.0;
    const double hc = hd_central(h, h.k, kEta, q);
    double i[3];
    const int n[3] = {32, 64, 128};
    for (int j = 0; j < 3; ++j) i[j] = squeeze_reference::scaled_integral(1.0 / r, n[j]);
    const double r1 = (4 * i[1] - i[0]) / 3, r2 = (4 * i[2] - i[1]) / 3;
    const double spread = std::fabs(r1 / r2 - 1);
    if (!(spread < 5e-5))
      throw std::runtime_error(fmt("the squeeze reference is under-resolved: Richardson spread "
                                   "%.2e >= 5e-5",
                                   spread));
    const double scale = 48.0 * kEta * h.rx * std::sqrt(h.rx * h.rx * r) / hc;
    Outcome o{f.damping(q), scale * r2, "", {}};
    o.detail = fmt("R_y/R_x %.2f; closed-form error of I at N = 32, 64, 128: %.2e, %.2e, %.2e; "
                   "Richardson spread %.1e",
                   r, i[0] / (M_PI / (4 * (1 + 1 / r))) - 1, i[1] / (M_PI / (4 * (1 + 1 / r))) - 1,
                   i[2] / (M_PI / (4 * (1 + 1 / r))) - 1, spread);
    return o;
  };
  return c;
}

}  // namespace

std::vector<Check> film_checks() {
  return {hamrock_dowson(Race::inner),
          hamrock_dowson(Race::outer),
          acceptance(Race::inner),
          acceptance(Race::outer),
          dry_limit(),
          stiffness_exponent(),
          heavy_load(),
          damping_sphere(),
          damping_numerical(1.0, "sphere"),
          damping_numerical(-1.0, "6205-inner")};
}

}  // namespace bearing::verify
