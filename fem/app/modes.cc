// `bearing-fem modes STRUCTURE --out DIR`: read the structure file and its gmsh mesh (or mesh its
// .geo with gmsh), check them, call the modal solver (fem/modes/elastic_modes.h), write
// modes.json (its keys: fem/README.md, "Natural modes"; the lumped model reads it), modes.vtu and
// with --frf frf.json, all or nothing as `contact` does. No physics here.

#include "app/modes.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/rank_zero.h"
#include "bearing/atomic_file_set.h"
#include "bearing/cli_options.h"
#include "bearing/errors.h"
#include "mesh/gmsh_mesh.h"
#include "mesh/gmsh_run.h"
#include "modes/elastic_modes.h"
#include "modes/structure_file.h"

namespace bearing::fem {

namespace {

using nlohmann::json;

// Everything checked before a file is written or a cell built.
struct ModesInput {
  StructureFile structure;
  GmshMesh mesh;
  ElasticModesParameters p;
};

// The fixed surfaces must hold every part of the mesh; a free-free mesh must be one part.
void check_parts(const StructureFile& s, const GmshMesh& mesh, const std::vector<int>& fixed) {
  unsigned int parts = 0;
  const std::vector<unsigned int> part = mesh_parts(mesh, parts);
  if (fixed.empty()) {
    if (parts > 1)
      throw InputError(s.source + ": the mesh " + mesh.file + " has " + std::to_string(parts) +
                       " separate parts: free-free it would have " + std::to_string(6 * parts) +
                       " rigid-body modes (six expected)");
    return;
  }
  const std::vector<bool> held = parts_touching(mesh, part, parts, fixed);
  const auto loose = std::count(held.begin(), held.end(), false);
  if (loose > 0)
    throw InputError(s.source + ": the fixed set leaves " + std::to_string(6 * loose) +
                     " rigid-body modes: " + std::to_string(loose) + " of the mesh's " +
                     std::to_string(parts) + " separate parts " +
                     (loose == 1 ? "touches" : "touch") + " no fixed surface");
}

bool is_geo(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".geo") == 0;
}

// The structure file, with the command line's overrides.
StructureFile structure_of(const ModesOptions& o) {
  StructureFile s = read_structure_file(o.structure);
  if (o.count > 0) s.count = o.count;
  if (o.max_frequency > 0) s.max_frequency = o.max_frequency;
  return s;
}

// The mesh `msh` (the structure's, or gmsh's from its .geo) checked against the structure and
// the options, and the solver's parameters.
ModesInput modes_input(const ModesOptions& o, StructureFile s, const std::string& msh) {
  ModesInput in;
  in.structure = std::move(s);
  in.mesh = read_gmsh_mesh(msh);
  const StructureFile& st = in.structure;
  check_structure_against_mesh(st, in.mesh);
  if (o.degree > 2 && in.mesh.cell_type == GmshMesh::CellType::tetrahedron)
    throw InputError("--degree " + std::to_string(o.degree) +
                     ": deal.II 9.4 has tetrahedral elements of degree 1 and 2 only (hexahedra "
                     "take 1-3); " +
                     st.mesh + " is a mesh of tetrahedra");
  ElasticModesParameters& p = in.p;
  for (const std::string& f : st.fixed) p.fixed.push_back(in.mesh.surface_tag(f));
  check_parts(st, in.mesh, p.fixed);
  p.mesh_scale = st.mesh_scale;
  p.young = st.young;
  p.poisson = st.poisson;
  p.density = st.density;
  p.seat = in.mesh.surface_tag(st.seat);
  p.seat_name = st.seat;
  for (const StructureSensor& sensor : st.sensors) p.sensors.push_back(sensor.point);
  p.count = st.count;
  p.max_frequency = st.max_frequency;
  p.degree = o.degree;
  p.refinements = o.refinements;
  p.tolerance = o.tolerance;
  p.frf_frequencies = o.frf;
  p.verbose = !o.quiet;
  return in;
}

json column(const std::vector<RigidFit>& fits, int what, int axis) {
  json a = json::array();
  for (const RigidFit& f : fits)
    a.push_back(what == 0 ? f.translation[axis] : what == 1 ? f.rotation[axis] : f.residual);
  return a;
}

// x, y, z, tilt_x, tilt_y, tilt_z, residual of a list of rigid fits.
json fits_json(const std::vector<RigidFit>& fits) {
  return {{"x", column(fits, 0, 0)},       {"y", column(fits, 0, 1)},
          {"z", column(fits, 0, 2)},       {"tilt_x", column(fits, 1, 0)},
          {"tilt_y", column(fits, 1, 1)},  {"tilt_z", column(fits, 1, 2)},
          {"residual", column(fits, 2, 0)}};
}

json modes_json(const ModesInput& in, const ElasticModesResult& r) {
  const StructureFile& s = in.structure;
  json sensors = json::array();
  for (std::size_t k = 0; k < s.sensors.size(); ++k) {
    const auto& fe = r.sensors[k];
    json j = {{"name", s.sensors[k].name},
              {"requested", s.sensors[k].point},
              {"point", fe.point},
              {"distance", fe.distance}};
    for (int d = 0; d < 3; ++d) {
      json c = json::array();
      for (const Vec3& u : fe.displacement) c.push_back(u[d]);
      j[std::string(1, "xyz"[d])] = c;
    }
    sensors.push_back(j);
  }
  json seat = fits_json(r.seat);
  json mesh = {{"file", s.mesh},
               {"unit", s.mesh_unit},
               {"format", in.mesh.version},
               {"element_type", r.cell_type},
               {"elements", r.cells},
               {"vertices", r.vertices},
               {"dofs", r.dofs},
               {"fe_degree", r.degree},
               {"refinements", in.p.refinements}};
  if (is_geo(s.mesh_path)) mesh["gmsh_output"] = "mesh.msh";  // beside modes.json
  seat["centre"] = r.seat_centre;
  seat["nodes"] = r.seat_nodes;
  seat["area"] = r.seat_area;
  return {
      {"format", "bearing-fem modes"},
      {"version", 1},
      {"structure", s.source},
      {"units",
       {{"frequency", "Hz"},
        {"length", "m"},
        {"shape", "kg^-1/2"},
        {"tilt", "rad kg^-1/2 m^-1"},
        {"modal_coordinate", "kg^1/2 m"},
        {"effective_mass", "kg"},
        {"young", "Pa"},
        {"density", "kg/m^3"},
        {"area", "m^2"},
        {"mass", "kg"},
        {"volume", "m^3"}}},
      {"mesh", mesh},
      {"material", {{"young", s.young}, {"poisson", s.poisson}, {"density", s.density}}},
      {"boundary", {{"fixed", s.fixed}, {"seat", s.seat}, {"free", s.fixed.empty()}}},
      {"rigid_body_modes", r.rigid_body_modes},
      {"count", r.frequencies.size()},
      {"frequencies", r.frequencies},
      {"effective_mass",
       {{"x", r.effective_mass[0]}, {"y", r.effective_mass[1]}, {"z", r.effective_mass[2]}}},
      {"seat", seat},
      {"sensors", sensors},
      {"orthogonality", {{"mass", r.orthogonality_mass}, {"stiffness", r.orthogonality_stiffness}}},
      {"solver",
       {{"method", "krylovschur shift-invert"},
        {"shift", r.shift},
        {"tolerance", r.tolerance},
        {"linear_solver", "mumps"},
        {"eigensolves", r.eigensolves},
        {"frequency_scale", r.frequency_scale},
        {"near_zero", r.near_zero},
        {"rigid_body_span", r.rigid_body_span},
        {"limited_by", r.limited_by}}},
      {"total_mass", r.total_mass},
      {"volume", r.volume},
      {"wall_time", r.wall_time},
      {"mpi_processes", r.mpi_processes}};
}

json frf_json(const ModesInput& in, const HarmonicResponse& h) {
  json j = {{"format", "bearing-fem frf"},
            {"version", 1},
            {"structure", in.structure.source},
            {"load",
             "a unit force along x, and one along y, spread uniformly over the seat (traction "
             "e/A); the seat's response is the rigid fit of the displacement, as modes.json's"},
            {"units", {{"frequency", "Hz"}, {"translation", "m/N"}, {"tilt", "rad/(N m)"}}},
            {"frequencies", h.frequencies},
            {"direct", {{"x", fits_json(h.direct[0])}, {"y", fits_json(h.direct[1])}}}};
  j["static"] = h.has_static ? json{{"x", fits_json({h.static_response[0]})},
                                    {"y", fits_json({h.static_response[1]})}}
                             : json(nullptr);
  return j;
}

// Every number finite (a NaN would be written as null).
void check_finite(const json& j, const std::string& file) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw SolverError(file + ": the solver produced a value that is not finite");
  if (j.is_structured())
    for (const auto& e : j) check_finite(e, file);
}

}  // namespace

CLI::App* add_modes_command(CLI::App& app, ModesOptions& o) {
  auto* cmd = app.add_subcommand(
      "modes",
      "Natural modes of an elastic structure (a housing) from a gmsh mesh: frequencies, "
      "mass-normalised shapes, the seat's rigid motion and the sensors' displacements per mode "
      "(modes.json, modes.vtu)");
  cmd->add_option("STRUCTURE", o.structure, "The structure file (TOML: mesh, material, boundary)")
      ->required();
  cmd->add_option("--out", o.out_dir, "Output folder (created if missing)")->required();
  cmd->add_option("--degree", o.degree, "Polynomial degree of the elements (default 2)")
      ->check(bearing::cli::range(1, 3));
  cmd->add_option("--refine", o.refinements,
                  "Global refinements of the mesh, each halving the cells (default 0)")
      ->check(bearing::cli::range(0, 4));
  cmd->add_option("--count", o.count, "Modes wanted (overrides [modes] count)")
      ->check(bearing::cli::range(1, 500));
  cmd->add_option("--max-frequency", o.max_frequency,
                  "No mode above this [Hz] (overrides [modes] max_frequency)")
      ->check(bearing::cli::range(0, 1e7, true));
  cmd->add_option("--tolerance", o.tolerance,
                  "The eigensolver's relative residual tolerance (default 1e-10)")
      ->check(bearing::cli::range(0, 1e-4, true));
  cmd->add_option("--frf", o.frf,
                  "f1,f2,... [Hz]: the seat's response to a unit seat force by a direct solve at "
                  "these frequencies (frf.json)")
      ->delimiter(',')
      ->check(bearing::cli::range(0, 1e7, true));
  cmd->add_flag("!--no-vtu", o.vtu, "Do not write modes.vtu");
  cmd->add_flag("--quiet", o.quiet, "No progress output");
  return cmd;
}

// The files in DIR, written all or nothing (AtomicFileSet, on rank 0, whose lock on DIR is held
// from before the solve to the commit), modes.json last.
int run_modes(const ModesOptions& o, MPI_Comm comm) {
  namespace fs = std::filesystem;
  if (o.frf.size() > 20)
    throw InputError("--frf: " + std::to_string(o.frf.size()) + " frequencies: at most 20");
  StructureFile structure = structure_of(o);
  const bool geo = is_geo(structure.mesh_path);
  // A mesh file is checked before any file is written; a .geo file needs gmsh first, whose mesh
  // and log go into DIR with the results.
  std::optional<ModesInput> in;
  if (!geo) in = modes_input(o, structure, structure.mesh_path);
  const fs::path out(o.out_dir);
  std::vector<std::string> names, others;
  (geo ? names : others).push_back("mesh.msh");
  (geo ? names : others).push_back("mesh.msh.log");
  (o.vtu ? names : others).push_back("modes.vtu");
  (o.frf.empty() ? others : names).push_back("frf.json");
  names.push_back("modes.json");
  std::optional<AtomicFileSet> set;  // rank 0's
  on_rank_zero(comm, [&] {
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec)
      throw InputError("--out " + o.out_dir + ": cannot create the folder (" + ec.message() + ")");
    set.emplace(out, names, others, "--out " + o.out_dir);
  });
  if (geo) {
    const std::string msh = temporary_path(out, "mesh.msh").string();
    mesh_geo_file(structure.mesh_path, msh, temporary_path(out, "mesh.msh.log").string(), comm);
    in = modes_input(o, structure, msh);
    in->mesh.file = (out / "mesh.msh").string();
  }
  if (o.vtu) in->p.vtu_file = temporary_path(out, "modes.vtu").string();
  const ElasticModesResult r = solve_elastic_modes(in->mesh, in->p, comm);
  if (!set) return 0;
  const json modes = modes_json(*in, r);
  check_finite(modes, "modes.json");
  if (!o.frf.empty()) {
    const json frf = frf_json(*in, r.frf);
    check_finite(frf, "frf.json");
    set->write("frf.json", frf.dump(2) + "\n");
  }
  set->write("modes.json", modes.dump(2) + "\n");
  set->commit();
  return 0;
}

}  // namespace bearing::fem
