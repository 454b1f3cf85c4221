// Structure family (issue 40): `bearing-fem modes` — the FE natural modes of a structure and the
// modal transfer path — against closed forms, its own convergence, a direct FE solve and the
// algebra of mass-normalised modes. The structures are written here (a gmsh .geo and a structure
// file each, in the FE runs' folder; bearing-fem meshes the .geo into tetrahedra, MSH 2.2, mm):
//
// - a free steel ring, centroid radius R = 50 mm, square section h = b = 4 mm (h/R = 0.08), its
//   circles cut into N = 96 segments: the in-plane flexural modes n = 2…5 against the thin
//   ring's closed form. The finite thickness lowers them: the Timoshenko ring (extension, shear,
//   rotary inertia; structure_reference.h) by Δ_n = −0.4 % (n = 2) to −2.6 % (n = 5). The thin
//   formula neglects terms of relative order (h/R)² n²: those and the curved bar's own section
//   effects of the same order, which stiffen (Winkler–Bach), so the 3-D ring lies between the
//   thin ring and the Timoshenko ring: the row's reference is the middle of that bracket,
//   f_thin (1 + Δ_n/2), and |Δ_n|/2 is the bias's share of the tolerance;
// - a steel cantilever 100 × 10 × 6 mm (x 10, y 6), ν = 0, clamped at z = 0: bending modes
//   against Timoshenko's beam with Cowper's shear coefficient (5/6 for ν = 0). ν = 0 because
//   with ν > 0 the 3-D clamp also holds the root section's Poisson contraction, which no beam
//   theory models (ν = 0.3: the 3-D beam is 0.4 % stiffer than Timoshenko's, fem/README.md); what
//   remains is the shear coefficient of a dynamic, non-uniform shear: the tolerance's bias share
//   is the frequency's change when k goes from Cowper's 5/6 to Mindlin's π²/12;
// - the cantilever's modal model at its seat (its tip face) against the direct harmonic solve of
//   bearing-fem (--frf): between two modes, near one, above the last kept; the tolerance is the
//   residual flexibility of the modes left out (harmonic_response.cc);
// - orthogonality (φᵀMφ = I, φᵀKφ = diag ω²) and Bessel's inequality for the effective masses;
// - the observed order of convergence under refinement against 2p = 4 (P2) on a free block of
//   hexahedra, and (reported at standard) the same on tetrahedra, whose order at these meshes is
//   the premise of the FE error bound below.
//
// The FE's own error: each frequency is computed on the gmsh mesh and on its global refinement
// (--refine 1: nested spaces, so f₁ ≤ f₀ and both converge from above). With the eigenvalue error
// ∝ h^q, f₁ − f_∞ = (f₀ − f₁)/(2^q − 1). Theory gives q = 2p = 4 for P2 on a smooth mode; on
// tetrahedra at these meshes the order is ~3 (pre-asymptotic: the reported row
// structure.convergence.tetrahedra measures it on a block), so the bound used is
// (f₀ − f₁)/(2² − 1), an order of 2 or more. The ring's
// polygons add the faceting bound: each circle lies between its polygon's inscribed circle,
// r cos(π/N), and r, so R shrinks by less than R π²/(2N²) and f ∝ 1/R² moves by less than π²/N².

#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "../context.h"
#include "../families.h"
#include "bearing/errors.h"
#include "check_util.h"
#include "structure_reference.h"

namespace bearing::verify {

namespace {

namespace ref = structure_reference;
constexpr double kPi = 3.14159265358979323846;

// --- the structures ---------------------------------------------------------------------------

struct Ring {
  double radius = 0.050, h = 0.004, b = 0.004;  // [m]
  double young = 210e9, poisson = 0.3, density = 7850;
  int segments = 96;  // per circle
  int sensors = 16;   // on the outer surface's mid-plane, equally spaced
};

struct Beam {
  double length = 0.100, bx = 0.010, hy = 0.006;  // [m]
  double young = 210e9, poisson = 0.0, density = 7850;
  double size = 0.003;  // gmsh's mesh size [m]
};

std::string number(double v) {
  return fmt("%.17g", v);
}

// The structure file: the .geo written beside it, the material (E through the Context), the
// boundary and the sensors (mesh units: mm).
std::string write_structure(const Context& ctx, const std::string& stem, const std::string& geo,
                            double young, double poisson, double density, const std::string& fixed,
                            const std::string& seat, const std::string& sensors) {
  const std::string geo_path = ctx.fem_input(stem, "geo", geo);
  const std::string name = geo_path.substr(geo_path.find_last_of('/') + 1);
  const std::string toml = "mesh = \"" + name + "\"\nmesh_unit = \"mm\"\n[material]\nyoung = " +
                           number(ctx.structure_young(young)) + "\npoisson = " + number(poisson) +
                           "\ndensity = " + number(density) + "\n[boundary]\nfixed = [" + fixed +
                           "]\nseat = \"" + seat + "\"\n[sensors]\n" + sensors;
  return ctx.fem_input(stem, "toml", toml);
}

std::string ring_structure(const Context& ctx, const Ring& r) {
  const double mm = 1e3;
  std::string geo =
      "// A free ring (bearing-verify, structure family): centroid radius R, section h x b [mm].\n"
      "SetFactory(\"OpenCASCADE\");\n" +
      fmt("R = %.17g; h = %.17g; b = %.17g; N = %.0f;\n", r.radius * mm, r.h * mm, r.b * mm,
          r.segments) +
      "Cylinder(1) = {0, 0, -b/2, 0, 0, b, R + h/2};\n"
      "Cylinder(2) = {0, 0, -b/2, 0, 0, b, R - h/2};\n"
      "BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
      "Physical Volume(\"ring\") = {3};\n"
      "Physical Surface(\"bore\") = {Surface In BoundingBox{-R, -R, -b, R, R, b}};\n"
      "// N segments on every circle; the mesh size h/1.5 elsewhere.\n"
      "Mesh.MeshSizeFromCurvature = N;\n"
      "Mesh.MeshSizeMax = 2 * Pi * (R + h/2) / N; Mesh.MeshSizeMin = h / 3;\n";
  std::string sensors;
  for (int j = 0; j < r.sensors; ++j) {
    const double t = 2 * kPi * j / r.sensors, rr = (r.radius + r.h / 2) * mm;
    sensors += fmt("s%02.0f = [%.12f, %.12f, 0]\n", j, rr * std::cos(t), rr * std::sin(t));
  }
  return write_structure(ctx, "ring", geo, r.young, r.poisson, r.density, "", "bore", sensors);
}

std::string beam_structure(const Context& ctx, const Beam& b) {
  const double mm = 1e3;
  const std::string geo =
      "// A cantilever (bearing-verify, structure family): x, y, length [mm], clamped at z = 0.\n"
      "SetFactory(\"OpenCASCADE\");\n" +
      fmt("bx = %.17g; hy = %.17g; L = %.17g; s = %.17g;\n", b.bx * mm, b.hy * mm, b.length * mm,
          b.size * mm) +
      "Box(1) = {-bx/2, -hy/2, 0, bx, hy, L};\n"
      "Physical Volume(\"beam\") = {1};\n"
      "Physical Surface(\"root\") = {5};\n"
      "Physical Surface(\"tip\") = {6};\n"
      "Mesh.MeshSizeMin = s; Mesh.MeshSizeMax = s;\n";
  return write_structure(ctx, "cantilever", geo, b.young, b.poisson, b.density, "\"root\"", "tip",
                         fmt("tip = [0, 0, %.17g]\n", b.length * mm));
}

// `bearing-fem modes` on a structure; modes.json as the toolkit's modal model reads it.
nlohmann::json modes(const Context& ctx, const std::string& structure, int count, int refine,
                     const std::vector<std::string>& extra = {}, int degree = 2) {
  std::vector<std::string> args = {"modes",    structure,
                                   "--degree", std::to_string(ctx.fe_degree(degree)),
                                   "--refine", std::to_string(refine),
                                   "--count",  std::to_string(count),
                                   "--no-vtu", "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  nlohmann::json j = ctx.fem(args, "modes.json");
  const double wall = j["wall_time_total"].get<double>();
  const std::string dir = j["dir"].get<std::string>();
  j = ctx.modal(std::move(j));
  j["wall_time_total"] = wall;
  j["dir"] = dir;
  return j;
}

// --- the ring ---------------------------------------------------------------------------------

// The in-plane flexural modes n = 2…5 of a ring run: each a pair (the ring's symmetry), the
// pair's mean. A mode is in-plane when its radial displacement at the sensors outweighs the axial
// tenfold; n is the sensors' dominant circumferential harmonic.
std::map<int, std::vector<double>> ring_modes(const nlohmann::json& j) {
  std::map<int, std::vector<double>> found;
  const auto& f = j["frequencies"];
  const auto& s = j["sensors"];
  for (std::size_t k = 0; k < f.size(); ++k) {
    const int ns = static_cast<int>(s.size());
    double radial2 = 0, axial2 = 0, best = 0;
    int n_best = 0;
    std::vector<double> ur(ns);
    for (int i = 0; i < ns; ++i) {
      const auto& p = s[i]["point"];
      const double t = std::atan2(p[1].get<double>(), p[0].get<double>());
      ur[i] = s[i]["x"][k].get<double>() * std::cos(t) + s[i]["y"][k].get<double>() * std::sin(t);
      radial2 += ur[i] * ur[i];
      axial2 += std::pow(s[i]["z"][k].get<double>(), 2);
    }
    for (int n = 0; n <= ns / 2; ++n) {
      std::complex<double> c = 0;
      for (int i = 0; i < ns; ++i) {
        const auto& p = s[i]["point"];
        c += ur[i] * std::exp(std::complex<double>(
                         0, -n * std::atan2(p[1].get<double>(), p[0].get<double>())));
      }
      if (std::abs(c) > best) best = std::abs(c), n_best = n;
    }
    if (radial2 > 10 * axial2 && n_best >= 2 && n_best <= 5)
      found[n_best].push_back(f[k].get<double>());
  }
  return found;
}

double pair_mean(const std::map<int, std::vector<double>>& m, int n, const std::string& run) {
  const auto it = m.find(n);
  if (it == m.end() || it->second.size() != 2)
    throw SolverError("the ring's in-plane n = " + std::to_string(n) +
                      " pair is not among the modes of " + run + " (found " +
                      std::to_string(it == m.end() ? 0 : it->second.size()) + " of 2)");
  return 0.5 * (it->second[0] + it->second[1]);
}

Check ring_check(int n) {
  Check c;
  c.id = fmt("structure.ring.n%.0f", n);
  c.family = "structure";
  c.reference = ReferenceKind::closed_form;
  c.compares = fmt(
      "value: z = (f_FE / f_ref - 1) / T, f_FE the free steel ring's in-plane flexural n = %.0f "
      "pair (mean) by bearing-fem modes, P2 tetrahedra, the gmsh mesh refined once; f_ref = "
      "f_thin (1 + D/2), f_thin the thin ring's closed form, D the Timoshenko ring's relative "
      "change from it; T = |D|/2 + (f0 - f1)/(3 f1) + pi^2/N^2; reference: 0",
      n);
  c.quantity = "z";
  c.unit = "-";
  c.tolerance = absolute(
      1.0,
      "T is derived: |D|/2 the finite thickness's bias (the 3-D ring lies between the thin ring "
      "and the Timoshenko ring: the neglected terms of order (h/R)^2 n^2 are the Timoshenko ring's "
      "softening and the curved bar's stiffening), (f0 - f1)/3 the FE error of the refined mesh "
      "for an eigenvalue order of 2 or more (P2: 4 asymptotically, ~3 at these meshes), pi^2/N^2 "
      "the faceting of circles cut into N = 96 segments; |z| <= 1 is agreement within it");
  c.level = Level::quick;
  c.cost = 20;
  c.catches = {"structure-young-x1.1", "fe-degree-lowered"};
  c.measure = [n](const Context& ctx) {
    const Ring r;
    const std::string s = ring_structure(ctx, r);
    const nlohmann::json j0 = modes(ctx, s, 18, 0), j1 = modes(ctx, s, 18, 1);
    if (j1["rigid_body_modes"].get<int>() != 6)
      throw SolverError("the free ring did not have its six rigid-body modes left out");
    const double f0 = pair_mean(ring_modes(j0), n, j0["dir"]);
    const double f1 = pair_mean(ring_modes(j1), n, j1["dir"]);
    const ref::Section sec{r.young, r.poisson, r.density, r.b, r.h};
    const double thin = ref::thin_ring_frequency(sec, r.radius, n);
    const double timo =
        ref::timoshenko_ring_frequency(sec, r.radius, n, ref::cowper_rectangle(r.poisson));
    const double d = timo / thin - 1, fref = thin * (1 + d / 2);
    const double fe = std::fabs(f0 - f1) / (3 * f1), facet = kPi * kPi / (r.segments * r.segments);
    const double t = std::fabs(d) / 2 + fe + facet;
    Outcome o{(f1 / fref - 1) / t, 0.0, "", {}};
    o.detail = fmt(
        "f_FE %.6g Hz (mesh %.6g Hz, refined %.6g Hz), f_thin %.6g Hz, Timoshenko ring %.6g Hz "
        "(D %+.3f %%); FE/thin %+.3f %%, FE/Timoshenko %+.3f %%; T = %.3f %% (thickness %.3f, FE "
        "%.4f, facets %.4f); rigid-body modes left out: %.0f (span residual %.1e); %.0f DoFs, "
        "%.1f s",
        f1, f0, f1, thin, timo, 100 * d, 100 * (f1 / thin - 1), 100 * (f1 / timo - 1), 100 * t,
        100 * std::fabs(d) / 2, 100 * fe, 100 * facet, j1["rigid_body_modes"].get<double>(),
        j1["solver"]["rigid_body_span"].get<double>(), j1["mesh"]["dofs"].get<double>(),
        j0["wall_time_total"].get<double>() + j1["wall_time_total"].get<double>());
    return o;
  };
  return c;
}

// --- the cantilever ---------------------------------------------------------------------------

// The beam's bending modes by direction (0 x, 1 y), ascending: a mode bends along d when the
// tip's rigid translation along d outweighs the other translations and the twist (θ_z times the
// section's half-diagonal) threefold.
std::map<int, std::vector<double>> bending_modes(const nlohmann::json& j, const Beam& b) {
  std::map<int, std::vector<double>> out;
  const auto& seat = j["seat"];
  const double arm = 0.5 * std::hypot(b.bx, b.hy);
  for (std::size_t k = 0; k < j["frequencies"].size(); ++k) {
    const double t[3] = {std::fabs(seat["x"][k].get<double>()),
                         std::fabs(seat["y"][k].get<double>()),
                         std::fabs(seat["z"][k].get<double>())};
    const double twist = std::fabs(seat["tilt_z"][k].get<double>()) * arm;
    for (int d = 0; d < 2; ++d)
      if (t[d] > 3 * (t[1 - d] + t[2] + twist)) out[d].push_back(j["frequencies"][k].get<double>());
  }
  return out;
}

struct BendingMode {
  int direction;  // 0 x, 1 y
  int index;      // 1, 2, 3 along that direction
};

Check cantilever_check(BendingMode m) {
  const char axis = "xy"[m.direction];
  Check c;
  c.id = std::string("structure.cantilever.") + axis + std::to_string(m.index);
  c.family = "structure";
  c.reference = ReferenceKind::closed_form;
  c.compares = std::string("value: z = (f_FE / f_T - 1) / T, f_FE the steel cantilever's ") +
               std::to_string(m.index) +
               (m.index == 1   ? "st"
                : m.index == 2 ? "nd"
                               : "rd") +
               " bending mode along " + axis +
               " by bearing-fem modes (P2 tetrahedra, the gmsh mesh refined once), f_T "
               "Timoshenko's clamped-free beam (Cowper's k = 5/6 for nu = 0); T = |f_T(pi^2/12) / "
               "f_T(5/6) - 1| + (f0 - f1)/(3 f1); reference: 0";
  c.quantity = "z";
  c.unit = "-";
  c.tolerance = absolute(
      1.0,
      "T is derived: the shear coefficient's uncertainty for a dynamic, non-uniform shear "
      "(Cowper's static 5/6 against Mindlin's pi^2/12, the only model term left with nu = 0) and "
      "(f0 - f1)/3 the FE error of the refined mesh for an eigenvalue order of 2 or more (P2: 4 "
      "asymptotically, ~3 at these meshes); |z| <= 1 is agreement within it");
  c.level = Level::quick;
  c.cost = 8;
  c.catches = {"structure-young-x1.1", "fe-degree-lowered"};
  c.measure = [m](const Context& ctx) {
    const Beam b;
    const std::string s = beam_structure(ctx, b);
    const nlohmann::json j0 = modes(ctx, s, 11, 0), j1 = modes(ctx, s, 11, 1);
    const auto modes0 = bending_modes(j0, b), modes1 = bending_modes(j1, b);
    const auto& list0 = modes0.count(m.direction) ? modes0.at(m.direction) : std::vector<double>{};
    const auto& list1 = modes1.count(m.direction) ? modes1.at(m.direction) : std::vector<double>{};
    if (static_cast<int>(std::min(list0.size(), list1.size())) < m.index)
      throw SolverError("the cantilever's bending mode " + std::to_string(m.index) + " along " +
                        std::string(1, "xy"[m.direction]) + " is not among its modes");
    const double f0 = list0[m.index - 1], f1 = list1[m.index - 1];
    // Bending along y: the section's depth along y is hy; along x it is bx.
    const ref::Section sec{b.young, b.poisson, b.density, m.direction == 1 ? b.bx : b.hy,
                           m.direction == 1 ? b.hy : b.bx};
    const double k = ref::cowper_rectangle(b.poisson);
    const double ft = ref::timoshenko_cantilever(sec, b.length, k, m.index).back();
    const double fm = ref::timoshenko_cantilever(sec, b.length, kPi * kPi / 12, m.index).back();
    const double eb = ref::euler_bernoulli_cantilever(sec, b.length, m.index).back();
    const double fe = std::fabs(f0 - f1) / (3 * f1), shear = std::fabs(fm / ft - 1);
    const double t = shear + fe;
    Outcome o{(f1 / ft - 1) / t, 0.0, "", {}};
    o.detail = fmt(
        "f_FE %.6g Hz (mesh %.6g Hz, refined %.6g Hz), Timoshenko %.6g Hz (k = pi^2/12: %.6g Hz), "
        "Euler-Bernoulli %.6g Hz; FE/Timoshenko %+.4f %%, T = %.4f %% (shear coefficient %.4f, "
        "FE %.4f); %.0f DoFs",
        f1, f0, f1, ft, fm, eb, 100 * (f1 / ft - 1), 100 * t, 100 * shear, 100 * fe,
        j1["mesh"]["dofs"].get<double>());
    return o;
  };
  return c;
}

// --- the modal model at the seat against the direct solve --------------------------------------

// N = 10 modes kept of the 11 computed; the 11th bounds the ones left out.
constexpr int kKept = 10;

struct FrfPoint {
  const char* tag;
  const char* what;
};
constexpr FrfPoint kFrfPoints[] = {{"between", "between modes 1 and 2 (their geometric mean)"},
                                   {"near", "1 % above mode 3"},
                                   {"above", "above the last kept mode (half way to the next)"}};

Check frf_check(int which) {
  const FrfPoint& p = kFrfPoints[which];
  Check c;
  c.id = std::string("structure.frf.") + p.tag;
  c.family = "structure";
  c.reference = ReferenceKind::fe;
  c.compares = std::string(
                   "value: z = max over a unit seat force along x and along y of |D - S - c| / w, "
                   "D the seat's translation along the force by bearing-fem's direct solve "
                   "(K - w^2 M) u = F, S the modal sum of the first 10 modes of modes.json, "
                   "sum_k s_k^2 / (w_k^2 - w^2), at a frequency ") +
               p.what +
               " of the cantilever; c, w the middle and half-width of [R, R w11^2/(w11^2 - w^2)], "
               "R the residual flexibility; reference: 0";
  c.quantity = "z";
  c.unit = "-";
  c.tolerance = absolute(
      1.0,
      "derived: the modes left out (k > 10) add sum_{k>10} s_k^2/(w_k^2 - w^2), each term "
      "between s_k^2/w_k^2 and that times w11^2/(w11^2 - w^2) below mode 11, so their sum lies in "
      "[R, R w11^2/(w11^2 - w^2)], R = G_static - sum_{k<=10} s_k^2/w_k^2 the residual flexibility "
      "(G_static by bearing-fem's static solve); w also holds 1e-9 of |D| and of the sum's terms "
      "(the solvers' relative accuracy: SLEPc 1e-10, MUMPS's backward error ~1e-15); |z| <= 1");
  c.level = Level::quick;
  c.cost = 3;
  c.catches = {"modal-shapes-x1.05"};
  c.measure = [which](const Context& ctx) {
    const Beam b;
    const std::string s = beam_structure(ctx, b);
    const nlohmann::json j = modes(ctx, s, kKept + 1, 0);
    const auto& f = j["frequencies"];
    const double hz[3] = {std::sqrt(f[0].get<double>() * f[1].get<double>()),
                          1.01 * f[2].get<double>(),
                          0.5 * (f[kKept - 1].get<double>() + f[kKept].get<double>())};
    const nlohmann::json frf =
        ctx.fem({"modes", s, "--degree", std::to_string(ctx.fe_degree(2)), "--refine", "0",
                 "--count", std::to_string(kKept + 1), "--no-vtu", "--quiet", "--frf",
                 fmt("%.17g,%.17g,%.17g", hz[0], hz[1], hz[2])},
                "frf.json");
    const double omega = 2 * kPi * frf["frequencies"][which].get<double>();
    const double w11 = 2 * kPi * f[kKept].get<double>();
    double worst = 0;
    std::string detail;
    for (const char* d : {"x", "y"}) {
      double modal = 0, modal_static = 0, terms = 0;
      for (int k = 0; k < kKept; ++k) {
        const double sk = j["seat"][d][k].get<double>(), wk = 2 * kPi * f[k].get<double>();
        modal += sk * sk / (wk * wk - omega * omega);
        terms += std::fabs(sk * sk / (wk * wk - omega * omega));
        modal_static += sk * sk / (wk * wk);
      }
      const double direct = frf["direct"][d][d][which].get<double>();
      const double residual = frf["static"][d][d][0].get<double>() - modal_static;
      const double hi = residual * w11 * w11 / (w11 * w11 - omega * omega);
      const double centre = 0.5 * (residual + hi);
      const double width = 0.5 * std::fabs(hi - residual) + 1e-9 * (std::fabs(direct) + terms);
      const double z = std::fabs(direct - modal - centre) / width;
      worst = std::max(worst, z);
      detail += std::string("; load ") + d +
                fmt(": direct %.6e m/N, modal %.6e m/N, difference %.4e, residual flexibility "
                    "R %.4e m/N, bracket [%.4e, %.4e], z %.2f",
                    direct, modal, direct - modal, residual, residual, hi, z);
    }
    return Outcome{worst,
                   0.0,
                   fmt("at %.6g Hz (modes 1-11: %.6g ... %.6g Hz)", omega / (2 * kPi),
                       f[0].get<double>(), f[kKept].get<double>()) +
                       detail,
                   {}};
  };
  return c;
}

// --- orthogonality and Bessel's inequality -----------------------------------------------------

Check orthogonality_check() {
  Check c;
  c.id = "structure.orthogonality.cantilever";
  c.family = "structure";
  c.reference = ReferenceKind::conservation;
  c.compares =
      "value: the largest of max|Phi^T M Phi - I| and max|Phi^T K Phi - diag(w^2)| / max w^2 "
      "(bearing-fem's measure on its matrices, 21 modes of the cantilever) and of sum_k "
      "m_eff,k / m - 1 in x, y, z (the effective masses as read from modes.json); reference: 0";
  c.quantity = "deviation";
  c.unit = "-";
  c.tolerance = absolute(
      1e-9,
      "derived: SLEPc's Krylov-Schur returns M-orthonormal Ritz vectors and bearing-fem "
      "normalises each, so the products are exact up to rounding in sums of 10^4-10^5 terms "
      "(~1e-12), the eigenpairs' residuals (tolerance 1e-10 relative, far smaller in practice) "
      "bound the stiffness products; for M-orthonormal shapes Bessel's inequality makes "
      "sum_k (phi_k^T M r_d)^2 <= r_d^T M r_d = m exactly");
  c.level = Level::quick;
  c.cost = 1;
  c.catches = {"modal-shapes-x1.05"};
  c.measure = [](const Context& ctx) {
    const Beam b;
    const nlohmann::json j = modes(ctx, beam_structure(ctx, b), 21, 0);
    const double mass = j["orthogonality"]["mass"].get<double>();
    const double stiffness = j["orthogonality"]["stiffness"].get<double>();
    const double m = j["total_mass"].get<double>();
    double bessel = 0, sums[3] = {0, 0, 0};
    for (int d = 0; d < 3; ++d) {
      for (const auto& e : j["effective_mass"][std::string(1, "xyz"[d])])
        sums[d] += e.get<double>();
      bessel = std::max(bessel, sums[d] / m - 1);
    }
    return Outcome{std::max({mass, stiffness, bessel}),
                   0.0,
                   fmt("Phi^T M Phi - I: %.2e; Phi^T K Phi - diag: %.2e; sum of effective masses "
                       "/ m: x %.4f, y %.4f, z %.4f (m = %.5g kg)",
                       mass, stiffness, sums[0] / m, sums[1] / m, sums[2] / m, m),
                   {}};
  };
  return c;
}

// --- the order of convergence -----------------------------------------------------------------

// A free 20 mm steel block (ν = 0): no clamp, no curved surface, no re-entrant corner, so its
// modes are smooth and its eigenvalues converge at the theoretical order 2p = 4 of degree-2
// elements. Hexahedra: a 2 x 2 x 2 gmsh mesh (transfinite); tetrahedra: gmsh's with size 6 mm.
std::string block_structure(const Context& ctx, bool hexahedra) {
  const std::string geo =
      hexahedra ? std::string(
                      "// A free 20 mm block in 2 x 2 x 2 hexahedra (bearing-verify, structure).\n"
                      "Point(1) = {0, 0, 0}; Point(2) = {20, 0, 0}; Point(3) = {20, 20, 0};\n"
                      "Point(4) = {0, 20, 0};\n"
                      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                      "Transfinite Curve{1, 2, 3, 4} = 3; Transfinite Surface{1};\n"
                      "Recombine Surface{1};\n"
                      "out[] = Extrude {0, 0, 20} { Surface{1}; Layers{2}; Recombine; };\n"
                      "Physical Volume(\"block\") = {out[1]};\n"
                      "Physical Surface(\"top\") = {out[0]};\n")
                : std::string(
                      "// A free 20 mm block in tetrahedra (bearing-verify, structure).\n"
                      "SetFactory(\"OpenCASCADE\");\n"
                      "Box(1) = {0, 0, 0, 20, 20, 20};\n"
                      "Physical Volume(\"block\") = {1};\n"
                      "Physical Surface(\"top\") = {6};\n"
                      "Mesh.MeshSizeMin = 6; Mesh.MeshSizeMax = 6;\n");
  return write_structure(ctx, hexahedra ? "block-hexahedra" : "block-tetrahedra", geo, 210e9, 0.0,
                         7850, "", "top", "");
}

// The observed order of the block's third elastic frequency (the first one not repeated by the
// cube's symmetry) from its mesh refined 0, 1, 2 times.
Outcome block_order(const Context& ctx, bool hexahedra) {
  const std::string s = block_structure(ctx, hexahedra);
  double f[3];
  std::string detail = "f3:";
  for (int r = 0; r < 3; ++r) {
    const nlohmann::json j = modes(ctx, s, 3, r);
    f[r] = j["frequencies"][2].get<double>();
    detail += fmt(" %.9g Hz (%.0f DoFs);", f[r], j["mesh"]["dofs"].get<double>());
  }
  const double p = std::log2((f[0] - f[1]) / (f[1] - f[2]));
  detail += fmt(" pairwise ratio %.3f, Richardson (order 4) %.9g Hz", (f[0] - f[1]) / (f[1] - f[2]),
                f[2] - (f[1] - f[2]) / 15);
  return Outcome{p, 4.0, detail, {}};
}

Check convergence_check(bool hexahedra) {
  Check c;
  c.id = std::string("structure.convergence.") + (hexahedra ? "hexahedra" : "tetrahedra");
  c.family = "structure";
  c.reference = ReferenceKind::convergence;
  c.compares = std::string(
                   "value: the observed order p = log2((f0 - f1)/(f1 - f2)) of a free 20 mm steel "
                   "block's third elastic frequency, its gmsh mesh of ") +
               (hexahedra ? "2 x 2 x 2 hexahedra" : "6 mm tetrahedra") +
               " refined 0, 1, 2 times (nested, degree 2); reference: 2p = 4, the order of an "
               "eigenvalue of degree-2 elements on a smooth mode";
  c.quantity = "order";
  c.unit = "-";
  if (hexahedra) {
    c.tolerance = absolute(
        0.5,
        "12 % of the order: three meshes of two to eight cells across are near, not in, the "
        "asymptotic range (the next term of the error's expansion moves a three-level estimate "
        "by a fraction of an order); 0.5 still tells degree 2's 4 from degree 1's 2");
    c.catches = {"fe-degree-lowered"};
  } else {
    // Reported: on these tetrahedral meshes the order is below 4 (pre-asymptotic); the rows on
    // tetrahedra bound the FE error with an order of 2 or more, which this row shows holds.
    c.tolerance = absolute(0.5, "reported, not judged: the tetrahedral rows' premise (order >= 2)");
    c.judged = false;
  }
  c.level = hexahedra ? Level::quick : Level::standard;
  c.cost = hexahedra ? 5 : 80;
  c.measure = [hexahedra](const Context& ctx) { return block_order(ctx, hexahedra); };
  return c;
}

}  // namespace

std::vector<Check> structure_checks() {
  std::vector<Check> all;
  for (int n = 2; n <= 5; ++n) all.push_back(ring_check(n));
  for (const BendingMode m :
       {BendingMode{1, 1}, BendingMode{1, 2}, BendingMode{1, 3}, BendingMode{0, 1}})
    all.push_back(cantilever_check(m));
  for (int k = 0; k < 3; ++k) all.push_back(frf_check(k));
  all.push_back(orthogonality_check());
  all.push_back(convergence_check(true));
  all.push_back(convergence_check(false));
  return all;
}

}  // namespace bearing::verify
