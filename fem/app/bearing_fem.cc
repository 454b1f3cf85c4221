// bearing-fem: command line of the deal.II finite-element references. Parses, calls the fem
// library, writes; no physics here.
//
//   bearing-fem contact CASE --race inner|outer [--geometry hertz|groove] --out DIR
//
// writes DIR/force_approach.csv (approach,force,semi_axis_a,semi_axis_b,peak_pressure),
// DIR/contact.json (fe.{K,exponent,semi_axes,fit_residual}, hertz.{K,semi_axes} at the same load,
// relative_difference.{K,semi_axes}) and DIR/vtu/contact_*.pvtu. Runs under mpirun.

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/static_load.h"
#include "contact/hertz_contact.h"

namespace {

struct ContactOptions {
  std::string case_path;
  std::vector<std::string> sets;
  std::string race = "inner";
  std::string geometry = "hertz";
  std::string out_dir;
  double cells = 8;       // cells per semi-minor axis b at the largest load
  double stretch = 2;     // cell aspect h_y/h_x
  double grading = 6;
  double domain = 256;
  unsigned int steps = 6;
  double tolerance = 1e-11;
  double load_min = 0;    // 0: load_max / 10
  double load_max = 0;    // 0: Q_max of the case
  bool vtu = true;
  bool quiet = false;
};

nlohmann::json step_json(const bearing::fem::ApproachStep& s) {
  return {{"approach", s.approach},
          {"force", s.force},
          {"semi_axis_a", s.semi_major},
          {"semi_axis_b", s.semi_minor},
          {"semi_axis_a_edge", s.semi_major_edge},
          {"semi_axis_b_edge", s.semi_minor_edge},
          {"edge_spacing_a", s.edge_spacing_major},
          {"edge_spacing_b", s.edge_spacing_minor},
          {"peak_pressure", s.peak_pressure},
          {"contact_nodes", s.active_nodes},
          {"active_set_iterations", s.active_set_iterations},
          {"cg_iterations", s.linear_iterations}};
}

int run_contact(const ContactOptions& o, MPI_Comm comm) {
  using namespace bearing;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  if (o.race != "inner" && o.race != "outer")
    throw InputError("--race = " + o.race + ": must be inner or outer");
  if (o.geometry == "groove")
    throw InputError("--geometry = groove: the real groove geometry (meshes/) is not implemented "
                     "yet; use --geometry hertz");
  if (o.geometry != "hertz") throw InputError("--geometry = " + o.geometry + ": must be hertz");

  std::vector<Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(parse_override(s));
  const Case c = o.case_path.empty() ? default_case(overrides)
                                     : read_case_file(o.case_path, overrides);
  const Race race = o.race == "inner" ? Race::inner : Race::outer;
  const auto exact = make_exact_hertz();
  const RaceContact rc = race_contact(c.bearing, race, *exact);
  const Curvatures rho = race_curvatures(c.bearing, race);

  // Load range: from light load to the case's largest ball load Q_max (lumped static solution).
  double q_max = o.load_max;
  std::string q_source = "--load-max";
  if (q_max <= 0) {
    const ContactConstants cc = contact_constants(c.bearing, *exact);
    const auto st = solve_static_load(c.bearing.balls, cc.K, c.bearing.ball_gap(),
                                      c.operation.load);
    q_max = st.q_max;
    q_source = "static load distribution of the case (lumped solve_static_load, exact Hertz)";
    if (!(q_max > 0))
      throw InputError("the case's radial load gives no ball load; pass --load-max");
  }
  const double q_min = o.load_min > 0 ? o.load_min : q_max / 10;
  if (!(q_min < q_max)) throw InputError("--load-min must be below the largest load");

  fem::HertzContactParameters p;
  p.contact_modulus = 1 / rc.compliance;
  p.poisson = 0.3;
  p.radius_x = 1 / (rho.ball_1 + rho.race_1);
  p.radius_y = 1 / (rho.ball_2 + rho.race_2);
  // Approach steps: geometric in load, through the analytic approach (a design choice only; the
  // FE force at each δ is what is measured).
  for (unsigned int k = 0; k < o.steps; ++k) {
    const double q = q_min * std::pow(q_max / q_min, o.steps > 1 ? double(k) / (o.steps - 1) : 1.0);
    p.approaches.push_back(rc.approach(q));
  }
  p.design_semi_minor = rc.semi_minor(q_max);
  p.design_semi_major = rc.semi_major(q_max);
  p.finest_cell_fraction = 1.0 / o.cells;
  p.stretch = o.stretch;
  p.grading = o.grading;
  p.domain_size = o.domain;
  p.verbose = !o.quiet;
  p.solver_tolerance = o.tolerance;
  const std::filesystem::path out(o.out_dir);
  if (root) std::filesystem::create_directories(out);
  if (o.vtu) {
    p.vtu_directory = (out / "vtu").string();
    if (root) std::filesystem::create_directories(p.vtu_directory);
  }
  MPI_Barrier(comm);
  if (root && !o.quiet)
    std::cout << "bearing-fem contact: " << o.race << " race, Hertz-reduced, E* = "
              << p.contact_modulus << " Pa, R_x = " << p.radius_x << " m, R_y = " << p.radius_y
              << " m, kappa = " << rc.shape.ellipticity << ", loads " << q_min << " .. " << q_max
              << " N\n";

  const fem::HertzContactResult r = fem::solve_hertz_contact(p, comm);
  if (!root) return 0;

  std::vector<double> d, f;
  for (const auto& s : r.steps) {
    d.push_back(s.approach);
    f.push_back(s.force);
  }
  const fem::PowerLawFit fit = fem::fit_power_law(d, f);
  const auto& last = r.steps.back();
  const double a_h = rc.semi_major(last.force), b_h = rc.semi_minor(last.force);

  {
    std::ofstream csv(out / "force_approach.csv");
    csv << "approach,force,semi_axis_a,semi_axis_b,peak_pressure\n" << std::setprecision(17);
    for (const auto& s : r.steps)
      csv << s.approach << ',' << s.force << ',' << s.semi_major << ',' << s.semi_minor << ','
          << s.peak_pressure << '\n';
  }
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : r.steps) {
    auto j = step_json(s);
    j["hertz_force"] = rc.K * std::pow(s.approach, 1.5);
    j["hertz_semi_axis_a"] = rc.semi_major(s.force);
    j["hertz_semi_axis_b"] = rc.semi_minor(s.force);
    j["hertz_peak_pressure"] = rc.peak_pressure(s.force);
    steps.push_back(j);
  }
  nlohmann::json j = {
      {"case", c.source},
      {"race", o.race},
      {"geometry", o.geometry},
      {"method",
       "3-D linear elasticity, Q1, quarter block with E = (1-nu^2) E*, rigid paraboloid; "
       "primal-dual active set; CG + Trilinos ML AMG"},
      {"load_range", {{"min", q_min}, {"max", q_max}, {"max_source", q_source}}},
      {"fe",
       {{"K", fit.K_three_halves},
        {"K_note", "K of the fit with the exponent fixed at 1.5 (comparable with Hertz's K)"},
        {"exponent", fit.exponent},
        {"K_free_exponent", fit.K},
        {"semi_axes", {last.semi_major, last.semi_minor}},
        {"semi_axes_edge", {last.semi_major_edge, last.semi_minor_edge}},
        {"load", last.force},
        {"peak_pressure", last.peak_pressure},
        {"fit_residual", fit.residual},
        {"fit_residual_three_halves", fit.residual_three_halves}}},
      {"hertz",
       {{"K", rc.K},
        {"exponent", 1.5},
        {"semi_axes", {a_h, b_h}},
        {"load", last.force},
        {"peak_pressure", rc.peak_pressure(last.force)},
        {"ellipticity", rc.shape.ellipticity},
        {"radius_x", p.radius_x},
        {"radius_y", p.radius_y},
        {"contact_modulus", p.contact_modulus}}},
      {"relative_difference",
       {{"K", fit.K_three_halves / rc.K - 1},
        {"exponent", fit.exponent - 1.5},
        {"semi_axes", {last.semi_major / a_h - 1, last.semi_minor / b_h - 1}},
        {"peak_pressure", last.peak_pressure / rc.peak_pressure(last.force) - 1}}},
      {"mesh",
       {{"cells", r.cells},
        {"dofs", r.dofs},
        {"cells_per_semi_minor", o.cells},
        {"stretch", p.stretch},
        {"grading", p.grading},
        {"finest_cell", {r.finest_cell_x, r.finest_cell_y}},
        {"domain", {r.domain_x, r.domain_y, r.domain_x}},
        {"domain_over_a", r.domain_x / p.design_semi_major}}},
      {"solver_tolerance", p.solver_tolerance},
      {"mpi_processes", r.mpi_processes},
      {"wall_time", r.wall_time},
      {"steps", steps}};
  std::ofstream(out / "contact.json") << std::setprecision(17) << j.dump(2) << '\n';
  if (!o.quiet)
    std::cout << std::setprecision(6) << "K_FE (n = 1.5) = " << fit.K_three_halves
              << " N/m^1.5, Hertz K = " << rc.K << " (" << 100 * (fit.K_three_halves / rc.K - 1)
              << " %); exponent " << fit.exponent << "; a " << 100 * (last.semi_major / a_h - 1)
              << " %, b " << 100 * (last.semi_minor / b_h - 1) << " %; " << r.wall_time
              << " s\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  CLI::App app{"bearing-fem: deal.II finite-element references of the bearing toolkit"};
  app.require_subcommand(1);
  ContactOptions o;
  auto* contact = app.add_subcommand(
      "contact", "Hertz-reduced ball-race contact by FE: force-approach curve, K, exponent, "
                 "semi-axes, compared with the analytic Hertz solution");
  contact->add_option("CASE", o.case_path, "TOML case file (default: the built-in 6308 case)");
  contact->add_option("--set", o.sets, "Override a case-file value, TABLE.KEY=VALUE");
  contact->add_option("--race", o.race, "inner | outer")->required();
  contact->add_option("--geometry", o.geometry, "hertz (groove: not yet)");
  contact->add_option("--out", o.out_dir, "Output folder (created if missing)")->required();
  contact->add_option("--cells", o.cells, "Finest cells per semi-minor axis b at the largest load")
      ->check(CLI::PositiveNumber);
  contact->add_option("--stretch", o.stretch, "Cell aspect h_y/h_x >= 1 (stretched along the major axis)")
      ->check(CLI::Range(1.0, 100.0));
  contact->add_option("--grading", o.grading, "Cell size >= distance / grading away from the patch");
  contact->add_option("--domain", o.domain, "Block size over the major semi-axis a (about)");
  contact->add_option("--tolerance", o.tolerance, "CG tolerance relative to the right-hand side");
  contact->add_option("--steps", o.steps, "Approach steps")->check(CLI::Range(2, 100));
  contact->add_option("--load-min", o.load_min, "Smallest load [N] (default: load-max / 10)");
  contact->add_option("--load-max", o.load_max, "Largest load [N] (default: Q_max of the case)");
  contact->add_flag("!--no-vtu", o.vtu, "Do not write VTU files");
  contact->add_flag("--quiet", o.quiet, "No progress output");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return run_contact(o, MPI_COMM_WORLD);
  } catch (const bearing::InputError& e) {
    std::cerr << "bearing-fem: input error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bearing-fem: error: " << e.what() << '\n';
    return 1;
  }
}
