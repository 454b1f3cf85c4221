// Hertz family, finite-element references (bearing-fem contact, fem/README.md): the lumped exact
// Hertz law of the 6308 (examples/seed003_6308.toml) against the FE Hertz-reduced block — K (fit
// with n = 1.5), the free-fit exponent and the minor semi-axis — at a cheap mesh (quick) and at
// the accurate mesh (standard). The real groove against Hertz's paraboloid: hertz_groove.cc.

#include <cmath>
#include <cstdio>
#include <string>

#include "../context.h"
#include "../families.h"
#include "check_util.h"

namespace bearing::verify {

namespace {

// One resolution of the convergence table of fem/README.md (6308, loads 2–20 N, 6 steps) with
// its measured errors (FE/Hertz − 1), which set the tolerances.
struct Mesh {
  const char* label;  ///< "level 0" …
  int cells;          ///< N_b, cells per semi-minor axis
  int grading;        ///< m
  Level level;        ///< the run level that uses it
  double k_error[2];  ///< measured K error, inner and outer [-]
  double k_tol;
  double n_error[2];  ///< measured exponent − 1.5
  double n_tol;
  double b_error[2];  ///< measured semi-minor error [-]
  double b_tol;
};

// Level 0 (N_b 4, m 3) and level 2 (N_b 8, m 6, the README's reference run). The tolerances are
// the measured errors rounded up — regression pins (pin()), counted apart in the report: no bound
// can be derived at these meshes, since K's error per level (+1.14/+0.75/+0.32/+0.26 %) is not in
// the asymptotic range (Richardson from levels 0 and 1 predicts 0.31 % left at level 1, where
// 0.69 % is). The minor semi-axis is: fe_semi_minor_richardson below (issue 30); halving N_b at
// fixed m moves K little (measured: level 0 with N_b 2: −0.28 %/−0.64 %; N_b 4, m 6: +0.01 %/−0.06
// % — the coarse patch's softness cancels the far field's stiffness), but the exponent
// (+0.023/+0.030 and +0.0057/+0.0075) and the minor semi-axis (−7.9 % and −2.2 %) leave their
// tolerances: those rows catch a halved mesh.
const Mesh kQuick{"level 0 (N_b 4, m 3)",
                  4,
                  3,
                  Level::quick,
                  {0.01142, 0.01080},
                  0.015,
                  {0.0067, 0.0086},
                  0.01,
                  {-0.02106, -0.02080},
                  0.025};
// Level 1 (N_b 6, m 4): only the Richardson row below uses it (no tolerances of its own).
const Mesh kLevel1{"level 1 (N_b 6, m 4)", 6, 4, Level::quick, {0, 0}, 0, {0, 0}, 0, {0, 0}, 0};
const Mesh kStandard{"level 2 (N_b 8, m 6)",
                     8,
                     6,
                     Level::standard,
                     {0.00321, 0.00343},
                     0.005,
                     {0.0015, 0.0019},
                     0.003,
                     {-0.00550, -0.00540},
                     0.008};

nlohmann::json block_run(const Context& ctx, Race race, const Mesh& m) {
  return ctx.fem(
      {"contact", ctx.source_dir() + "/examples/seed003_6308.toml", "--race", to_string(race),
       "--geometry", "hertz", "--cells", std::to_string(ctx.fe_cells(m.cells)), "--grading",
       std::to_string(m.grading), "--no-vtu", "--quiet"},
      "contact.json");
}

std::string run_detail(const nlohmann::json& j) {
  return fmt("FE: %.0f cells, %.0f DoFs, F_max = %.4g N, %.1f s", j["mesh"]["cells"].get<double>(),
             j["mesh"]["dofs"].get<double>(), j["fe"]["load"].get<double>(),
             j["wall_time_total"].get<double>());
}

std::string level_suffix(const Mesh& m) {
  return m.level == Level::quick ? ".coarse" : ".accurate";
}

Check base(const std::string& what, Race race, const Mesh& m) {
  Check c;
  c.id = "hertz.fe-" + what + ".6308." + to_string(race) + level_suffix(m);
  c.family = "hertz";
  c.reference = ReferenceKind::fe;
  c.level = m.level;
  c.cost = m.level == Level::quick ? 8.0 : 30.0;
  return c;
}

Check fe_k(Race race, const Mesh& m) {
  const int r = race == Race::inner ? 0 : 1;
  Check c = base("k", race, m);
  c.compares = std::string("value: the lumped exact-Hertz K of the 6308 ") + to_string(race) +
               " race; reference: the FE Hertz-reduced block's K (least squares of ln F on ln "
               "delta, n fixed at 1.5), " +
               m.label + ", loads 2-20 N";
  c.quantity = "K";
  c.unit = "N/m^1.5";
  c.tolerance = pin(relative(
      m.k_tol, fmt("fem/README.md's convergence table: the FE K at this mesh is %+.2f %% off Hertz "
                   "(the displacement method is too stiff), rounded up to %.1f %%",
                   100 * m.k_error[r], 100 * m.k_tol)));
  c.catches = {"contact-constant-x1.03"};
  c.measure = [race, m](const Context& ctx) {
    const nlohmann::json j = block_run(ctx, race, m);
    const RaceContact rc = ctx.race_contact(ctx.bearing("6308"), race, HertzMethod::exact);
    Outcome o{rc.K, j["fe"]["K"].get<double>(), run_detail(j), {}};
    Figure f;
    f.name = std::string("hertz-fe-force-approach-6308-") + to_string(race) +
             (m.level == Level::quick ? "-coarse" : "-accurate");
    f.title = std::string("6308 ") + to_string(race) + " race: FE block against the lumped law, " +
              m.label;
    f.x_label = "approach delta [m]";
    f.y_label = "force F [N]";
    f.log_x = f.log_y = true;
    Series fe{"FE Hertz-reduced block", {}, {}, "marker"};
    for (const auto& s : j["steps"]) {
      fe.x.push_back(s["approach"].get<double>());
      fe.y.push_back(s["force"].get<double>());
    }
    f.series = {fe};
    f.panel = Panel::force_approach;
    f.laws = {{"lumped exact Hertz", rc.K, rc.exponent}};
    o.figures.push_back(f);
    return o;
  };
  return c;
}

Check fe_exponent(Race race, const Mesh& m) {
  const int r = race == Race::inner ? 0 : 1;
  Check c = base("exponent", race, m);
  c.compares = std::string("value: the lumped exact-Hertz exponent of the 6308 ") +
               to_string(race) +
               " race; reference: the FE block's exponent (free least-squares fit of ln F on ln "
               "delta), " +
               m.label;
  c.quantity = "n";
  c.unit = "-";
  c.tolerance = pin(absolute(
      m.n_tol, fmt("fem/README.md's convergence table: the FE exponent at this mesh is 1.5 %+.4f, "
                   "rounded up to %.3f",
                   m.n_error[r], m.n_tol)));
  c.catches = {"contact-exponent+0.05", "fe-mesh-halved"};
  c.measure = [race, m](const Context& ctx) {
    const nlohmann::json j = block_run(ctx, race, m);
    const RaceContact rc = ctx.race_contact(ctx.bearing("6308"), race, HertzMethod::exact);
    return Outcome{
        rc.exponent,
        j["fe"]["exponent"].get<double>(),
        run_detail(j) + fmt(", fit residual %.1e", j["fe"]["fit_residual"].get<double>()),
        {}};
  };
  return c;
}

Check fe_semi_minor(Race race, const Mesh& m) {
  const int r = race == Race::inner ? 0 : 1;
  Check c = base("semi-minor", race, m);
  c.compares = std::string("value: the lumped exact-Hertz minor semi-axis b of the 6308 ") +
               to_string(race) +
               " race at the FE's largest force; reference: the FE block's b from the pressure's "
               "second moment (b^2/5 for Hertz's ellipsoid), " +
               m.label;
  c.quantity = "b";
  c.unit = "m";
  c.tolerance = pin(relative(
      m.b_tol, fmt("fem/README.md's convergence table: the FE b at this mesh is %+.2f %% off "
                   "Hertz (about 1/N_b of a cell), rounded up to %.1f %%",
                   100 * m.b_error[r], 100 * m.b_tol)));
  c.catches = {"fe-mesh-halved"};
  c.measure = [race, m](const Context& ctx) {
    const nlohmann::json j = block_run(ctx, race, m);
    const RaceContact rc = ctx.race_contact(ctx.bearing("6308"), race, HertzMethod::exact);
    const double load = j["fe"]["load"].get<double>();
    Outcome o{rc.semi_minor(load), j["fe"]["semi_axes"][1].get<double>(), run_detail(j), {}};
    o.detail += fmt("; a: lumped %.5g m, FE %.5g m", rc.semi_major(load),
                    j["fe"]["semi_axes"][0].get<double>());
    return o;
  };
  return c;
}

// The minor semi-axis extrapolated to zero cell size: a derived bound, not a pin (issue 30). b is a
// smooth functional of the Q1 solution: its error falls as h^2 (fem/README.md's convergence table,
// pairwise orders 1.9-2.0; hertz.fe-convergence.semi-minor checks the order at --level full).
// Levels 0 (N_b 4, m 3) and 1 (N_b 6, m 4) shrink the patch's cells by r = 1.5, so Richardson's
// b_R = b1 + (b1 - b0) / (r^p - 1) with p = 2. Its uncertainty U is what the order's uncertainty
// p in [1.8, 2.2] moves b_R by, plus the clamped block's finite-size bias: the block is stiffer
// by <= 0.10 % (fem/README.md, "Finite size": 0.26 % x 107 a / L at L >= 256 a), which at one
// force shrinks b like a stiffer E*, by a third of that. Both levels' b are first scaled to
// level 1's largest force with Hertz's b ~ F^(1/3) (the forces differ by ~0.4 %: an exponent off
// by 0.01 moves b by < 1e-5). The row's value is z = (b_lumped - b_R) / U: |z| <= 1 is agreement
// within the bound. Solver tolerances (CG 1e-11) and another compiler move b by ~1e-10, far
// inside U.
Check fe_semi_minor_richardson(Race race) {
  Check c;
  c.id = std::string("hertz.fe-semi-minor-richardson.6308.") + to_string(race);
  c.family = "hertz";
  c.reference = ReferenceKind::fe;
  c.level = Level::quick;
  c.cost = 16.0;
  c.compares = std::string(
                   "value: (b_lumped - b_R) / U, the lumped exact-Hertz minor semi-axis of "
                   "the 6308 ") +
               to_string(race) +
               " race against the FE block's b extrapolated from levels 0 and 1 (Richardson, "
               "order 2), in units of the extrapolation's uncertainty U; reference: 0";
  c.quantity = "z";
  c.unit = "-";
  c.tolerance = absolute(
      1.0,
      "U = the spread of b_R for the order p in [1.8, 2.2] about p = 2 (fem/README.md: b's "
      "pairwise orders 1.9-2.0) plus a third of the block's finite-size stiffening (<= "
      "0.10 %): |z| <= 1 is agreement within the derived bound");
  c.catches = {"ellipse-minor-x1.01"};
  c.measure = [race](const Context& ctx) {
    const nlohmann::json j0 = block_run(ctx, race, kQuick);
    const nlohmann::json j1 = block_run(ctx, race, kLevel1);
    const double f1 = j1["fe"]["load"].get<double>();
    auto scaled_b = [f1](const nlohmann::json& j) {
      return j["fe"]["semi_axes"][1].get<double>() * std::cbrt(f1 / j["fe"]["load"].get<double>());
    };
    const double b0 = scaled_b(j0), b1 = scaled_b(j1);
    const double r = static_cast<double>(kLevel1.cells) / kQuick.cells;
    auto extrapolated = [&](double p) { return b1 + (b1 - b0) / (std::pow(r, p) - 1.0); };
    const double b_r = extrapolated(2.0);
    const double spread = 0.5 * std::fabs(extrapolated(1.8) - extrapolated(2.2));
    const double u = spread + b_r * 0.0010 / 3.0;
    const RaceContact rc = ctx.race_contact(ctx.bearing("6308"), race, HertzMethod::exact);
    const double b_lumped = rc.semi_minor(f1);
    Outcome o{(b_lumped - b_r) / u, 0.0, "", {}};
    o.detail =
        fmt("b_lumped %.6g m, FE b0 %.6g m, b1 %.6g m (at F = %.4g N), b_R %.6g m "
            "(%+.3f %% off lumped), U %.3g m (%.3f %%: order %.3f %%, finite size "
            "%.3f %%)",
            b_lumped, b0, b1, f1, b_r, 100 * (b_r / b_lumped - 1), u, 100 * u / b_r,
            100 * spread / b_r, 100 * 0.0010 / 3.0);
    return o;
  };
  return c;
}

// The other presets at standard: the block at level 1 (N_b 6, m 4). The mesh scales with each
// bearing's contact, so its discretisation error is the same for every bearing: fem/README.md's
// groove table measured the block at this level at +0.80 to +0.96 % on the 608, 6304 and 6308,
// both races.
Check fe_k_preset(const std::string& name, Race race) {
  Check c;
  c.id = "hertz.fe-k." + name + "." + to_string(race) + ".level1";
  c.family = "hertz";
  c.reference = ReferenceKind::fe;
  c.level = Level::standard;
  c.cost = 10.0;
  c.compares = "value: the lumped exact-Hertz K of the " + name + " " + to_string(race) +
               " race; reference: the FE Hertz-reduced block's K (n = 1.5 fit), level 1 (N_b 6, "
               "m 4), loads Q_max/10 to Q_max of examples/seed003_6308.toml's 20 N radial load "
               "on this bearing";
  c.quantity = "K";
  c.unit = "N/m^1.5";
  c.tolerance = pin(relative(0.012,
                             "the block's error at level 1, measured +0.80 to +0.96 % on three "
                             "bearings and both races (fem/README.md, groove table), the same "
                             "for every bearing because the mesh scales with the contact; "
                             "rounded up to 1.2 %"));
  c.catches = {"contact-constant-x1.03"};
  c.measure = [name, race](const Context& ctx) {
    const nlohmann::json j = ctx.fem(
        {"contact", ctx.source_dir() + "/examples/seed003_6308.toml", "--set",
         "bearing.preset=\"" + name + "\"", "--race", to_string(race), "--geometry", "hertz",
         "--cells", std::to_string(ctx.fe_cells(6)), "--grading", "4", "--no-vtu", "--quiet"},
        "contact.json");
    const RaceContact rc = ctx.race_contact(ctx.bearing(name), race, HertzMethod::exact);
    return Outcome{rc.K, j["fe"]["K"].get<double>(), run_detail(j), {}};
  };
  return c;
}

}  // namespace

std::vector<Check> hertz_fe_checks() {
  std::vector<Check> all;
  for (const Mesh* m : {&kQuick, &kStandard}) {
    for (Race race : {Race::inner, Race::outer}) {
      all.push_back(fe_k(race, *m));
      all.push_back(fe_exponent(race, *m));
      all.push_back(fe_semi_minor(race, *m));
    }
  }
  for (Race race : {Race::inner, Race::outer}) all.push_back(fe_semi_minor_richardson(race));
  for (const std::string name : {"608", "6304", "6205", "209"})
    for (Race race : {Race::inner, Race::outer}) all.push_back(fe_k_preset(name, race));
  return all;
}

}  // namespace bearing::verify
