// `bearing-fem radiate`: parses, sets up the bodies and motions, calls solve_helmholtz, compares
// with lumped's exact transfer functions (acoustics/sources.h), writes. No physics here.
//
//   bearing-fem radiate --source cylinder-monopole|cylinder-dipole|sphere-monopole|sphere-dipole
//                       --radius R [--microphone r,angle]... [--frequencies f1,f2,...] --out DIR
//   bearing-fem radiate --source bearing CASE [--microphone r,angle]... --out DIR
//
// DIR/radiation.csv: frequency,p_fe_re,p_fe_im,p_exact_re,p_exact_im,diff_db,diff_phase_deg,
// r,angle_deg,motion — one row per frequency, microphone and motion (per unit surface velocity,
// Pa per m/s). DIR/radiation.json: the set-up, the mesh, the largest differences (per octave band
// for the bearing), the wall time. DIR/vtu/radiation_NNN.vtu: the field per frequency.

#include "app/radiate.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bearing/acoustics/sources.h"
#include "bearing/case_file.h"
#include "bearing/cli_options.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "radiation/helmholtz_radiation.h"

namespace bearing::fem {
namespace {

using cplx = std::complex<double>;
constexpr double kDeg = pi / 180;

// One-third-octave band centres from 100 Hz to 20 kHz (IEC 61260 nominal values).
std::vector<double> third_octave_centres() {
  return {100,  125,  160,  200,  250,  315,  400,  500,  630,   800,   1000,  1250,
          1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000, 12500, 16000, 20000};
}

struct PolarPoint {
  double r, angle;  // [m], [rad]
};

PolarPoint parse_microphone(const std::string& s) {
  std::istringstream in(s);
  PolarPoint p{};
  char comma = 0;
  if (!(in >> p.r >> comma >> p.angle) || comma != ',' || !(in >> std::ws).eof() ||
      !std::isfinite(p.r) || !std::isfinite(p.angle) || p.r <= 0)
    throw InputError("--microphone = " + s +
                     ": expected r,angle with r > 0 in metres and the angle in degrees");
  p.angle *= kDeg;
  return p;
}

// Air at 20 °C (or the case's), with --density / --sound-speed applied where given (0: not given).
Air air_with_options(Air air, const RadiateOptions& o) {
  if (o.density != 0) {
    if (!(o.density > 0 && std::isfinite(o.density)))
      throw InputError("--density = " + std::to_string(o.density) + " kg/m^3: must be positive");
    air.density = o.density;
  }
  if (o.sound_speed != 0) {
    if (!(o.sound_speed > 0 && std::isfinite(o.sound_speed)))
      throw InputError("--sound-speed = " + std::to_string(o.sound_speed) +
                       " m/s: must be positive");
    air.sound_speed = o.sound_speed;
  }
  return air;
}

struct Comparison {
  double diff_db, diff_phase_deg;
};
Comparison compare(cplx fe, cplx exact) {
  const cplx ratio = fe / exact;
  return {20 * std::log10(std::abs(ratio)), std::arg(ratio) / kDeg};
}

void write_row(std::ostream& out, double f, cplx fe, cplx exact, const PolarPoint& mic,
               const std::string& motion) {
  const Comparison c = compare(fe, exact);
  out << f << ',' << fe.real() << ',' << fe.imag() << ',' << exact.real() << ',' << exact.imag()
      << ',' << c.diff_db << ',' << c.diff_phase_deg << ',' << mic.r << ',' << mic.angle / kDeg
      << ',' << motion << '\n';
}

constexpr const char* kCsvHeader =
    "frequency,p_fe_re,p_fe_im,p_exact_re,p_exact_im,diff_db,diff_phase_deg,r,angle_deg,motion\n";

// Writes DIR/radiation.csv and DIR/radiation.json, each to a .part file renamed when complete, so
// an interrupted run never leaves a result that looks whole.
void write_results(const std::string& dir, const std::string& csv, nlohmann::json j,
                   const HelmholtzResult& r) {
  j["frequencies"] = r.frequencies;
  j["wall_time"] = r.wall_time;
  j["mpi_processes"] = r.mpi_processes;
  const std::pair<std::string, std::string> files[] = {{"radiation.csv", csv},
                                                       {"radiation.json", j.dump(2) + "\n"}};
  for (const auto& [name, text] : files) {
    const std::string path = dir + "/" + name;
    std::ofstream out(path + ".part");
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path);
    std::filesystem::rename(path + ".part", path);
  }
}

nlohmann::json mesh_json(const HelmholtzParameters& p, const HelmholtzResult& r) {
  return {{"degree", p.degree},
          {"cells_per_wavelength", p.cells_per_wavelength},
          {"cells_per_radius", p.cells_per_radius},
          {"refinements", p.refinements},
          {"cells", r.n_cells},
          {"unknowns", r.n_dofs},
          {"largest_cell", r.largest_cell},
          {"physical_radius", r.physical_radius},
          {"pml_thickness", r.pml_thickness},
          {"pml_layers", r.pml_layers},
          {"pml_attenuation", p.pml_attenuation}};
}

HelmholtzParameters discretisation(const RadiateOptions& o) {
  HelmholtzParameters p;
  p.frequencies = o.frequencies.empty() ? third_octave_centres() : o.frequencies;
  p.degree = o.degree;
  p.cells_per_wavelength = o.cells_per_wavelength;
  p.cells_per_radius = o.cells_per_radius;
  p.refinements = o.refinements;
  p.physical_radius = o.physical_radius;
  p.pml_thickness = o.pml_thickness;
  p.pml_layers = o.pml_layers;
  p.pml_attenuation = o.pml_attenuation;
  p.work_dir = o.out_dir;
  if (o.vtu) p.vtu_dir = o.out_dir + "/vtu";
  p.verbose = !o.quiet;
  return p;
}

// --- one body, against its exact field ---------------------------------------------------------
int run_single(const RadiateOptions& o, MPI_Comm comm, bool root) {
  const std::string& name = o.source[0];
  const bool cylinder = name == "cylinder-monopole" || name == "cylinder-dipole";
  const bool sphere = name == "sphere-monopole" || name == "sphere-dipole";
  if (!cylinder && !sphere)
    throw InputError("--source = " + name +
                     ": must be cylinder-monopole, cylinder-dipole, sphere-monopole, "
                     "sphere-dipole or bearing CASE");
  if (o.source.size() > 1)
    throw InputError("--source " + name + " takes no case file (only --source bearing CASE)");
  if (!(o.radius > 0 && std::isfinite(o.radius)))
    throw InputError("--radius = " + std::to_string(o.radius) +
                     " m: the body's radius must be given and positive");
  const Air air = air_with_options(Air{}, o);
  const std::string reference = o.reference.empty() ? name : o.reference;
  const auto exact = make_source(reference, o.radius, air, "--reference");
  if (exact->cylindrical() != cylinder)
    throw InputError("--reference = " + reference + ": a " + (cylinder ? "cylinder" : "sphere") +
                     " must be compared with a " + (cylinder ? "cylinder" : "sphere") + "'s field");

  HelmholtzParameters p = discretisation(o);
  p.air = air;
  p.geometry = cylinder ? RadiationGeometry::planar : RadiationGeometry::axisymmetric;
  const bool breathing = name.find("monopole") != std::string::npos;
  p.bodies = {RadiatingBody{0, 0, o.radius, breathing, 0}};
  p.motions = {SurfaceMotion{0, breathing, 0, name}};
  std::vector<PolarPoint> mics;
  for (const auto& s : o.microphones) mics.push_back(parse_microphone(s));
  if (mics.empty()) mics.push_back({4 * o.radius, 0});
  for (const auto& m : mics) {
    if (m.r <= o.radius)
      throw InputError("--microphone r = " + std::to_string(m.r) + " m: must exceed the radius " +
                       std::to_string(o.radius) + " m");
    if (sphere && (m.angle < 0 || m.angle > pi))
      throw InputError("--microphone angle = " + std::to_string(m.angle / kDeg) +
                       " deg: a sphere's angle from its axis of motion is 0 to 180");
    // Planar: the cylinder translates along +x. Axisymmetric: the sphere along the axis (FE y).
    p.microphones.push_back(
        cylinder ? std::array<double, 2>{m.r * std::cos(m.angle), m.r * std::sin(m.angle)}
                 : std::array<double, 2>{m.r * std::sin(m.angle), m.r * std::cos(m.angle)});
  }
  if (root && o.vtu) std::filesystem::create_directories(p.vtu_dir);
  MPI_Barrier(comm);
  if (root && !o.quiet)
    std::cout << "radiate: " << name << ", a = " << o.radius << " m, " << p.frequencies.size()
              << " frequencies, " << mics.size() << " microphone(s)\n";
  const HelmholtzResult r = solve_helmholtz(p, comm);
  if (!root) return 0;

  std::ostringstream out;
  out << kCsvHeader << std::setprecision(12);
  double worst_db = 0, worst_deg = 0;
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t f = 0; f < r.frequencies.size(); ++f)
    for (std::size_t i = 0; i < mics.size(); ++i) {
      const cplx fe = r.pressure[f][0][i];
      const cplx ex =
          exact->transfer(two_pi * r.frequencies[f], mics[i].r, std::cos(mics[i].angle));
      write_row(out, r.frequencies[f], fe, ex, mics[i], name);
      const Comparison c = compare(fe, ex);
      if (!std::isfinite(c.diff_db) || !std::isfinite(c.diff_phase_deg))
        throw std::runtime_error("radiate: a non-finite pressure at " +
                                 std::to_string(r.frequencies[f]) + " Hz");
      worst_db = std::max(worst_db, std::abs(c.diff_db));
      worst_deg = std::max(worst_deg, std::abs(c.diff_phase_deg));
    }
  nlohmann::json j = {{"source", name},
                      {"reference", reference},
                      {"radius", o.radius},
                      {"air", {{"density", air.density}, {"sound_speed", air.sound_speed}}},
                      {"geometry", cylinder ? "planar" : "axisymmetric"},
                      {"mesh", mesh_json(p, r)},
                      {"max_abs_diff_db", worst_db},
                      {"max_abs_diff_phase_deg", worst_deg}};
  write_results(o.out_dir, out.str(), j, r);
  if (!o.quiet)
    std::cout << "radiate: " << r.n_dofs << " unknowns, " << r.n_cells << " cells; largest |diff| "
              << worst_db << " dB, " << worst_deg << " deg against " << reference << "; "
              << r.wall_time << " s on " << r.mpi_processes << " process(es)\n  wrote " << o.out_dir
              << "/radiation.csv\n";
  return 0;
}

// --- a bearing's section: all bodies together against the superposition of free ones ----------
int run_bearing(const RadiateOptions& o, MPI_Comm comm, bool root) {
  if (o.source.size() != 2)
    throw InputError("--source bearing needs the case file: --source bearing CASE");
  if (o.radius != 0)
    throw InputError("--radius: not used with --source bearing (the case sets the sizes)");
  if (!o.reference.empty()) throw InputError("--reference: not used with --source bearing");
  std::vector<Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(parse_override(s));
  const Case c = read_case_file(o.source[1], overrides);
  const Bearing& b = c.bearing;
  const double ball_r = 0.5 * b.ball_diameter, pitch = 0.5 * b.pitch_diameter;
  const double ring_case =
      c.acoustics.enabled ? c.acoustics.ring_radius : 0.5 * b.inner_raceway_diameter();
  if (!(o.gap >= 0 && std::isfinite(o.gap)))
    throw InputError("--gap = " + std::to_string(o.gap) + " m: must be positive (0: 5 % of D)");
  if (!std::isfinite(o.ball_angle))
    throw InputError("--ball-angle: must be a finite angle in degrees");
  const double gap = o.gap > 0 ? o.gap : 0.05 * b.ball_diameter;
  if (gap >= 0.5 * ball_r)
    throw InputError("--gap = " + std::to_string(gap) + " m: must be below a quarter of D (" +
                     std::to_string(0.5 * ball_r) + " m)");
  // In the section the ball touches the ring's raceway; a mesh needs them apart.
  const double ring_r = std::min(ring_case, pitch - ball_r - gap);
  const Air air = air_with_options(Air{c.acoustics.density, c.acoustics.sound_speed}, o);
  if (o.ball_motion != "radial" && o.ball_motion != "breathing")
    throw InputError("--ball-motion = " + o.ball_motion + ": must be radial or breathing");
  const bool breathing = o.ball_motion == "breathing";

  HelmholtzParameters p = discretisation(o);
  p.air = air;
  p.geometry = RadiationGeometry::planar;
  p.bodies.push_back({0, 0, ring_r, false, 0});
  p.motions.push_back({0, false, 0, "ring-x"});
  p.motions.push_back({0, false, pi / 2, "ring-y"});
  for (int j = 0; j < b.balls; ++j) {
    const double t = o.ball_angle * kDeg + two_pi * j / b.balls;
    p.bodies.push_back({pitch * std::cos(t), pitch * std::sin(t), ball_r, breathing, t});
    p.motions.push_back(
        {static_cast<std::size_t>(j + 1), breathing, t, "ball" + std::to_string(j + 1)});
  }
  std::vector<PolarPoint> mics;
  for (const auto& s : o.microphones) mics.push_back(parse_microphone(s));
  if (mics.empty())
    for (const auto& m : c.acoustics.microphones) mics.push_back({m.radius, m.angle});
  if (mics.empty())
    throw InputError(
        "radiate --source bearing: no microphone (give --microphone r,angle or "
        "acoustics.microphones in the case)");
  for (const auto& m : mics)
    p.microphones.push_back({m.r * std::cos(m.angle), m.r * std::sin(m.angle)});

  // Free-field references: each body alone, as the lumped model's superposition takes it.
  const auto ring_free = make_source("cylinder-dipole", ring_r, air);
  const auto ball_free =
      make_source(breathing ? "cylinder-monopole" : "cylinder-dipole", ball_r, air);
  auto free_field = [&](std::size_t motion, double omega, std::size_t i) {
    const auto& m = p.motions[motion];
    const auto& body = p.bodies[m.body];
    const double dx = p.microphones[i][0] - body.x, dy = p.microphones[i][1] - body.y;
    const double d = std::hypot(dx, dy);
    const double cos_angle = (dx * std::cos(m.direction) + dy * std::sin(m.direction)) / d;
    return (m.body == 0 ? *ring_free : *ball_free).transfer(omega, d, cos_angle);
  };

  if (root) {
    std::filesystem::create_directories(o.out_dir);
    if (o.vtu) std::filesystem::create_directories(p.vtu_dir);
  }
  MPI_Barrier(comm);
  if (root && !o.quiet)
    std::cout << "radiate: bearing section of " << c.source << ": ring a = " << ring_r << " m, "
              << b.balls << " balls of radius " << ball_r << " m on r = " << pitch << " m, "
              << p.frequencies.size() << " frequencies, " << mics.size() << " microphone(s)\n";
  const HelmholtzResult r = solve_helmholtz(p, comm);
  if (!root) return 0;

  // Octave bands (centre f_c, edges f_c/√2 … f_c√2). A comparison enters the table only where
  // the free-field pressure is within 20 dB of its largest over the microphones: in a dipole's
  // null the ratio measures nothing but the null (the CSV has every row).
  const std::vector<double> centres{125, 250, 500, 1000, 2000, 4000, 8000, 16000};
  struct Worst {
    double db = 0, deg = 0;
    bool any = false;
  };
  const std::vector<std::string> groups{"ring-x", "ring-y", "balls", "all"};
  std::vector<std::vector<Worst>> table(centres.size(), std::vector<Worst>(groups.size()));
  auto record = [&](double f, std::size_t g, const Comparison& cmp) {
    for (std::size_t band = 0; band < centres.size(); ++band)
      if (f >= centres[band] / std::sqrt(2.0) && f < centres[band] * std::sqrt(2.0)) {
        Worst& w = table[band][g];
        w.db = std::max(w.db, std::abs(cmp.diff_db));
        w.deg = std::max(w.deg, std::abs(cmp.diff_phase_deg));
        w.any = true;
      }
  };
  constexpr double kNull = 0.1;  // −20 dB

  std::ostringstream out;
  out << kCsvHeader << std::setprecision(12);
  for (std::size_t f = 0; f < r.frequencies.size(); ++f) {
    const double omega = two_pi * r.frequencies[f];
    const std::size_t nm = p.motions.size();
    // fe[m][i], free[m][i]; motion nm is every body together (1 m/s each, in phase).
    std::vector<std::vector<cplx>> fe(nm + 1, std::vector<cplx>(mics.size())), free = fe;
    for (std::size_t i = 0; i < mics.size(); ++i)
      for (std::size_t m = 0; m < nm; ++m) {
        fe[m][i] = r.pressure[f][m][i], free[m][i] = free_field(m, omega, i);
        fe[nm][i] += fe[m][i], free[nm][i] += free[m][i];
      }
    for (std::size_t m = 0; m <= nm; ++m) {
      double largest = 0;
      for (const cplx& q : free[m]) largest = std::max(largest, std::abs(q));
      for (std::size_t i = 0; i < mics.size(); ++i) {
        write_row(out, r.frequencies[f], fe[m][i], free[m][i], mics[i],
                  m < nm ? p.motions[m].name : "all");
        if (std::abs(free[m][i]) >= kNull * largest)
          record(r.frequencies[f], m < 2 ? m : (m < nm ? 2 : 3), compare(fe[m][i], free[m][i]));
      }
    }
  }
  nlohmann::json bands = nlohmann::json::array();
  for (std::size_t band = 0; band < centres.size(); ++band) {
    nlohmann::json row = {{"centre", centres[band]}};
    bool any = false;
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (table[band][g].any) {
        row[groups[g]] = {{"max_abs_diff_db", table[band][g].db},
                          {"max_abs_diff_phase_deg", table[band][g].deg}};
        any = true;
      }
    if (any) bands.push_back(row);
  }
  nlohmann::json mj = nlohmann::json::array();
  for (const auto& m : mics) mj.push_back({{"r", m.r}, {"angle_deg", m.angle / kDeg}});
  nlohmann::json j = {{"source", "bearing"},
                      {"case", c.source},
                      {"ring_radius", ring_r},
                      {"ring_radius_case", ring_case},
                      {"ball_radius", ball_r},
                      {"pitch_radius", pitch},
                      {"balls", b.balls},
                      {"first_ball_angle_deg", o.ball_angle},
                      {"ball_motion", o.ball_motion},
                      {"microphones", mj},
                      {"air", {{"density", air.density}, {"sound_speed", air.sound_speed}}},
                      {"mesh", mesh_json(p, r)},
                      {"octave_bands", bands}};
  write_results(o.out_dir, out.str(), j, r);
  if (!o.quiet) {
    std::cout << "radiate: " << r.n_dofs << " unknowns, " << r.n_cells << " cells, " << r.wall_time
              << " s on " << r.mpi_processes << " process(es)\n"
              << "  largest |FE - free-field superposition| [dB] per octave band (outside nulls):\n"
              << "      band   ring-x   ring-y    balls      all\n";
    for (std::size_t band = 0; band < centres.size(); ++band) {
      std::cout << "  " << std::setw(6) << centres[band] << " Hz";
      for (std::size_t g = 0; g < groups.size(); ++g) {
        std::cout << std::setw(9);
        if (table[band][g].any)
          std::cout << std::fixed << std::setprecision(3) << table[band][g].db;
        else
          std::cout << "-";
      }
      std::cout << std::defaultfloat << '\n';
    }
    std::cout << "  wrote " << o.out_dir << "/radiation.csv\n";
  }
  return 0;
}

}  // namespace

CLI::App* add_radiate_command(CLI::App& app, RadiateOptions& o) {
  auto* cmd = app.add_subcommand(
      "radiate",
      "Helmholtz radiation by FE (PML, real/imaginary split): one source against its exact "
      "field, or a bearing's 2-D section against the superposition of free sources");
  cmd->add_option("--source", o.source,
                  "cylinder-monopole | cylinder-dipole | sphere-monopole | sphere-dipole | "
                  "bearing CASE")
      ->required()
      ->expected(1, 2);
  cmd->add_option("--reference", o.reference,
                  "Exact source the FE field is compared with (default: the same source; e.g. "
                  "pulsating-sphere for seed 000's ball model)");
  cmd->add_option("--radius", o.radius, "Body radius a [m] (single source)")
      ->check(bearing::cli::range(0, 100));
  cmd->add_option("--microphone", o.microphones,
                  "r,angle: distance [m] from the centre and angle [deg] from the direction of "
                  "motion (repeatable; default 4a,0; bearing: the case's microphones)");
  cmd->add_option("--frequencies", o.frequencies,
                  "f1,f2,... [Hz] (default: the 24 one-third-octave centres 100 Hz - 20 kHz)")
      ->delimiter(',')
      ->check(bearing::cli::range(0, 1e6, true));
  cmd->add_option("--set", o.sets, "Override a case-file value, TABLE.KEY=VALUE (bearing)");
  cmd->add_option("--density", o.density, "Air density [kg/m^3] (default 1.204, 20 C)")
      ->check(bearing::cli::range(0, 1e4));
  cmd->add_option("--sound-speed", o.sound_speed, "Speed of sound [m/s] (default 343.2, 20 C)")
      ->check(bearing::cli::range(0, 1e5));
  cmd->add_option("--degree", o.degree, "Polynomial degree of the elements (default 4)")
      ->check(bearing::cli::range(1, 8));
  cmd->add_option("--cells-per-wavelength", o.cells_per_wavelength,
                  "Coarse cells per shortest wavelength (default 1.5)")
      ->check(bearing::cli::range(0, 20, true));
  cmd->add_option("--cells-per-radius", o.cells_per_radius,
                  "Coarse cells per body radius along its surface (default 4)")
      ->check(bearing::cli::range(4, 64));
  cmd->add_option("--refinements", o.refinements, "Global refinements of the coarse mesh")
      ->check(bearing::cli::range(0, 6));
  cmd->add_option("--physical-radius", o.physical_radius,
                  "Radius of the meshed zone R0 [m] (default: 1.25 x the bodies' extent, or 1.1 "
                  "x the farthest microphone within 3 x the extent; farther microphones are "
                  "reached by outgoing-mode continuation)")
      ->check(bearing::cli::range(0, 100));
  cmd->add_option("--pml-thickness", o.pml_thickness,
                  "Layer thickness L [m] (default: min(shortest wavelength / 2, R0 / 2))")
      ->check(bearing::cli::range(0, 100));
  cmd->add_option("--pml-layers", o.pml_layers,
                  "Coarse cells across the layer (default: automatic, at least 4 and about one "
                  "e-fold of the near field per cell at the lowest frequency)")
      ->check(bearing::cli::range(0, 200));
  cmd->add_option("--pml-attenuation", o.pml_attenuation,
                  "Decay of an outgoing wave across the layer, e^-s (default s = 12)")
      ->check(bearing::cli::range(0, 1000, true));
  cmd->add_option("--gap", o.gap,
                  "bearing: clearance between ring and balls in the section [m] (default 5 % of "
                  "D; the ring's radius is reduced to make it)")
      ->check(bearing::cli::range(0, 1));
  cmd->add_option("--ball-angle", o.ball_angle,
                  "bearing: ball 1's angle from +x [deg] (default -90)")
      ->check(bearing::cli::range(-360, 360));
  cmd->add_option("--ball-motion", o.ball_motion,
                  "bearing: radial (each ball translating along its radius, default) | breathing");
  cmd->add_option("--out", o.out_dir, "Output folder (created if missing)")->required();
  cmd->add_flag("!--no-vtu", o.vtu, "Do not write VTU files");
  cmd->add_flag("--quiet", o.quiet, "No progress output");
  return cmd;
}

int run_radiate(const RadiateOptions& o, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool root = rank == 0;
  if (root) {
    std::filesystem::create_directories(o.out_dir);
    std::filesystem::remove(o.out_dir + "/radiation.csv");  // never leave a stale result
    std::filesystem::remove(o.out_dir + "/radiation.json");
  }
  MPI_Barrier(comm);
  return o.source.at(0) == "bearing" ? run_bearing(o, comm, root) : run_single(o, comm, root);
}

}  // namespace bearing::fem
