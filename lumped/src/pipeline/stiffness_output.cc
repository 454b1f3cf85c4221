// The files and tables of `bearing-sim stiffness` (stiffness_output.h).

#include "bearing/stiffness_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "bearing/atomic_file_set.h"
#include "bearing/ball_pass_output.h"
#include "bearing/errors.h"
#include "bearing/json_helpers.h"
#include "bearing/units.h"

namespace bearing {

// format_number allows 2 ulp: not enough for files that hold the solver's doubles bit for bit.
std::string stiffness_number(double v) {
  if (v == 0) v = 0;  // "0", not "-0"
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string damping_unit(int i, int j) {
  const bool moment = i >= 3, tilt = j >= 3;
  if (moment && tilt) return "N*m*s/rad";
  if (moment) return "N*s";  // N m s per m
  return tilt ? "N*s/rad" : "N*s/m";
}

std::string damping_name(int i, int j) {
  return "c" + stiffness_name(i, j).substr(1);
}

nlohmann::json stiffness_matrix_json(const Matrix5& K) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 5; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 5; ++j) row.push_back(K(i, j));
    rows.push_back(row);
  }
  return rows;
}

namespace {

constexpr std::array<const char*, 5> kLoadNames = {"Fx", "Fy", "Fz", "Mx", "My"};

std::string with_unit(const std::string& name, const std::string& unit) {
  return name + " [" + (unit.empty() ? "-" : unit) + "]";
}

std::string num(double v, int digits = 5) {
  if (v == 0) v = 0;  // no "-0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// Fixed decimals: the solver's round-off (~1e-21 m) is not worth showing as "-1.3e-15 um".
std::string fixed(double v, int decimals) {
  if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string pad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

// "operation.axial_load = 100 N, bearing.clearance = 1e-05 m": the varied values of a row.
std::string point_values(const StiffnessTable& t, const StiffnessRow& r) {
  std::string out;
  for (std::size_t k = 0; k < t.keys.size(); ++k)
    out += (k ? ", " : "") + t.keys[k].key + " = " + format_number(r.values[k]) +
           (t.keys[k].unit.empty() ? "" : " " + t.keys[k].unit);
  return out;
}

nlohmann::json vector_json(const Vector5& v) {
  return nlohmann::json(std::vector<double>(v.data(), v.data() + 5));
}

// A point's rotor coefficients: K and, with [lubricant], C beside it.
nlohmann::json rotor_json(const RotorCoefficients& c, bool lubricated) {
  nlohmann::json j = {{"samples", c.samples},
                      {"stiffness", stiffness_matrix_json(c.stiffness)},
                      {"warnings", c.warnings}};
  if (lubricated) j["damping"] = stiffness_matrix_json(c.damping);
  return j;
}

nlohmann::json point_json(const StiffnessTable& t, const StiffnessRow& r) {
  const FiveDofSolution& s = r.point.solution;
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t k = 0; k < t.keys.size(); ++k) values[t.keys[k].key] = r.values[k];
  nlohmann::json j = {
      {"values", values},
      {"speed", r.speed},
      {"load", vector_json(r.point.load)},
      {"cage_angle", r.point.cage_angle},
      {"displacement", vector_json(s.displacement)},
      {"stiffness_at_cage_angle", stiffness_matrix_json(s.at.stiffness)},
      {"q_max", r.point.q_max()},
      {"loaded_balls", r.point.loaded_balls()},
      {"ball_angles", s.at.ball_angles},
      {"ball_loads", s.at.ball_loads},
      {"contact_angles", s.at.contact_angles},
      {"outer_ball_loads", s.at.outer_loads},
      {"outer_contact_angles", s.at.outer_contact_angles},
      {"peak_pressure",
       {{"inner", r.point.inner_peak_pressure}, {"outer", r.point.outer_peak_pressure}}},
      {"elastic", r.point.elastic()},
      {"residual", s.residual},
      {"iterations", s.iterations}};
  if (r.point.ball_pass) j["ball_pass"] = ball_pass_json(r.point);
  if (t.lubricated) {
    j["inner_films"] = s.at.inner_films;  // each ball's central film h_c [m]
    j["outer_films"] = s.at.outer_films;
    j["damping_at_cage_angle"] = stiffness_matrix_json(s.at.damping);
    if (r.point.ball_pass)
      j["ball_pass"]["damping_mean"] = stiffness_matrix_json(r.point.ball_pass->damping_mean);
  }
  if (r.point.rotor) j["rotor"] = rotor_json(*r.point.rotor, t.lubricated);
  return j;
}

nlohmann::json damping_units_json() {
  nlohmann::json c = nlohmann::json::array();
  for (int i = 0; i < 5; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 5; ++j) row.push_back(damping_unit(i, j));
    c.push_back(row);
  }
  return c;
}

nlohmann::json units_json(bool ball_pass) {
  nlohmann::json k = nlohmann::json::array();
  for (int i = 0; i < 5; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 5; ++j) row.push_back(stiffness_unit(i, j));
    k.push_back(row);
  }
  nlohmann::json u = {{"values", "SI, the unit of each key in varied[]"},
                      {"speed", "rad/s"},
                      {"load", kStiffnessLoadUnits},
                      {"cage_angle", "rad"},
                      {"displacement", kStiffnessDofUnits},
                      {"stiffness", k},
                      {"stiffness_at_cage_angle", "units.stiffness, entry by entry"},
                      {"q_max", "N"},
                      {"ball_angles", "rad"},
                      {"ball_loads", "N"},
                      {"contact_angles", "rad"},
                      {"outer_ball_loads", "N"},
                      {"outer_contact_angles", "rad"},
                      {"peak_pressure", "Pa"},
                      {"pressure_limit", "Pa"},
                      {"residual", "1"}};
  if (ball_pass) {
    u.update(ball_pass_units_json("units.stiffness"));
    u["rotor.stiffness"] = "units.stiffness, entry by entry";
  }
  return u;
}

constexpr std::array<const char*, 5> kAssumptions = {
    "the 5-DOF static equilibrium of the inner ring (x, y, z, gx, gy) on Hertzian ball contacts "
    "Q = K delta^n, each ball's contact angle following the deflection (five_dof_static.h)",
    "rigid rings; the outer ring fixed",
    "at operation.speed each ball carries its centrifugal load m_b w_c^2 d_m/2 (ball.centrifugal, "
    "on by default) and has its own inner and outer contact angles (Jones); the gyroscopic "
    "moment is neglected",
    "no damping: dry contacts, the bearing's damping is not modelled without [lubricant] (ROSS's "
    "cxx..cyy are written as 0)",
    "K = dF/dq is the tangent stiffness at the equilibrium under the load F, symmetric; the "
    "force the bearing exerts on the ring for a small extra displacement dq is -K dq"};

constexpr const char* kRotorDefinition =
    "the coefficients a linear rotor model takes (ROSS's kxx, kxy, kyx, kyy are "
    "rotor.stiffness[0..1][0..1], stiffness_ross.csv): rotor.stiffness is K averaged over one "
    "ball pass, the mean of ball_pass's `samples` cage angles (ball_pass.mean), where the cage "
    "angle has no say; rotor.warnings says why it is singular or near it: K = 0 (no ball loaded "
    "at any cage angle, the load in the clearance), or the translations (x, y, z) or the tilts "
    "(gx, gy) with their smallest eigenvalue below 1e-9 times their largest (each cage angle's K "
    "is positive semi-definite, so the mean is singular only along a direction unsupported at "
    "every cage angle)";

}  // namespace

std::string stiffness_csv(const StiffnessTable& t) {
  std::ostringstream o;
  std::vector<std::string> header;
  for (const auto& k : t.keys) header.push_back(with_unit(k.key, k.unit));
  for (int i = 0; i < 5; ++i)
    for (int j = i; j < 5; ++j)
      header.push_back(with_unit(stiffness_name(i, j), stiffness_unit(i, j)));
  for (int i = 0; i < 5; ++i) header.push_back(with_unit(kStiffnessDofs[i], kStiffnessDofUnits[i]));
  header.push_back("q_max [N]");
  header.push_back("loaded_balls");
  for (int i = 0; i < 5; ++i) header.push_back(with_unit(kLoadNames[i], kStiffnessLoadUnits[i]));
  if (t.lubricated)
    for (int i = 0; i < 5; ++i)
      for (int j = i; j < 5; ++j)
        header.push_back(with_unit(damping_name(i, j), damping_unit(i, j)));
  for (std::size_t c = 0; c < header.size(); ++c) o << (c ? "," : "") << header[c];
  o << "\n";
  for (const StiffnessRow& r : t.rows) {
    const FiveDofSolution& s = r.point.solution;
    std::vector<std::string> cells;
    for (double v : r.values) cells.push_back(stiffness_number(v));
    for (int i = 0; i < 5; ++i)
      for (int j = i; j < 5; ++j) cells.push_back(stiffness_number(s.at.stiffness(i, j)));
    for (int i = 0; i < 5; ++i) cells.push_back(stiffness_number(s.displacement(i)));
    cells.push_back(stiffness_number(r.point.q_max()));
    cells.push_back(std::to_string(r.point.loaded_balls()));
    for (int i = 0; i < 5; ++i) cells.push_back(stiffness_number(r.point.load(i)));
    if (t.lubricated)
      for (int i = 0; i < 5; ++i)
        for (int j = i; j < 5; ++j) cells.push_back(stiffness_number(s.at.damping(i, j)));
    for (std::size_t c = 0; c < cells.size(); ++c) o << (c ? "," : "") << cells[c];
    o << "\n";
  }
  return o.str();
}

nlohmann::json stiffness_json(const StiffnessTable& t) {
  using nlohmann::json;
  json varied = json::array();
  for (const auto& k : t.keys) varied.push_back({{"key", k.key}, {"unit", k.unit}});
  json points = json::array();
  for (const StiffnessRow& r : t.rows) points.push_back(point_json(t, r));
  json assumptions = kAssumptions;
  if (t.lubricated)
    assumptions[3] =
        "[lubricant]: each contact's EHL film (Hamrock-Dowson h_c) in series with Hertz, and its "
        "squeeze-film damping (isoviscous, a lower estimate); the films at the free contact angle "
        "and the pure-rolling cage speed (ehl_film.h); ROSS's cxx..cyy are C averaged over one "
        "ball "
        "pass (rotor.damping)";
  json j = {{"case", {{"source", t.source}, {"bearing", t.bearing}}},
            {"model",
             {{"name", "5-DOF static solution of the inner ring"}, {"assumptions", assumptions}}},
            {"dofs", kStiffnessDofs},
            {"loads", kLoadNames},
            {"stiffness_definition",
             "stiffness_at_cage_angle[i][j] = dF_i/dq_j at the equilibrium with ball 0 at the "
             "case's cage angle (cage_angle), F = (Fx, Fy, Fz, Mx, My) the load on the inner "
             "ring, q = (x, y, z, gx, gy) its displacement and tilts about +x and +y; y is up. "
             "It depends on where the balls stand; a rotor model takes rotor.stiffness"},
            {"pressure_limit", kElasticPressureLimit},
            {"varied", varied},
            {"points", points},
            {"units", units_json(t.ball_pass_samples > 0)}};
  if (t.ball_pass_samples > 0) {
    j["ball_pass_definition"] = kBallPassDefinition;
    j["rotor_definition"] = kRotorDefinition;
  }
  if (t.lubricated) {
    j["damping_definition"] =
        "damping_at_cage_angle[i][j] = dF_i/d(dq_j/dt), the squeeze films of the EHL contacts "
        "(five_dof_static.h; the film's stiffness is in series with Hertz in "
        "stiffness_at_cage_angle); rotor.damping its mean over one ball pass";
    j["units"]["damping_at_cage_angle"] = damping_units_json();
    j["units"]["inner_films"] = j["units"]["outer_films"] = "m";
    if (t.ball_pass_samples > 0) {
      j["units"]["ball_pass.damping_mean"] = "units.damping_at_cage_angle";
      j["units"]["rotor.damping"] = "units.damping_at_cage_angle, entry by entry";
    }
  }
  require_finite(j);
  return j;
}

namespace {

// The largest |K_ij| of the block of one unit: forces or moments (rows) by displacements or
// tilts (columns); the off-diagonal blocks taken together, as K is symmetric.
double block_scale(const Matrix5& K, bool moment_row, bool tilt_column) {
  double m = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const bool mixed = (i >= 3) != (j >= 3), want_mixed = moment_row != tilt_column;
      if (mixed ? want_mixed : (!want_mixed && (i >= 3) == moment_row))
        m = std::max(m, std::fabs(K(i, j)));
    }
  return m;
}

}  // namespace

std::string stiffness_matrix_text(const Matrix5& K, const std::string& indent) {
  std::ostringstream o;
  o << indent << pad("K = dF/dq", 12);
  for (int j = 0; j < 5; ++j) o << pad(with_unit(kStiffnessDofs[j], kStiffnessDofUnits[j]), 13);
  o << "\n";
  for (int i = 0; i < 5; ++i) {
    o << indent << pad(with_unit(kLoadNames[i], kStiffnessLoadUnits[i]), 12);
    for (int j = 0; j < 5; ++j) {
      // A term at round-off of its block's largest (e.g. 1e-9 N/m beside 1e7 N/m) shows as 0.
      const double scale = block_scale(K, i >= 3, j >= 3);
      o << pad(num(std::fabs(K(i, j)) <= 1e-12 * scale ? 0.0 : K(i, j)), 13);
    }
    o << "\n";
  }
  o << indent
    << "units: N/m (Fx, Fy, Fz by x, y, z), N/rad (Fx, Fy, Fz by gx, gy), N (Mx, My by x, y, z), "
       "N*m/rad (Mx, My by gx, gy); symmetric\n";
  return o.str();
}

std::string damping_matrix_text(const Matrix5& C, const std::string& indent) {
  std::ostringstream o;
  o << indent << pad("C = dF/dq'", 12);
  for (int j = 0; j < 5; ++j)
    o << pad(with_unit(kStiffnessDofs[j], kStiffnessDofUnits[j] + std::string("/s")), 13);
  o << "\n";
  for (int i = 0; i < 5; ++i) {
    o << indent << pad(with_unit(kLoadNames[i], kStiffnessLoadUnits[i]), 12);
    for (int j = 0; j < 5; ++j) {
      const double scale = block_scale(C, i >= 3, j >= 3);
      o << pad(num(std::fabs(C(i, j)) <= 1e-12 * scale ? 0.0 : C(i, j)), 13);
    }
    o << "\n";
  }
  o << indent
    << "units: N*s/m (Fx, Fy, Fz by x, y, z), N*s/rad (by gx, gy), N*s (Mx, My by x, y, z), "
       "N*m*s/rad (Mx, My by gx, gy); the squeeze films of the EHL contacts\n";
  return o.str();
}

std::string stiffness_elastic_warning(const StiffnessTable& t) {
  const auto beyond = [](const StiffnessRow& r) { return !r.point.elastic(); };
  const auto first = std::find_if(t.rows.begin(), t.rows.end(), beyond);
  if (first == t.rows.end()) return "";
  const auto n = std::count_if(t.rows.begin(), t.rows.end(), beyond);
  const double p = std::max(first->point.inner_peak_pressure, first->point.outer_peak_pressure);
  std::string where = t.keys.empty()
                          ? "at the operating point"
                          : "at " + std::to_string(n) + " of " + std::to_string(t.rows.size()) +
                                " operating points (first: " + point_values(t, *first) + ")";
  return where + " the most loaded ball's peak Hertz pressure, " + num(p * 1e-9, 3) +
         " GPa, passes the elastic limit of " + num(kElasticPressureLimit * 1e-9, 2) +
         " GPa (ISO 76): the contacts yield, and the elastic contact law behind K does not hold "
         "there";
}

std::string stiffness_note(const StiffnessPoint& p, const std::string& indent) {
  const int n = p.loaded_balls();
  if (n == 0)
    return indent +
           "no ball is loaded (the ring sits in the clearance): K = 0; give operation.load, "
           "operation.axial_load or operation.moment\n";
  if (n < 3)
    return indent + "only " + std::to_string(n) + " ball" + (n == 1 ? "" : "s") +
           " loaded at this cage angle: K here is singular (a ball stiffens the ring in two "
           "directions only); " +
           (p.rotor ? "a rotor model takes K averaged over one ball pass; " : "") +
           "a preload (operation.axial_load) or a larger load loads more balls\n";
  return "";
}

std::string stiffness_rotor_warning(const StiffnessTable& t) {
  const auto warned = [](const StiffnessRow& r) {
    return r.point.rotor && !r.point.rotor->warnings.empty();
  };
  const auto first = std::find_if(t.rows.begin(), t.rows.end(), warned);
  if (first == t.rows.end()) return "";
  const auto n = std::count_if(t.rows.begin(), t.rows.end(), warned);
  std::string out = t.keys.empty()
                        ? "at the operating point"
                        : "at " + std::to_string(n) + " of " + std::to_string(t.rows.size()) +
                              " operating points (first: " + point_values(t, *first) + ")";
  out +=
      " the rotor stiffness (K averaged over one ball pass: stiffness_ross.csv, "
      "stiffness.json's rotor) is singular or near it";
  for (const std::string& w : first->point.rotor->warnings) out += "\n  " + w;
  return out;
}

std::string stiffness_text(const StiffnessTable& t) {
  std::ostringstream o;
  o << "Bearing stiffness (5-DOF static solution of the inner ring: rigid rings, the balls' "
       "centrifugal load at the case's speed, "
    << (t.lubricated ? "the EHL films and their squeeze damping" : "no damping")
    << ")\nCase: " << t.source << (t.bearing.empty() ? "" : " (" + t.bearing + ")") << "\n";
  if (t.rows.size() == 1) {
    const StiffnessPoint& p = t.rows.front().point;
    const Vector5& q = p.solution.displacement;
    if (!t.keys.empty()) o << "Point: " << point_values(t, t.rows.front()) << "\n";
    o << "Load on the inner ring: Fx = " << num(p.load(0)) << " N, Fy = " << num(p.load(1))
      << " N, Fz = " << num(p.load(2)) << " N, Mx = " << num(p.load(3))
      << " N*m, My = " << num(p.load(4)) << " N*m\n"
      << "Displacement: x = " << fixed(q(0) * 1e6, 4) << " um, y = " << fixed(q(1) * 1e6, 4)
      << " um, z = " << fixed(q(2) * 1e6, 4) << " um, gx = " << fixed(q(3) * 1e6, 4)
      << " urad, gy = " << fixed(q(4) * 1e6, 4) << " urad\n"
      << "Balls: " << p.loaded_balls() << " of " << p.solution.at.ball_loads.size()
      << " loaded, the largest load " << num(p.q_max()) << " N\n\n"
      << "K at the case's cage angle (ball 0 at " << num(p.cage_angle) << " rad):\n"
      << stiffness_matrix_text(p.solution.at.stiffness);
    if (t.lubricated)
      o << "(the EHL films in series with Hertz: [lubricant]); C at the case's cage angle:\n"
        << damping_matrix_text(p.solution.at.damping);
    o << stiffness_note(p);
    if (p.rotor) {
      o << "\nK averaged over one ball pass (" << p.rotor->samples
        << " cage angles): the matrix a rotor model takes (stiffness_ross.csv, stiffness.json's "
           "rotor.stiffness):\n"
        << stiffness_matrix_text(p.rotor->stiffness);
      if (t.lubricated)
        o << "C averaged over one ball pass (stiffness_ross.csv's cxx ... cyy, rotor.damping):\n"
          << damping_matrix_text(p.rotor->damping);
    }
    o << ball_pass_text(t);
    return o.str();
  }
  o << t.rows.size()
    << " operating points; the main terms at the case's cage angle (every term: stiffness.csv; "
       "the rotor's, averaged over one ball pass: the mean below)\n";
  std::vector<std::string> head;
  for (const auto& k : t.keys) head.push_back(with_unit(k.key, k.unit));
  for (int i = 0; i < 5; ++i) head.push_back(with_unit(stiffness_name(i, i), stiffness_unit(i, i)));
  head.push_back("q_max [N]");
  head.push_back("loaded_balls");
  std::vector<std::size_t> width;
  for (const auto& h : head) width.push_back(std::max<std::size_t>(h.size() + 2, 13));
  for (std::size_t c = 0; c < head.size(); ++c) o << pad(head[c], width[c]);
  o << "\n";
  for (const StiffnessRow& r : t.rows) {
    std::vector<std::string> cells;
    for (double v : r.values) cells.push_back(num(v));
    const Matrix5& K = r.point.solution.at.stiffness;
    for (int i = 0; i < 5; ++i)
      cells.push_back(
          num(std::fabs(K(i, i)) <= 1e-12 * block_scale(K, i >= 3, i >= 3) ? 0.0 : K(i, i)));
    cells.push_back(num(r.point.q_max()));
    cells.push_back(std::to_string(r.point.loaded_balls()));
    for (std::size_t c = 0; c < cells.size(); ++c) o << pad(cells[c], width[c]);
    o << "\n";
  }
  const bool singular = std::any_of(t.rows.begin(), t.rows.end(),
                                    [](const auto& r) { return r.point.loaded_balls() < 3; });
  if (singular)
    o << "note: where fewer than 3 balls are loaded at the case's cage angle K there is singular "
         "(a "
         "ball stiffens the ring in two directions only; no ball: K = 0)\n";
  return o.str() + ball_pass_text(t);
}

std::string stiffness_ross_csv(const StiffnessTable& t) {
  for (const auto& k : t.keys)
    if (k.key != "operation.speed")
      throw InputError(
          "--format ross: ROSS's BearingElement interpolates its coefficients over "
          "the speed (its frequency column), so the points may vary operation.speed "
          "only; this call varies " +
          k.key + " (write one table per value with --set " + k.key + "=...)");
  std::vector<const StiffnessRow*> rows;
  for (const auto& r : t.rows) rows.push_back(&r);
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto* a, const auto* b) { return a->speed < b->speed; });
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i]->speed == rows[i - 1]->speed)
      throw InputError("--format ross: operation.speed = " + format_number(rows[i]->speed) +
                       " rad/s appears twice; ROSS needs each speed once (N = 1, or FROM != TO)");
  for (const StiffnessRow* r : rows)
    if (!r->point.rotor)
      throw InputError(
          "--format ross: ROSS's table carries K averaged over one ball pass, which --ball-pass 0 "
          "leaves out; give --ball-pass N (4 to " +
          std::to_string(kMaxBallPassSamples) + ") or leave it at its default, " +
          std::to_string(kBallPassSamples));
  std::ostringstream o;
  o << "frequency,kxx,kxy,kyx,kyy,cxx,cxy,cyx,cyy\n";
  for (const StiffnessRow* r : rows) {
    // The ball-pass means; C is 0 for dry contacts (no [lubricant]).
    const Matrix5& K = r->point.rotor->stiffness;
    const Matrix5& C = r->point.rotor->damping;
    o << stiffness_number(r->speed);
    for (const Matrix5* M : {&K, &C})
      o << "," << stiffness_number((*M)(0, 0)) << "," << stiffness_number((*M)(0, 1)) << ","
        << stiffness_number((*M)(1, 0)) << "," << stiffness_number((*M)(1, 1));
    o << "\n";
  }
  return o.str();
}

void write_stiffness(const std::string& dir, const StiffnessTable& t, bool ross) {
  namespace fs = std::filesystem;
  // Every text first: an error leaves no folder and no file.
  const std::string csv = stiffness_csv(t);
  const std::string json = stiffness_json(t).dump(2) + "\n";
  const std::string ross_csv = ross ? stiffness_ross_csv(t) : std::string();
  const bool ball_pass = t.ball_pass_samples > 0;
  const std::string ball_pass_table = ball_pass ? ball_pass_csv(t) : std::string();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
  std::vector<std::string> names = {"stiffness.csv", "stiffness.json"};
  std::vector<std::string> others;  // an earlier call's tables that this one does not write
  (ball_pass ? names : others).push_back("stiffness_ball_pass.csv");
  (ross ? names : others).push_back("stiffness_ross.csv");
  AtomicFileSet files(dir, names, others, "--out " + dir);
  files.write("stiffness.csv", csv);
  files.write("stiffness.json", json);
  if (ball_pass) files.write("stiffness_ball_pass.csv", ball_pass_table);
  if (ross) files.write("stiffness_ross.csv", ross_csv);
  files.commit();
}

}  // namespace bearing
