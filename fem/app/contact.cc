// `bearing-fem contact` and `bearing-fem calibrate`: parse, call the fem contact library,
// write; no physics here.
//
//   bearing-fem contact CASE --race inner|outer [--geometry hertz|groove] --out DIR
//
// writes DIR/force_approach.csv (approach,force,semi_axis_a,semi_axis_b,peak_pressure),
// DIR/contact.json (fe.{K,exponent,semi_axes,fit_residual}, hertz.{K,semi_axes} at the same load,
// relative_difference.{K,semi_axes}) and DIR/vtu/contact_*.pvtu. Runs under mpirun.
//
//   bearing-fem calibrate CASE --out FILE
//
// writes FILE and, beside it, <stem>_inner/ and <stem>_outer/ with each race's files. Both
// commands write all or nothing (AtomicFileSet on rank 0): input is checked before any file, every
// file goes to a temporary name, and the set is committed after the solves.

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/contact.h"
#include "app/rank_zero.h"
#include "bearing/atomic_file_set.h"
#include "bearing/calibration.h"
#include "bearing/case_file.h"
#include "bearing/cli_options.h"
#include "bearing/constants.h"
#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/static_load.h"
#include "contact/hertz_contact.h"

namespace bearing::fem {
namespace {

// ISO 15 boundary dimensions d × D × B of the presets [m] (the lumped case carries only the
// ball set's geometry; the groove reference also needs the rings).
struct RingDimensions {
  double bore, outside, width;
};
bool iso15_dimensions(const std::string& designation, RingDimensions& r) {
  const struct {
    const char* name;
    RingDimensions d;
  } table[] = {{"608", {8e-3, 22e-3, 7e-3}},
               {"6304", {20e-3, 52e-3, 15e-3}},
               {"6308", {40e-3, 90e-3, 23e-3}},
               {"6205", {25e-3, 52e-3, 15e-3}},
               {"209", {45e-3, 85e-3, 19e-3}}};
  for (const auto& e : table)
    if (designation == e.name) return r = e.d, true;
  return false;
}

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

// The ring segment of --geometry groove, checked before anything is written: its dimensions (ISO
// 15 by designation unless given), the segment's angle and a JSON record; the coarse mesh comes
// later (solve_contact).
struct Raceway {
  bearing::fem::RacewaySegment segment;
  double groove_depth = 0;   // h, groove bottom to land [m]
  double segment_angle = 0;  // [rad]
  nlohmann::json record;     // contact.json's "raceway"
};

Raceway raceway_geometry(const ContactOptions& o, const bearing::Case& c, bearing::Race race) {
  using namespace bearing;
  const Bearing& b = c.bearing;
  RingDimensions dims{o.bore, o.outside, o.width};
  RingDimensions iso{};
  const bool known = iso15_dimensions(b.designation, iso);
  if (dims.bore <= 0) dims.bore = iso.bore;
  if (dims.outside <= 0) dims.outside = iso.outside;
  if (dims.width <= 0) dims.width = iso.width;
  if (!(dims.bore > 0 && dims.outside > 0 && dims.width > 0))
    throw InputError("--geometry groove needs the ring dimensions: bearing \"" + b.designation +
                     "\" has no ISO 15 entry here" +
                     (known ? ""
                            : " (known: 608, 6304, 6308, "
                              "6205, 209)") +
                     "; give --bore, --outside-diameter and --width [m]");
  if (b.contact_angle != 0)
    throw InputError(
        "--geometry groove models the radial contact at the groove bottom; "
        "bearing.contact_angle = " +
        std::to_string(b.contact_angle * 180 / pi) +
        " deg is not supported (use --geometry hertz)");
  const bool outer = race == Race::outer;
  const double D = b.ball_diameter;
  Raceway w;
  fem::RacewaySegment& r = w.segment;
  r.outer = outer;
  r.ball_radius = D / 2;
  r.groove_radius = (outer ? b.outer_conformity : b.inner_conformity) * D;
  r.groove_bottom = (outer ? b.outer_raceway_diameter() : b.inner_raceway_diameter()) / 2;
  r.back_radius = (outer ? dims.outside : dims.bore) / 2;
  r.half_width = dims.width / 2;
  if (outer ? r.back_radius <= r.groove_bottom + 0.05 * D
            : r.back_radius >= r.groove_bottom - 0.05 * D)
    throw InputError(std::string(outer ? "--outside-diameter" : "--bore") + " = " +
                     std::to_string(2 * r.back_radius) + " m leaves no ring under the groove " +
                     "(groove-bottom diameter " + std::to_string(2 * r.groove_bottom) + " m)");
  // --groove-depth and --segment-angle are range-checked on the command line (main).
  w.segment_angle = o.segment_angle > 0 ? o.segment_angle * pi / 180 : pi / b.balls;
  w.groove_depth = o.groove_depth * D;
  r.paraboloid_gap = o.gap == "paraboloid";
  w.record = {{"ring", outer ? "outer" : "inner"},
              {"bore", dims.bore},
              {"outside_diameter", dims.outside},
              {"width", dims.width},
              {"dimensions_source", o.bore > 0 || o.outside > 0 || o.width > 0
                                        ? "command line (ISO 15 for the rest)"
                                        : "ISO 15 boundary dimensions of " + b.designation},
              {"groove_radius", r.groove_radius},
              {"groove_bottom_radius", r.groove_bottom},
              {"clamped_radius", r.back_radius},
              {"segment_angle", w.segment_angle},
              {"gap", o.gap},
              {"mesh_source", std::string(BEARING_MESH_DIR) + "/raceway_segment.geo"}};
  return w;
}

// One contact computation, checked and set up before anything is written: the case, the race,
// Hertz's reference, the load range and the FE parameters (groove: the ring, not yet meshed).
struct ContactProblem {
  bearing::Case c;
  bearing::Race race = bearing::Race::inner;
  bearing::RaceContact rc;
  double q_min = 0, q_max = 0;
  std::string q_source;
  bearing::fem::HertzContactParameters p;
  Raceway raceway;  // --geometry groove
};

ContactProblem contact_problem(const ContactOptions& o) {
  using namespace bearing;
  if (o.race != "inner" && o.race != "outer")
    throw InputError("--race = " + o.race + ": must be inner or outer");
  if (o.geometry != "hertz" && o.geometry != "groove")
    throw InputError("--geometry = " + o.geometry + ": must be hertz or groove");
  if (o.gap != "exact" && o.gap != "paraboloid")
    throw InputError("--gap = " + o.gap + ": must be exact or paraboloid");

  ContactProblem pr;
  std::vector<Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(parse_override(s));
  pr.c = o.case_path.empty() ? default_case(overrides) : read_case_file(o.case_path, overrides);
  const Case& c = pr.c;
  pr.race = o.race == "inner" ? Race::inner : Race::outer;
  const auto exact = make_exact_hertz();
  pr.rc = race_contact(c.bearing, pr.race, *exact);
  const RaceContact& rc = pr.rc;
  const Curvatures rho = race_curvatures(c.bearing, pr.race);

  // Load range: from light load to the case's largest ball load Q_max (lumped static solution).
  pr.q_max = o.load_max;
  pr.q_source = "--load-max";
  if (o.peak_pressure > 0) {
    if (o.load_max > 0) throw InputError("give --load-max or --peak-pressure, not both");
    // p₀ ∝ Q^{1/3} in Hertz's theory: scale from any reference load.
    pr.q_max = std::pow(o.peak_pressure / rc.peak_pressure(1.0), 3.0);
    pr.q_source = "--peak-pressure " + std::to_string(o.peak_pressure) + " Pa (Hertz, this race)";
  }
  if (pr.q_max <= 0) {
    const ContactConstants cc = contact_constants(c.bearing, *exact);
    const auto st =
        solve_static_load(c.bearing.balls, cc.K, c.bearing.ball_gap(), c.operation.load);
    pr.q_max = st.q_max;
    pr.q_source = "static load distribution of the case (lumped solve_static_load, exact Hertz)";
    if (!(pr.q_max > 0))
      throw InputError("the case's radial load gives no ball load; pass --load-max");
  }
  const double q_max = pr.q_max;
  pr.q_min = o.load_min > 0 ? o.load_min : q_max * o.load_min_fraction;
  const double q_min = pr.q_min;
  if (!(q_min < q_max)) throw InputError("--load-min must be below the largest load");

  fem::HertzContactParameters& p = pr.p;
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
  if (o.geometry == "groove") {
    p.geometry = "groove";
    pr.raceway = raceway_geometry(o, c, pr.race);
    p.raceway = pr.raceway.segment;
  }
  return pr;
}

// contact.json: the FE result, Hertz's at the same load, their differences, the mesh, each step.
nlohmann::json contact_json(const ContactOptions& o, const ContactProblem& pr,
                            const bearing::fem::HertzContactResult& r,
                            const bearing::fem::PowerLawFit& fit) {
  using bearing::Race;
  const bearing::RaceContact& rc = pr.rc;
  const bearing::fem::HertzContactParameters& p = pr.p;
  const auto& last = r.steps.back();
  const double a_h = rc.semi_major(last.force), b_h = rc.semi_minor(last.force);
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : r.steps) {
    auto j = step_json(s);
    j["hertz_force"] = rc.K * std::pow(s.approach, 1.5);
    j["hertz_semi_axis_a"] = rc.semi_major(s.force);
    j["hertz_semi_axis_b"] = rc.semi_minor(s.force);
    j["hertz_peak_pressure"] = rc.peak_pressure(s.force);
    steps.push_back(j);
  }
  return {
      {"case", pr.c.source},
      {"race", o.race},
      {"geometry", o.geometry},
      {"method",
       o.geometry == "hertz"
           ? "3-D linear elasticity, Q1, quarter block with E = (1-nu^2) E*, rigid paraboloid; "
             "primal-dual active set; CG + Trilinos ML AMG"
           : std::string("3-D linear elasticity, Q1, quarter ring segment with its true groove "
                         "(gmsh meshes/raceway_segment.geo, refined on the exact surfaces), "
                         "E = (1-nu^2) E* (equivalent modulus: the ball's compliance given to the "
                         "ring), clamped ") +
                 (pr.race == Race::outer ? "outside diameter" : "bore") +
                 (o.gap == "exact" ? ", rigid sphere of the ball's radius (exact gap along z)"
                                   : ", Hertz's paraboloid gap (isolates the finite ring)") +
                 "; primal-dual active set; CG + Trilinos ML AMG"},
      {"raceway", pr.raceway.record},
      {"load_range", {{"min", pr.q_min}, {"max", pr.q_max}, {"max_source", pr.q_source}}},
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
}

// The files of one contact result, named relative to the folder of their file set: `prefix` is
// "" for `contact --out DIR`, "6308_inner/" for a race of `calibrate`. They are committed in this
// order, contact.json last: once it is the new one, so are the others. `others`: what this run
// does not write that an earlier one may have (its VTU, its groove mesh); the commit removes it.
struct ContactFiles {
  std::vector<std::string> names, others;
};

ContactFiles contact_files(const ContactOptions& o, const std::string& prefix) {
  ContactFiles f;
  const auto add = [&](bool written, const char* name) {
    (written ? f.names : f.others).push_back(prefix + name);
  };
  add(o.geometry == "groove", "raceway_segment.msh");
  add(o.geometry == "groove", "raceway_segment.msh.log");
  add(o.vtu, "vtu/");
  add(true, "force_approach.csv");
  add(true, "contact.json");
  return f;
}

// What one race gives to be written (on rank 0; empty elsewhere).
struct ContactResult {
  nlohmann::json json;  // contact.json
  std::string csv;      // force_approach.csv
};

// Solves `pr` (collective). Its groove mesh and VTU files go to their temporary names in `dir`
// under `prefix` (contact_files), prepared by rank 0 under the file set's lock.
ContactResult solve_contact(const ContactOptions& o, ContactProblem pr,
                            const std::filesystem::path& dir, const std::string& prefix,
                            MPI_Comm comm) {
  using namespace bearing;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  fem::HertzContactParameters& p = pr.p;
  if (o.geometry == "groove") {
    // gmsh on rank 0, the others wait.
    fem::mesh_raceway_segment(p.raceway, pr.raceway.groove_depth, pr.raceway.segment_angle,
                              temporary_path(dir, prefix + "raceway_segment.msh").string(),
                              temporary_path(dir, prefix + "raceway_segment.msh.log").string(),
                              comm);
    pr.raceway.record["land_depth"] = p.raceway.land_depth;
    pr.raceway.record["coarse_mesh"] = (dir / (prefix + "raceway_segment.msh")).string();
  }
  if (o.vtu) p.vtu_directory = temporary_path(dir, prefix + "vtu/").string();
  if (root && !o.quiet)
    std::cout << "bearing-fem contact: " << o.race << " race, "
              << (o.geometry == "hertz" ? "Hertz-reduced" : "groove (" + o.gap + " gap)")
              << ", E* = " << p.contact_modulus << " Pa, R_x = " << p.radius_x
              << " m, R_y = " << p.radius_y << " m, kappa = " << pr.rc.shape.ellipticity
              << ", loads " << pr.q_min << " .. " << pr.q_max << " N\n";

  const fem::HertzContactResult r = fem::solve_hertz_contact(p, comm);
  if (!root) return {};

  std::vector<double> d, f;
  for (const auto& s : r.steps) {
    d.push_back(s.approach);
    f.push_back(s.force);
  }
  const fem::PowerLawFit fit = fem::fit_power_law(d, f);
  std::ostringstream csv;
  csv << "approach,force,semi_axis_a,semi_axis_b,peak_pressure\n" << std::setprecision(17);
  for (const auto& s : r.steps)
    csv << s.approach << ',' << s.force << ',' << s.semi_major << ',' << s.semi_minor << ','
        << s.peak_pressure << '\n';
  const auto& last = r.steps.back();
  const RaceContact& rc = pr.rc;
  const double a_h = rc.semi_major(last.force), b_h = rc.semi_minor(last.force);
  if (!o.quiet)
    std::cout << std::setprecision(6) << "K_FE (n = 1.5) = " << fit.K_three_halves
              << " N/m^1.5, Hertz K = " << rc.K << " (" << 100 * (fit.K_three_halves / rc.K - 1)
              << " %); exponent " << fit.exponent << "; a " << 100 * (last.semi_major / a_h - 1)
              << " %, b " << 100 * (last.semi_minor / b_h - 1) << " %; " << r.wall_time << " s\n";
  return {contact_json(o, pr, r, fit), csv.str()};
}

// Creates `dir` (and its parents) for `--out out`; an input error if it cannot.
void create_folder(const std::filesystem::path& dir, const std::string& out) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw bearing::InputError("--out " + out + ": cannot create the folder " + dir.string() + " (" +
                              ec.message() + ")");
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

}  // namespace

CLI::App* add_contact_command(CLI::App& app, ContactOptions& o) {
  auto* contact = app.add_subcommand(
      "contact",
      "Ball-race contact by FE (--geometry hertz: the Hertz-reduced problem; groove: the ring "
      "segment with its true groove): force-approach curve, K, exponent, semi-axes, compared "
      "with the analytic Hertz solution");
  contact->add_option("CASE", o.case_path, "TOML case file (default: the built-in 6308 case)");
  contact->add_option("--set", o.sets, "Override a case-file value, TABLE.KEY=VALUE");
  contact->add_option("--race", o.race, "inner | outer")->required();
  contact->add_option("--geometry", o.geometry,
                      "hertz (block + paraboloid) | groove (ring segment with its true groove)");
  contact->add_option("--gap", o.gap,
                      "groove: exact (rigid sphere) | paraboloid (Hertz's gap on the real ring)");
  contact
      ->add_option("--groove-depth", o.groove_depth,
                   "groove: land depth below the groove edge over D (default 0.2)")
      ->check(bearing::cli::range(0, 0.49, true));
  contact
      ->add_option("--segment-angle", o.segment_angle,
                   "groove: segment half-angle [deg] (default 180/Z: half the ball pitch)")
      ->check(bearing::cli::range(0, 89.9));
  contact->add_option("--bore", o.bore, "groove: inner-ring bore d [m] (default: ISO 15)")
      ->check(bearing::cli::range(0, 10));
  contact
      ->add_option("--outside-diameter", o.outside,
                   "groove: outer-ring outside diameter [m] (default: ISO 15)")
      ->check(bearing::cli::range(0, 10));
  contact->add_option("--width", o.width, "groove: ring width B [m] (default: ISO 15)")
      ->check(bearing::cli::range(0, 10));
  contact->add_option("--out", o.out_dir, "Output folder (created if missing)")->required();
  contact->add_option("--cells", o.cells, "Finest cells per semi-minor axis b at the largest load")
      ->check(bearing::cli::range(1, 64));
  contact
      ->add_option("--stretch", o.stretch,
                   "Cell aspect h_y/h_x >= 1 (stretched along the major axis)")
      ->check(bearing::cli::range(1, 100));
  contact->add_option("--grading", o.grading, "Cell size >= distance / grading away from the patch")
      ->check(bearing::cli::range(1, 100));
  contact->add_option("--domain", o.domain, "Block size over the major semi-axis a (about)")
      ->check(bearing::cli::range(4, 1e4));
  contact->add_option("--tolerance", o.tolerance, "CG tolerance relative to the right-hand side")
      ->check(bearing::cli::range(0, 1e-3, true));
  contact->add_option("--steps", o.steps, "Approach steps")->check(bearing::cli::range(2, 100));
  contact
      ->add_option("--load-min", o.load_min,
                   "Smallest load [N] (default: load-max x --load-min-fraction)")
      ->check(bearing::cli::range(0, 1e7));
  contact
      ->add_option("--load-min-fraction", o.load_min_fraction,
                   "Smallest load over the largest when --load-min is not given (default 0.1)")
      ->check(bearing::cli::range(1e-6, 0.999));
  contact->add_option("--load-max", o.load_max, "Largest load [N] (default: Q_max of the case)")
      ->check(bearing::cli::range(0, 1e7));
  contact
      ->add_option("--peak-pressure", o.peak_pressure,
                   "Largest load given as its Hertz peak pressure on this race [Pa], e.g. "
                   "4.2e9 (ISO 76's static limit)")
      ->check(bearing::cli::range(0, 1e11));
  contact->add_flag("!--no-vtu", o.vtu, "Do not write VTU files");
  contact->add_flag("--quiet", o.quiet, "No progress output");
  return contact;
}

CLI::App* add_calibrate_command(CLI::App& app, ContactOptions& o, std::string& out) {
  // Three approach steps per race: the fitted K moves by < 0.01 % from six steps' and the run
  // takes half the time (both races of the 6308 in < 30 s on 2 cores: fem/README.md, issue 18).
  o.steps = 3;
  auto* calibrate = app.add_subcommand(
      "calibrate",
      "FE contact constants of both races (Q = K delta^n over light load to Q_max) "
      "for the lumped model's contact = \"calibrated\"");
  calibrate->add_option("CASE", o.case_path, "TOML case file (default: the built-in 6308 case)");
  calibrate->add_option("--set", o.sets, "Override a case-file value, TABLE.KEY=VALUE");
  calibrate->add_option("--out", out, "Calibration file to write (JSON)")->required();
  calibrate->add_option("--geometry", o.geometry, "hertz (default) | groove");
  calibrate->add_option("--gap", o.gap, "groove: exact | paraboloid");
  calibrate->add_option("--cells", o.cells, "Finest cells per semi-minor axis b at Q_max")
      ->check(bearing::cli::range(1, 64));
  calibrate->add_option("--grading", o.grading, "Cell size >= distance / grading")
      ->check(bearing::cli::range(1, 100));
  calibrate->add_option("--steps", o.steps, "Approach steps per race (default 3)")
      ->check(bearing::cli::range(2, 100));
  calibrate->add_option("--load-min", o.load_min, "Smallest load [N] (default: Q_max / 10)")
      ->check(bearing::cli::range(0, 1e7));
  calibrate->add_option("--load-max", o.load_max, "Largest load [N] (default: Q_max of the case)")
      ->check(bearing::cli::range(0, 1e7));
  calibrate->add_flag("--quiet", o.quiet, "No progress output");
  return calibrate;
}

// bearing-fem contact: one race solved; its files in DIR written all or nothing (AtomicFileSet,
// on rank 0, whose lock on DIR is held from before the solve to the commit).
int run_contact(const ContactOptions& o, MPI_Comm comm) {
  ContactProblem problem = contact_problem(o);  // bad input ends here, before any file
  const std::filesystem::path out(o.out_dir);
  const ContactFiles files = contact_files(o, "");
  std::optional<bearing::AtomicFileSet> set;  // rank 0's
  on_rank_zero(comm, [&] {
    create_folder(out, o.out_dir);
    set.emplace(out, files.names, files.others, "--out " + o.out_dir);
    if (o.vtu) set->fresh_folder("vtu/");
  });
  const ContactResult r = solve_contact(o, std::move(problem), out, "", comm);
  if (!set) return 0;
  set->write("force_approach.csv", r.csv);
  set->write("contact.json", r.json.dump(2) + "\n");
  set->commit();
  return 0;
}

// bearing-fem calibrate: both races over the case's load range (light load to Q_max), the power
// law Q = K δ^n fitted to each (exponent free), written for lumped's contact = "calibrated".
// The races' own contact.json and force_approach.csv go to <stem>_inner/ and <stem>_outer/ next
// to the calibration file: one file set in the file's folder, committed after both solves, the
// calibration file last.
int run_calibrate(const ContactOptions& base, const std::string& out_file, MPI_Comm comm) {
  using namespace bearing;
  namespace fs = std::filesystem;
  if (out_file.empty()) throw InputError("--out: give the calibration file to write");
  const fs::path file(out_file);
  if (!file.has_filename() || fs::is_directory(file))
    throw InputError("--out " + out_file + ": a folder; give the calibration file to write (JSON)");
  const fs::path dir = file.has_parent_path() ? file.parent_path() : ".";
  const std::string stem = file.stem().string();
  CalibrationDocument doc;
  ContactCalibration& cal = doc.calibration;
  std::string mesh;
  struct Race {
    const char* race;
    RaceLaw& law;
    RaceFitRecord& fit;
    ContactOptions o;
    ContactProblem problem;
    ContactResult result;
  } races[] = {{"inner", cal.inner, doc.inner_fit, base, {}, {}},
               {"outer", cal.outer, doc.outer_fit, base, {}, {}}};
  std::vector<std::string> names, others;
  for (auto& r : races) {
    r.o.race = r.race;
    r.o.vtu = false;
    r.problem = contact_problem(r.o);  // both races' input checked before any file is written
    const ContactFiles f = contact_files(r.o, stem + "_" + r.race + "/");
    names.insert(names.end(), f.names.begin(), f.names.end());
    others.insert(others.end(), f.others.begin(), f.others.end());
  }
  names.push_back(file.filename().string());  // last: once it is the new one, so are the others
  std::optional<AtomicFileSet> set;  // rank 0's; its lock on the folder is held to the commit
  on_rank_zero(comm, [&] {
    for (const auto& r : races) create_folder(dir / (stem + "_" + r.race), out_file);
    set.emplace(dir, names, others, "--out " + out_file);
  });
  for (auto& r : races)
    r.result = solve_contact(r.o, r.problem, dir, stem + "_" + r.race + "/", comm);
  if (!set) return 0;
  for (const auto& [race, law, fit, o, problem, result] : races) {
    const nlohmann::json& j = result.json;
    law.K = j["fe"]["K_free_exponent"];
    law.exponent = j["fe"]["exponent"];
    law.fit_residual = j["fe"]["fit_residual"];
    fit.K_three_halves = j["fe"]["K"];
    fit.hertz_K = j["hertz"]["K"];
    fit.details = stem + "_" + race;  // next to the file
    cal.load_min = j["load_range"]["min"];
    cal.load_max = j["load_range"]["max"];
    mesh += std::string(mesh.empty() ? "" : "; ") + race + ": " +
            std::to_string(j["mesh"]["cells"].get<unsigned long>()) + " cells, " +
            std::to_string(j["mesh"]["dofs"].get<unsigned long>()) + " DoFs";
    set->write(fit.details + "/force_approach.csv", result.csv);
    set->write(fit.details + "/contact.json", j.dump(2) + "\n");
  }
  const Case& c = races[0].problem.c;
  cal.bearing = c.bearing;
  cal.geometry = base.geometry == "hertz" ? "hertz" : "groove";
  const std::string body =
      cal.geometry == "hertz"
          ? "Hertz-reduced quarter block with E* and a rigid paraboloid"
          : "ring segment with its true groove (meshes/raceway_segment.geo), E* in the ring, "
            "rigid sphere (" +
                base.gap + " gap)";
  cal.method =
      "bearing-fem contact per race: 3-D linear elasticity, Q1, primal-dual active set, CG + "
      "Trilinos ML; " +
      body + "; Q = K delta^n fitted by least squares of ln Q on ln delta over " +
      std::to_string(base.steps) + " approach steps from light load to Q_max";
  std::ostringstream mesh_text;
  mesh_text << "N_b = " << base.cells << " cells per semi-minor axis at Q_max, grading "
            << base.grading << ", stretch " << base.stretch << "; ";
  cal.mesh = mesh_text.str() + mesh;
  cal.date = utc_now();
  doc.case_source = c.source;
  set->write(file.filename().string(), calibration_text(doc));
  set->commit();
  if (!base.quiet) {
    using nlohmann::json;  // the numbers as the file shows them
    std::cout << "calibration written to " << file.string() << ": inner K = " << json(cal.inner.K)
              << " N/m^" << json(cal.inner.exponent) << ", outer K = " << json(cal.outer.K)
              << " N/m^" << json(cal.outer.exponent) << '\n';
  }
  return 0;
}

}  // namespace bearing::fem
