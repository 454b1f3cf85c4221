// `bearing-sim stiffness`: the operating points (the case, or the sweep's grid of it), each
// solved, then the files written all at once and the table printed.

#include "stiffness_command.h"

#include <charconv>
#include <cstdio>
#include <iostream>
#include <memory>
#include <system_error>

#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/stiffness_output.h"
#include "bearing/sweep.h"
#include "bearing/units.h"

namespace bearing_app {

namespace {

using bearing::InputError;

// Each point's JSON holds its balls: a bound that keeps stiffness.json to tens of megabytes.
constexpr std::size_t kMaxPoints = 100000;

// "operating point 2 of 3 (operation.axial_load = 100 N)", or "the operating point".
std::string point_name(std::size_t i, std::size_t n, const std::vector<bearing::SweepKey>& keys,
                       const bearing::SweepPoint& p) {
  if (keys.empty()) return "the operating point";
  std::string values;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::string unit = keys[k].integer ? "" : bearing::si_unit(keys[k].dimension).data();
    values += (k ? ", " : "") + keys[k].key + " = " + bearing::format_number(p.values[k]) +
              (unit.empty() ? "" : " " + unit);
  }
  return "operating point " + std::to_string(i + 1) + " of " + std::to_string(n) + " (" + values +
         ")";
}

// --ball-pass: an integer 4 … kMaxBallPassSamples, or 0 (no ball pass).
int ball_pass_samples(const std::string& text) {
  int n = -1;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, n);
  if (text.empty() || ec != std::errc() || ptr != end || (n != 0 && n < 4) ||
      n > bearing::kMaxBallPassSamples)
    throw InputError("--ball-pass " + text + ": allowed an integer from 4 to " +
                     std::to_string(bearing::kMaxBallPassSamples) +
                     " (cage angles through one ball pitch), or 0 to leave the ball pass out");
  return n;
}

// One point's case and solution (with its ball pass at `samples` cage angles, 0: none); its
// errors name the point.
bearing::StiffnessRow solve(const bearing::SweepBase& base, const bearing::SweepPoint& p,
                            int samples, const std::string& where) {
  try {
    const bearing::Case c = bearing::load_sweep_case(base, p.overrides);
    bearing::StiffnessRow row;
    row.values = p.values;
    row.speed = c.operation.speed;
    row.point = bearing::stiffness_point(c, samples);
    return row;
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  } catch (const bearing::SolverError& e) {
    throw bearing::SolverError(where + ": " + e.what());
  }
}

std::unique_ptr<bearing::SweepDesign> grid_of(const std::vector<std::string>& vary) {
  if (vary.empty()) return nullptr;
  std::vector<bearing::SweepAxis> axes;
  for (const auto& v : vary) axes.push_back(bearing::parse_vary(v));
  const std::size_t n = bearing::sweep_size(axes);
  if (n > kMaxPoints)
    throw InputError("--vary: " + std::to_string(n) +
                     " operating points in all; stiffness takes at "
                     "most " +
                     std::to_string(kMaxPoints) + " (the product of the axes' N)");
  return bearing::grid_design(std::move(axes));
}

}  // namespace

CLI::App* add_stiffness_command(CLI::App& app, StiffnessOptions& o, const std::string& case_help) {
  auto* cmd = app.add_subcommand(
      "stiffness",
      "The bearing's 5x5 stiffness K = dF/dq of the inner ring (x, y, z and the tilts gx, gy) at "
      "the case's operating point, from the 5-DOF static solution (rigid rings, each ball's "
      "centrifugal load at operation.speed with ball.centrifugal on, no damping) under its loads: "
      "operation.load (with the rotor weight when operation.gravity), "
      "operation.axial_load and operation.moment, whatever model.kind; or at every point of a "
      "--vary grid. Writes DIR/stiffness.csv (per point the varied keys, the 15 k_ij with units, "
      "the displacement, q_max, loaded_balls, the load: at the case's cage angle), "
      "DIR/stiffness.json (also the full matrix at the cage angle, each ball's load and contact "
      "angle, the ball pass, the rotor's matrix averaged over it, the units and assumptions) and "
      "DIR/stiffness_ball_pass.csv (per point and k_ij its value at the cage angle, mean, min, "
      "max and amplitudes at 1xBPFO, 2xBPFO, ... over one ball pass), all or nothing; prints the "
      "matrix (one point) or the main terms (a grid), and the ball pass's range. A rotor model "
      "takes K averaged over one ball pass (ROSS's table, stiffness.json's rotor.stiffness): "
      "where it is singular or near it a warning says why.");
  cmd->add_option("CASE", o.case_path, case_help);
  cmd->add_option("--set", o.sets, "Override one case-file value (repeat for more)")
      ->type_name("TABLE.KEY=VALUE")
      ->allow_extra_args(false);
  cmd->add_option("--vary", o.vary,
                  "KEY=FROM:TO:N, N values from FROM to TO (units allowed), repeat for more keys "
                  "(Cartesian product), e.g. --vary operation.axial_load=0:200:3")
      ->allow_extra_args(false);
  cmd->add_option("--out", o.out_dir, "Folder for the result files (created if missing)")
      ->required();
  cmd->add_option("--format", o.format,
                  "csv (default: stiffness.csv and stiffness.json) | ross: also "
                  "stiffness_ross.csv, the table ROSS's BearingElement reads (frequency [rad/s], "
                  "kxx, kxy, kyx, kyy [N/m] and cxx, cxy, cyx, cyy [N s/m]: K and C averaged over one "
                  "ball pass; C from the films with [lubricant], else 0; the points "
                  "may vary operation.speed only)")
      ->capture_default_str();
  cmd->add_option("--ball-pass", o.ball_pass,
                  "Cage angles through one ball pitch at which K is solved, each its own "
                  "equilibrium under the point's load: its mean, min, max and BPFO harmonics, the "
                  "parametric excitation (an integer from 4 to 4096; 0: leave it out, no "
                  "stiffness_ball_pass.csv)")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_flag("--quiet", o.quiet, "Print nothing on success");
  return cmd;
}

int stiffness_command(const StiffnessOptions& o) {
  if (o.format != "csv" && o.format != "ross")
    throw InputError("--format " + o.format +
                     ": allowed csv (stiffness.csv and stiffness.json) or ross (also "
                     "stiffness_ross.csv, ROSS's BearingElement table)");
  const int samples = ball_pass_samples(o.ball_pass);
  std::vector<bearing::Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(bearing::parse_override(s));
  const bearing::SweepBase base = bearing::sweep_base(o.case_path, overrides);
  const std::unique_ptr<bearing::SweepDesign> grid = grid_of(o.vary);
  const std::size_t n = grid ? grid->size() : 1;
  const std::vector<bearing::SweepKey> keys =
      grid ? grid->keys() : std::vector<bearing::SweepKey>{};
  bearing::StiffnessTable table;
  table.source = base.source;
  table.ball_pass_samples = samples;
  for (const auto& k : keys)
    table.keys.push_back({k.key, k.integer ? "" : std::string(bearing::si_unit(k.dimension))});
  for (std::size_t i = 0; i < n; ++i) {
    const bearing::SweepPoint p = grid ? grid->point(i) : bearing::SweepPoint{};
    table.rows.push_back(solve(base, p, samples, point_name(i, n, keys, p)));
  }
  const bearing::Case first = bearing::load_sweep_case(base, {});
  table.bearing = first.bearing.designation;
  table.lubricated = first.lubricant.enabled;
  bearing::write_stiffness(o.out_dir, table, o.format == "ross");
  // As run does: the result is written (a user may study it), with a warning.
  for (const std::string& warning :
       {bearing::stiffness_elastic_warning(table), bearing::stiffness_rotor_warning(table)})
    if (!warning.empty()) std::cerr << "bearing-sim: warning: " << warning << "\n";
  if (!o.quiet) {
    std::cout << bearing::stiffness_text(table);
    std::fprintf(stderr, "stiffness: wrote %s/ (%zu operating point%s)\n", o.out_dir.c_str(), n,
                 n == 1 ? "" : "s");
  }
  return 0;
}

}  // namespace bearing_app
