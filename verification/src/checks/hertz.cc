// Hertz family, closed forms: the toolkit's Hertz constants of every preset bearing against the
// checks' own exact Hertz solution (hertz_reference.h), and the two approximate methods
// (Hamrock–Brewe, Harris's table) against exact Hertz within their accuracy.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../context.h"
#include "../families.h"
#include "bearing/presets.h"
#include "check_util.h"
#include "hertz_reference.h"

namespace bearing::verify {

namespace {

using reference::exact_hertz;

// The closed forms are exact to the root tolerances: κ to 1e-14 (reference) and 1e-15 (toolkit),
// GSL's elliptic integrals to ~1e-15; K ∝ κ E^{1/2} K(e)^{-3/2} carries these at O(1) gain.
const char* kRoundOff =
    "both sides solve Hertz's ellipticity equation to 1e-14 relative (Brent) with GSL's "
    "double-precision elliptic integrals; through K ~ kappa E^1/2 K(e)^-3/2 that is < 1e-13, so "
    "1e-9 is round-off with a wide margin";

Check exact_k(const std::string& name, Race race) {
  Check c;
  c.id = "hertz.exact-k." + name + "." + to_string(race);
  c.family = "hertz";
  c.reference = ReferenceKind::closed_form;
  c.compares = std::string("value: the lumped exact-Hertz load-deflection constant K of the ") +
               to_string(race) + " race of the " + name +
               "; reference: Hertz's K from the check's own curvatures, Brent root of F(kappa) "
               "and GSL elliptic integrals (Hamrock's form of the equations)";
  c.quantity = std::string("K_") + to_string(race);
  c.unit = "N/m^1.5";
  c.tolerance = relative(1e-9, kRoundOff);
  c.catches = {"contact-constant-x1.03", "pitch-diameter-x1.01"};
  c.measure = [name, race](const Context& ctx) {
    const RaceContact rc = ctx.race_contact(ctx.bearing(name), race, HertzMethod::exact);
    const auto ref = exact_hertz(preset(name), race);
    Outcome o{rc.K,
              ref.K,
              fmt("F(rho) = %.6f, kappa = %.4f (reference %.4f), sum rho = %.2f 1/m", ref.f_rho,
                  rc.shape.ellipticity, ref.kappa, ref.sum_rho),
              {}};
    return o;
  };
  return c;
}

// The figure of K per bearing (all presets, three methods, both races), on log axes over D.
Figure k_per_bearing(const Context& ctx) {
  Figure f;
  f.name = "hertz-k-per-bearing";
  f.title = "Hertz load-deflection constant K of every preset bearing";
  f.x_label = "ball diameter D [m]";
  f.y_label = "K [N/m^1.5]";
  f.log_x = f.log_y = true;
  const struct {
    HertzMethod m;
    const char* label;
  } methods[] = {{HertzMethod::exact, "toolkit exact"},
                 {HertzMethod::hamrock_brewe, "toolkit Hamrock-Brewe"},
                 {HertzMethod::harris_table, "toolkit Harris table"}};
  for (Race race : {Race::inner, Race::outer}) {
    Series ref{std::string("reference exact, ") + to_string(race), {}, {}, "marker"};
    std::vector<Series> tk;
    for (const auto& m : methods)
      tk.push_back({std::string(m.label) + ", " + to_string(race), {}, {}, "marker"});
    for (const auto& name : preset_names()) {
      const double D = preset(name).ball_diameter;
      ref.x.push_back(D);
      ref.y.push_back(exact_hertz(preset(name), race).K);
      for (std::size_t i = 0; i < tk.size(); ++i) {
        tk[i].x.push_back(D);
        tk[i].y.push_back(ctx.race_contact(ctx.bearing(name), race, methods[i].m).K);
      }
    }
    f.series.push_back(ref);
    for (auto& s : tk) f.series.push_back(s);
  }
  return f;
}

// Semi-axes of both races at a stated load; the value is the one of the four (a, b per race)
// farthest from its reference, so one row covers the ellipse of a bearing.
constexpr double kSemiAxisLoad = 100.0;  // [N]

Check semi_axes(const std::string& name) {
  Check c;
  c.id = "hertz.semi-axes." + name;
  c.family = "hertz";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: the lumped exact-Hertz semi-axis (a or b, inner or outer race: the one "
      "farthest from its reference) of the " +
      name +
      " at Q = 100 N; reference: Hertz's a = (6 kappa^2 E Q R / (pi E'))^1/3, "
      "b = (6 E Q R / (pi kappa E'))^1/3 from the check's own solution";
  c.quantity = "a or b";
  c.unit = "m";
  c.tolerance = relative(1e-9, kRoundOff);
  c.catches = {"pitch-diameter-x1.01", "ellipse-minor-x1.01"};
  c.measure = [name](const Context& ctx) {
    Outcome worst{0, 1, "", {}};
    double worst_dev = -1;
    std::string all;
    for (Race race : {Race::inner, Race::outer}) {
      const RaceContact rc = ctx.race_contact(ctx.bearing(name), race, HertzMethod::exact);
      const auto ref = exact_hertz(preset(name), race);
      const double v[2] = {rc.semi_major(kSemiAxisLoad), rc.semi_minor(kSemiAxisLoad)};
      const double r[2] = {ref.semi_major(kSemiAxisLoad), ref.semi_minor(kSemiAxisLoad)};
      for (int i = 0; i < 2; ++i) {
        const double dev = std::abs(v[i] / r[i] - 1);
        if (dev > worst_dev) {
          worst_dev = dev;
          worst.value = v[i];
          worst.reference = r[i];
          worst.detail = std::string(i == 0 ? "a" : "b") + ", " + to_string(race) + " race";
        }
      }
      all += std::string("; ") + to_string(race) + fmt(" a = %.6g m, b = %.6g m", v[0], v[1]);
    }
    worst.detail += " is the farthest" + all;
    return worst;
  };
  return c;
}

// The toolkit's K by `method` against the check's exact K on the race where they differ most;
// `describe` writes each race's line of the detail.
template <typename Describe>
Outcome worst_race_k(const Context& ctx, const std::string& name, HertzMethod method,
                     Describe describe) {
  Outcome o{0, 1, "", {}};
  double worst = -1;
  for (Race race : {Race::inner, Race::outer}) {
    const RaceContact rc = ctx.race_contact(ctx.bearing(name), race, method);
    const auto ref = exact_hertz(preset(name), race);
    o.detail += std::string(to_string(race)) + describe(rc, ref);
    const double dev = std::abs(rc.K / ref.K - 1);
    if (dev > worst) worst = dev, o.value = rc.K, o.reference = ref.K;
  }
  return o;
}

// Hamrock–Brewe: κ ≈ 1.0339 (R_y/R_x)^0.636, E ≈ 1.0003 + 0.5968 R_x/R_y,
// K ≈ 1.5277 + 0.6023 ln(R_y/R_x). K_contact ∝ κ E^{1/2} K(e)^{-3/2}, so its relative error is at
// most |Δκ/κ| + ½|ΔE/E| + 1.5|ΔK/K|. For the presets' grooves (F = 0.887–0.958, R_y/R_x = 17–46)
// the fits are within 3.4 % (κ, for R_y/R_x ≤ 50), 0.07 % (E) and 0.6 % (K(e)) of exact — their
// accuracy over the bearing range as tests/lumped/test_contact.cc states it (no published figure
// was found) — so |ΔK_contact/K| ≤ 3.4 + 0.04 + 0.9 = 4.3 %.
Check hamrock_brewe(const std::string& name) {
  Check c;
  c.id = "hertz.hamrock-brewe-k." + name;
  c.family = "hertz";
  c.reference = ReferenceKind::cross_model;
  c.compares = "value: the lumped Hamrock-Brewe K of the " + name +
               " (the race farther from exact); reference: the check's exact Hertz K";
  c.quantity = "K";
  c.unit = "N/m^1.5";
  c.tolerance = relative(
      0.043,
      "Hamrock-Brewe's fits for R_y/R_x <= 50 (the presets: 17-46) are within 3.4 % (kappa), "
      "0.07 % (E(e)) and 0.6 % (K(e)) of exact (tests/lumped/test_contact.cc; no published "
      "figure found); K ~ kappa E^1/2 K(e)^-3/2 bounds the error of K by 3.4 + 0.04 + 0.9 = "
      "4.3 %");
  c.catches = {"contact-constant-x1.03"};
  c.measure = [name](const Context& ctx) {
    return worst_race_k(ctx, name, HertzMethod::hamrock_brewe,
                        [](const RaceContact& rc, const reference::HertzContact& ref) {
                          return fmt(": K %+.3f %%, kappa %+.3f %%; ", 100 * (rc.K / ref.K - 1),
                                     100 * (rc.shape.ellipticity / ref.kappa - 1));
                        });
  };
  return c;
}

// Harris's δ* table (seed 001 Table 1, four significant digits) interpolated: within 2e-4 of the
// exact δ* for 0.87 ≤ F ≤ 0.9995 (tests/lumped/test_contact.cc), the printed digits' rounding
// (≤ 0.5e-4 on δ* ≈ 0.6–0.7, i.e. 8e-5) included. K ∝ δ*^{-3/2}: 3e-4 on K.
Check harris_table(const std::string& name) {
  Check c;
  c.id = "hertz.harris-table-k." + name;
  c.family = "hertz";
  c.reference = ReferenceKind::cross_model;
  c.compares = "value: the lumped Harris-table K of the " + name +
               " (the race farther from exact); reference: the check's exact Hertz K";
  c.quantity = "K";
  c.unit = "N/m^1.5";
  c.tolerance = relative(
      4.5e-4,
      "Harris's delta* is printed to 4 digits (rounding <= 8e-5 relative here) and its monotone "
      "interpolation in (1-F)^1/3 is within 2e-4 of exact delta* for 0.87 <= F <= 0.9995 (the "
      "presets' range); K ~ delta*^-3/2: 1.5 x 3e-4");
  c.catches = {"contact-constant-x1.03"};
  c.measure = [name](const Context& ctx) {
    return worst_race_k(ctx, name, HertzMethod::harris_table,
                        [](const RaceContact& rc, const reference::HertzContact& ref) {
                          return fmt(": F = %.5f, K %+.4f %%; ", ref.f_rho,
                                     100 * (rc.K / ref.K - 1));
                        });
  };
  return c;
}

// The exponent the toolkit's law has, measured as a log-slope of its approach between two loads,
// against Hertz's δ ∝ Q^{2/3} (the check's own approach formula at the same loads). The law's
// exponent is one number for every bearing, so one row covers all presets, both races and the
// ball's series law (the value is the slope farthest from Hertz's).
Figure load_approach_6308(const RaceContact& rc, const reference::HertzContact& ref) {
  Figure f;
  f.name = "hertz-load-approach-6308";
  f.title = "6308 inner race: Q(delta), lumped exact law and Hertz";
  f.x_label = "approach delta [m]";
  f.y_label = "load Q [N]";
  f.log_x = f.log_y = true;
  // The check's Hertz solution as points, the lumped law Q = K δ^n (the toolkit's K and n, which
  // the mutations move) as the line through them.
  Series hertz{"Hertz (reference)", {}, {}, "marker"};
  for (int i = 0; i <= 20; i += 4) {
    const double q = std::pow(10.0, 1.0 + 3.0 * i / 20.0);
    hertz.x.push_back(ref.approach(q));
    hertz.y.push_back(q);
  }
  f.series = {hertz};
  f.panel = Panel::force_approach;
  f.laws = {{"lumped, inner race", rc.K, rc.exponent}};
  return f;
}

Check exponent() {
  Check c;
  c.id = "hertz.exponent";
  c.family = "hertz";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: ln(Q2/Q1) / ln(delta2/delta1) of the lumped exact laws (every preset, both races and "
      "the ball's series law: the slope farthest from Hertz's) for Q = 10 N, 1 kN; reference: the "
      "same slope of Hertz's delta(Q) from the check's own solution";
  c.quantity = "n";
  c.unit = "-";
  c.tolerance = absolute(1e-9, "both slopes are exact powers; round-off of two logarithms");
  c.catches = {"contact-exponent+0.05"};
  c.measure = [](const Context& ctx) {
    const double q1 = 10.0, q2 = 1000.0;
    const auto slope = [&](auto approach) {
      return std::log(q2 / q1) / std::log(approach(q2) / approach(q1));
    };
    Outcome o{0, 1.5, "", {}};
    double worst = -1;
    for (const auto& name : preset_names()) {
      const Bearing b = ctx.bearing(name);
      const ContactConstants k = ctx.contact(b, HertzMethod::exact);
      const auto ref = exact_hertz(preset(name), Race::inner);
      const double n_ref = slope([&](double q) { return ref.approach(q); });
      const double n[3] = {slope([&](double q) { return k.inner.approach(q); }),
                           slope([&](double q) { return k.outer.approach(q); }),
                           slope([&](double q) { return std::pow(q / k.K, 1.0 / k.exponent); })};
      for (double v : n) {
        if (std::abs(v - n_ref) > worst) {
          worst = std::abs(v - n_ref);
          o.value = v;
          o.reference = n_ref;
        }
      }
      o.detail += name + fmt(" %.12f; ", std::max({n[0], n[1], n[2]}));
      if (name == "6308") o.figures.push_back(load_approach_6308(k.inner, ref));
    }
    return o;
  };
  return c;
}

// The approach itself, δ(Q) = (Q/K)^{1/n} at one load: the exponent row fits only its slope in
// ln Q, which a law computing (Q·K)^{1/n} (code mutant contact-c3dcbe9f) or any constant factor
// leaves unchanged. One row over every preset and both races (the worst ratio is the value).
Check approach() {
  Check c;
  c.id = "hertz.approach";
  c.family = "hertz";
  c.reference = ReferenceKind::closed_form;
  c.compares =
      "value: the approach delta(1 kN) of the lumped exact law of every preset and both races "
      "(the one farthest from its reference); reference: Hertz's delta(1 kN) from the check's "
      "own solution";
  c.quantity = "delta";
  c.unit = "m";
  c.tolerance = relative(1e-9,
                         "delta = (Q/K)^(2/3) on both sides with K equal to < 1e-13 (the exact-K "
                         "rows' round-off): round-off");
  c.catches = {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"};
  c.measure = [](const Context& ctx) {
    const double q = 1000.0;
    Outcome o{0, 1, "", {}};
    double worst = -1;
    for (const auto& name : preset_names())
      for (Race race : {Race::inner, Race::outer}) {
        const double v = ctx.race_contact(ctx.bearing(name), race, HertzMethod::exact).approach(q);
        const double ref = exact_hertz(preset(name), race).approach(q);
        if (std::abs(v / ref - 1) > worst) {
          worst = std::abs(v / ref - 1);
          o = {v, ref, name + " " + to_string(race) + " race is the farthest", {}};
        }
      }
    return o;
  };
  return c;
}

}  // namespace

std::vector<Check> hertz_checks() {
  std::vector<Check> all;
  for (const auto& name : preset_names())
    for (Race race : {Race::inner, Race::outer}) all.push_back(exact_k(name, race));
  // The K-per-bearing figure rides on the first row.
  {
    auto measure = all.front().measure;
    all.front().measure = [measure](const Context& ctx) {
      Outcome o = measure(ctx);
      o.figures.push_back(k_per_bearing(ctx));
      return o;
    };
  }
  for (const auto& name : preset_names()) all.push_back(semi_axes(name));
  for (const auto& name : preset_names()) all.push_back(hamrock_brewe(name));
  for (const auto& name : preset_names()) all.push_back(harris_table(name));
  all.push_back(exponent());
  all.push_back(approach());
  return all;
}

}  // namespace bearing::verify
