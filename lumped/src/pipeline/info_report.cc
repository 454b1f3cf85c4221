#include "bearing/info_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bearing/ball_pass_output.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/json_helpers.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_registry.h"
#include "bearing/models/three_dof.h"
#include "bearing/presets.h"
#include "bearing/simulation.h"
#include "bearing/stiffness_output.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The case's constant loads on a perfect bearing: the static state the peak pressure is read at.
ModelInputs static_model_inputs(const Case& c) {
  ModelInputs in = model_inputs(c);
  in.inner_waviness = {};
  in.outer_waviness = {};
  in.ball_size_errors.clear();
  in.defects.clear();
  return in;
}

// The largest ball load at the kind's static state (its initial displacement) [N].
double model_static_peak_load(ModelKind kind, const ModelInputs& in) {
  const ModelDescriptor& d = model_descriptor(kind);
  if (!d.dynamic) throw std::logic_error("info: an axial load on a kind without a model");
  const std::unique_ptr<BearingModel> model = d.dynamic(in);
  const std::vector<double> q = model->initial_displacement();
  std::vector<double> loads(static_cast<std::size_t>(in.bearing.balls));
  model->ball_loads(0.0, q.data(), loads.data());
  return *std::max_element(loads.begin(), loads.end());
}

}  // namespace

InfoReport compute_info(const Case& c, InfoParts parts) {
  InfoReport r;
  r.input = c;
  r.contact = contact_constants(c);
  r.frequencies = bearing_frequencies(c.bearing, c.operation.speed);
  StaticLoadOptions o;
  o.exponent = r.contact.exponent;
  r.static_load =
      solve_static_load(c.bearing.balls, r.contact.K, c.bearing.ball_gap(), c.operation.load, o);
  r.peak_load = r.static_load.q_max;
  if (model_descriptor(c.model.kind).axial_load && c.operation.axial_load != 0) {
    const ModelInputs in = static_model_inputs(c);
    const AxialPreload a = solve_axial_preload(in);
    r.axial = AxialStaticInfo{a.contact_angle, a.ball_load, a.z};
    r.peak_load = model_static_peak_load(c.model.kind, in);
  }
  r.inner_peak_pressure = r.contact.inner.peak_pressure(r.peak_load);
  r.outer_peak_pressure = r.contact.outer.peak_pressure(r.peak_load);
  const Bearing& b = c.bearing;
  const double wc = cage_speed(b, c.operation.speed);
  for (const LocalDefect& d : c.excitation.defects) {
    DefectInfo info;
    if (d.location != DefectLocation::outer)
      info.inner_drop = DefectPath(b, d, Race::inner).max_drop();
    if (d.location != DefectLocation::inner)
      info.outer_drop = DefectPath(b, d, Race::outer).max_drop();
    info.crossing = defect_transit_time(d, b, c.operation.speed, wc, b.contact_angle);
    info.max_step = info.crossing / kStepsPerDefectCrossing;
    r.defects.push_back(info);
  }
  if (c.housing.enabled)
    r.housing_modes = housing_modes(*make_dynamic_model(c.model.kind, static_model_inputs(c)),
                                    c.housing.support_dofs());
  if (parts == InfoParts::without_stiffness) return r;
  // A section of the report, not its purpose: a case the 5-DOF solution cannot take still gets
  // the rest, with the reason shown (`bearing-sim stiffness` fails on it instead); an equilibrium
  // not reached at another cage angle leaves the matrix, without its ball pass.
  try {
    try {
      r.stiffness = stiffness_point(c, kInfoBallPassSamples);
    } catch (const SolverError& e) {
      r.stiffness = stiffness_point(c, 0);
      r.ball_pass_error = e.what();
    }
  } catch (const InputError& e) {
    r.stiffness_error = e.what();
  } catch (const SolverError& e) {
    r.stiffness_error = e.what();
  }
  if (c.lubricant.enabled)
    r.film = r.stiffness ? film_info(c, r.contact, r.stiffness->q_max(), r.stiffness->outer_q_max())
                         : film_info(c, r.contact, r.peak_load, r.peak_load);
  return r;
}

namespace {

nlohmann::json stiffness_info_json(const InfoReport& r) {
  using nlohmann::json;
  if (!r.stiffness) return {{"error", r.stiffness_error}};
  const StiffnessPoint& p = *r.stiffness;
  const auto vec = [](const Vector5& v) { return std::vector<double>(v.data(), v.data() + 5); };
  json matrix = json::array(), units = json::array();
  for (int i = 0; i < 5; ++i) {
    json row = json::array(), unit = json::array();
    for (int j = 0; j < 5; ++j) {
      row.push_back(p.solution.at.stiffness(i, j));
      unit.push_back(stiffness_unit(i, j));
    }
    matrix.push_back(row);
    units.push_back(unit);
  }
  json j = {{"dofs", kStiffnessDofs},
            {"load", vec(p.load)},
            {"displacement", vec(p.solution.displacement)},
            {"matrix", matrix},
            {"matrix_units", units},
            {"q_max", p.q_max()},
            {"loaded_balls", p.loaded_balls()},
            {"ball_loads", p.solution.at.ball_loads},
            {"contact_angles", p.solution.at.contact_angles}};
  if (p.ball_pass)
    j["ball_pass"] = ball_pass_json(p);
  else
    j["ball_pass"] = {{"error", r.ball_pass_error}};
  if (r.input.lubricant.enabled) {
    json damping = json::array(), damping_units = json::array();
    for (int i = 0; i < 5; ++i) {
      json row = json::array(), unit = json::array();
      for (int k = 0; k < 5; ++k) {
        row.push_back(p.solution.at.damping(i, k));
        unit.push_back(damping_unit(i, k));
      }
      damping.push_back(row);
      damping_units.push_back(unit);
    }
    j["damping"] = damping;
    j["damping_units"] = damping_units;
    j["inner_films"] = p.solution.at.inner_films;  // each ball's central film h_c [m]
    j["outer_films"] = p.solution.at.outer_films;
  }
  return j;
}

}  // namespace

nlohmann::json info_json(const InfoReport& r) {
  using nlohmann::json;
  const auto race = [](const RaceContact& rc) {
    return json{{"sum_rho", rc.sum_rho},
                {"f_rho", rc.f_rho},
                {"ellipticity", rc.shape.ellipticity},
                {"delta_star", rc.shape.delta_star},
                {"K", rc.K},
                {"exponent", rc.exponent}};
  };
  const Bearing& b = r.input.bearing;
  json j;
  j["case"] = {{"source", r.input.source},
               {"bearing", b.designation},
               {"speed", r.input.operation.speed},
               {"load", {r.input.operation.load.x(), r.input.operation.load.y()}}};
  j["kinematics"] = {{"shaft", r.frequencies.shaft},
                     {"ftf", r.frequencies.ftf},
                     {"bpfo", r.frequencies.bpfo},
                     {"bpfi", r.frequencies.bpfi},
                     {"bsf", r.frequencies.bsf}};
  j["contact"] = {{"method", name_of(kContactLaws, r.contact.method)},
                  {"inner", race(r.contact.inner)},
                  {"outer", race(r.contact.outer)},
                  {"K", r.contact.K},
                  {"exponent", r.contact.exponent}};
  const auto& cal = r.input.model.calibration;
  if (cal) j["contact"]["calibration"] = calibration_json(*cal, r.contact);
  const auto& s = r.static_load;
  j["static"] = {
      {"deflection", {s.deflection.x(), s.deflection.y()}},
      {"ball_angles", s.ball_angles},
      {"ball_loads", s.ball_loads},
      {"q_max", s.q_max},
      {"peak_load", r.peak_load},
      {"peak_pressure", {{"inner", r.inner_peak_pressure}, {"outer", r.outer_peak_pressure}}},
      {"pressure_limit", kElasticPressureLimit},
      {"elastic", elastic_limit_warning(r).empty()}};
  if (r.axial)
    j["static"]["axial"] = {{"contact_angle", r.axial->contact_angle},
                            {"ball_load", r.axial->ball_load},
                            {"z", r.axial->z}};
  for (std::size_t i = 0; i < r.defects.size(); ++i) {
    const LocalDefect& d = r.input.excitation.defects[i];
    const DefectInfo& info = r.defects[i];
    const auto finite_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    j["defects"].push_back({{"location", name_of(kDefectLocations, d.location)},
                            {"width", d.width},
                            {"depth", d.depth},
                            {"inner_drop", info.inner_drop},
                            {"outer_drop", info.outer_drop},
                            {"crossing", finite_or_null(info.crossing)},
                            {"max_step", finite_or_null(info.max_step)}});
  }
  if (r.input.housing.enabled) {
    const Housing& h = r.input.housing;
    json modes = json::array();
    for (const HousingMode& m : r.housing_modes)
      modes.push_back({{"frequency", m.frequency}, {"housing_share", m.housing_share}});
    j["housing"] = housing_json(h);
    j["housing"]["modes"] = modes;
  }
  if (r.input.slip.enabled()) j["slip"] = slip_json(r.input.slip, r.frequencies.bpfo);
  // K is in N/m^n with the exponent n beside it (1.5 for the Hertz methods).
  const std::string k_unit = cal ? "N/m^exponent" : "N/m^1.5";
  j["units"] = {{"case.speed", "rad/s"},
                {"case.load", "N"},
                {"kinematics", "Hz"},
                {"contact.*.sum_rho", "1/m"},
                {"contact.*.K", k_unit},
                {"contact.K", k_unit},
                {"contact.*.exponent", "1"},
                {"contact.exponent", "1"},
                {"static.deflection", "m"},
                {"static.ball_angles", "rad"},
                {"static.ball_loads", "N"},
                {"static.q_max", "N"},
                {"static.peak_load", "N"},
                {"static.peak_pressure", "Pa"},
                {"static.pressure_limit", "Pa"},
                {"static.axial.contact_angle", "rad"},
                {"static.axial.ball_load", "N"},
                {"static.axial.z", "m"}};
  if (!r.defects.empty()) {
    for (const char* k :
         {"defects.width", "defects.depth", "defects.inner_drop", "defects.outer_drop"})
      j["units"][k] = "m";
    j["units"]["defects.crossing"] = "s";
    j["units"]["defects.max_step"] = "s";
  }
  if (r.input.housing.enabled) {
    add_housing_units(r.input.housing, j["units"]);
    j["units"]["housing.modes.frequency"] = "Hz";
    j["units"]["housing.modes.housing_share"] = "1";
  }
  if (r.input.slip.enabled()) add_slip_units(j["units"]);
  j["stiffness"] = stiffness_info_json(r);
  if (r.film) {
    j["film"] = film_json(*r.film);
    add_film_units(j["units"]);
  }
  if (r.stiffness && r.input.lubricant.enabled)
    j["units"]["stiffness.damping"] = "stiffness.damping_units";
  if (r.stiffness) {
    j["units"]["stiffness.load"] = kStiffnessLoadUnits;
    j["units"]["stiffness.displacement"] = kStiffnessDofUnits;
    j["units"]["stiffness.matrix"] = "stiffness.matrix_units";
    j["units"]["stiffness.q_max"] = "N";
    j["units"]["stiffness.ball_loads"] = "N";
    j["units"]["stiffness.contact_angles"] = "rad";
    if (r.input.lubricant.enabled)
      j["units"]["stiffness.inner_films"] = j["units"]["stiffness.outer_films"] = "m";
    if (r.stiffness->ball_pass) {
      const json units = ball_pass_units_json("stiffness.matrix_units");
      for (const auto& [key, unit] : units.items()) j["units"]["stiffness." + key] = unit;
    }
  }
  if (cal) {
    j["units"]["contact.calibration.load_range"] = "N";
    j["units"]["contact.calibration.series_fit_residual"] = "1";
  }
  require_finite(j);
  return j;
}

namespace {

std::string num(double v, int sig = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", sig, v);
  return buf;
}

std::string fixed(double v, int decimals) {
  if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;  // no "-0.0000"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string pad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

std::string rpad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

// "Contact law: calibrated (...)" and what it means, for info_text.
std::string calibrated_law_text(const ContactCalibration& cal, const ContactConstants& cc) {
  std::ostringstream o;
  const auto law = [](double K, double n) {
    return "K = " + num(K) + " N/m^" + num(n) + ", n = " + num(n);
  };
  o << "Contact law: calibrated (FE";
  if (!cal.geometry.empty()) o << ", " << cal.geometry << " geometry";
  o << ", file " << cal.path;
  if (!cal.date.empty()) o << ", " << cal.date;
  o << "): inner " << law(cc.inner.K, cc.inner.exponent) << "; outer "
    << law(cc.outer.K, cc.outer.exponent) << "; ball between both races " << law(cc.K, cc.exponent)
    << "\n";
  if (!cal.method.empty()) o << "  FE method: " << cal.method << "\n";
  if (!cal.mesh.empty()) o << "  FE mesh: " << cal.mesh << "\n";
  if (cal.inner.fit_residual >= 0 || cal.outer.fit_residual >= 0) {
    const auto res = [](double v) { return v >= 0 ? num(v, 3) : std::string("not given"); };
    o << "  FE fit residual: inner " << res(cal.inner.fit_residual) << ", outer "
      << res(cal.outer.fit_residual) << "\n";
  }
  if (cal.has_load_range())
    o << "  FE load range: " << num(cal.load_min) << " N to " << num(cal.load_max) << " N\n";
  if (cal.inner.exponent == cal.outer.exponent)
    o << "  ball law: exact series of the two races (equal exponents)\n";
  else
    o << "  ball law: least-squares fit of the series law delta(Q) = (Q/K_i)^(1/n_i) + "
         "(Q/K_o)^(1/n_o) over 50 loads in the FE load range, relative RMS residual "
      << num(cc.series_fit_residual, 3) << "\n";
  o << "  K and n are the FE constants; curvatures, F(rho), ellipticity, delta* and the contact "
       "ellipse are the exact Hertz solution's\n";
  return o.str();
}

}  // namespace

namespace {

// The defects as the contacts see them, and the step they ask for.
// The housing and what it becomes with the bearing on it, for info_text; empty without one.
std::string housing_text(const InfoReport& r) {
  const Housing& h = r.input.housing;
  if (!h.enabled) return "";
  std::ostringstream o;
  if (h.modal()) {
    const StructureModes& m = *h.modes;
    o << "\nHousing (outer ring on the structure's modes, " << m.path << ")\n  " << m.count()
      << " modes, " << num(m.frequencies.front(), 5) << " to " << num(m.frequencies.back(), 5)
      << " Hz alone; damping ratio "
      << (h.damping_ratios.empty() ? num(h.damping_ratio) : std::string("one per mode"))
      << "; sensors:";
    for (const StructureSensor* s : h.written_sensors()) o << " " << s->name;
    o << "\n  with the bearing, linearised at the static state (undamped), the modes:\n";
  } else {
    o << "\nHousing (outer ring on its support)\n  m_h = " << num(h.mass)
      << " kg, f_h = " << num(h.frequency) << " Hz alone, damping ratio " << num(h.damping_ratio)
      << ": k_h = " << num(h.stiffness(), 4) << " N/m, c_h = " << num(h.damping(), 4) << " N s/m\n"
      << "  with the bearing, linearised at the static state (undamped), the modes:\n";
  }
  o << "  " << rpad("frequency [Hz]", 16) << rpad("housing share", 16) << "\n";
  for (const HousingMode& m : r.housing_modes)
    o << "  " << rpad(num(m.frequency, 5), 16) << rpad(fixed(100 * m.housing_share, 1) + " %", 16)
      << "\n";
  return o.str();
}

// The 5-DOF stiffness at the case's loads, for info_text.
std::string stiffness_info_text(const InfoReport& r) {
  std::ostringstream o;
  o << "\nStiffness at the operating point and the case's cage angle (5-DOF static solution: "
       "rigid rings, the balls' centrifugal load at the case's speed, "
    << (r.input.lubricant.enabled ? "the EHL films and their squeeze damping" : "no damping")
    << "; every load of the case, whatever model.kind; a rotor model takes K averaged over one "
       "ball pass: `bearing-sim stiffness --format ross`)\n";
  if (!r.stiffness) return o.str() + "  not available: " + r.stiffness_error + "\n";
  const StiffnessPoint& p = *r.stiffness;
  const Vector5& q = p.solution.displacement;
  o << "  load Fx = " << num(p.load(0)) << " N, Fy = " << num(p.load(1))
    << " N, Fz = " << num(p.load(2)) << " N, Mx = " << num(p.load(3))
    << " N*m, My = " << num(p.load(4)) << " N*m\n"
    << "  displacement x = " << fixed(q(0) * 1e6, 4) << " um, y = " << fixed(q(1) * 1e6, 4)
    << " um, z = " << fixed(q(2) * 1e6, 4) << " um, gx = " << fixed(q(3) * 1e6, 4)
    << " urad, gy = " << fixed(q(4) * 1e6, 4) << " urad; " << p.loaded_balls()
    << (p.loaded_balls() == 1 ? " ball" : " balls") << " loaded, the largest " << num(p.q_max())
    << " N\n"
    << stiffness_matrix_text(p.solution.at.stiffness);
  if (r.input.lubricant.enabled)
    o << "  (the EHL films in series with Hertz: [lubricant])\n"
      << damping_matrix_text(p.solution.at.damping);
  o << stiffness_note(p);
  if (p.ball_pass)
    o << ball_pass_diagonal_text(p);
  else
    o << "  over one ball pass: not available: " << r.ball_pass_error << "\n";
  return o.str();
}

std::string defects_text(const InfoReport& r) {
  if (r.defects.empty()) return "";
  std::ostringstream o;
  o << "\nLocal defects (drop: the largest extra clearance a contact gains over the defect)\n";
  for (std::size_t i = 0; i < r.defects.size(); ++i) {
    const LocalDefect& d = r.input.excitation.defects[i];
    const DefectInfo& info = r.defects[i];
    o << "  " << i << ": " << name_of(kDefectLocations, d.location);
    if (d.location == DefectLocation::ball) o << " (ball " << d.ball << ")";
    o << ", " << num(d.width * 1e3) << " mm wide, " << num(d.depth * 1e3) << " mm deep, "
      << name_of(kDefectProfiles, d.profile) << ": drop";
    if (d.location != DefectLocation::outer) o << " " << num(info.inner_drop * 1e6) << " um inner";
    if (d.location == DefectLocation::ball) o << ",";
    if (d.location != DefectLocation::inner) o << " " << num(info.outer_drop * 1e6) << " um outer";
    if (std::isfinite(info.crossing))
      o << "; crossed in " << num(info.crossing * 1e6)
        << " us: solver.dt <= " << num(info.max_step * 1e6) << " us";
    o << "\n";
  }
  return o.str();
}

}  // namespace

std::string info_text(const InfoReport& r) {
  const Case& c = r.input;
  const Bearing& b = c.bearing;
  std::ostringstream o;
  const double rpm = c.operation.speed * 60.0 / (2.0 * pi);
  o << "Case: " << c.source << "\n";
  o << "Bearing " << b.designation;
  if (!c.preset.empty()) o << " (preset: " << preset_source(c.preset) << ")";
  o << "\n  D = " << num(b.ball_diameter * 1e3) << " mm, d_m = " << num(b.pitch_diameter * 1e3)
    << " mm, Z = " << b.balls << ", f_i = " << num(b.inner_conformity, 4)
    << ", f_o = " << num(b.outer_conformity, 4) << ", P_d = " << num(b.clearance * 1e6)
    << " um (gap per ball " << num(b.ball_gap() * 1e6)
    << " um), alpha = " << num(b.contact_angle * 180.0 / pi) << " deg\n";
  o << "  balls: E = " << num(b.ball.young / 1e9) << " GPa, nu = " << num(b.ball.poisson)
    << "; rings: E = " << num(b.rings.young / 1e9) << " GPa, nu = " << num(b.rings.poisson) << "\n";
  o << "Operation: inner ring " << num(rpm)
    << " rpm, outer ring fixed; radial load Fx = " << num(c.operation.load.x())
    << " N, Fy = " << num(c.operation.load.y()) << " N (y up)\n\n";

  const auto& f = r.frequencies;
  o << "Kinematics (pure rolling)\n";
  o << "  shaft  " << rpad(fixed(f.shaft, 3), 10) << " Hz\n";
  o << "  FTF    " << rpad(fixed(f.ftf, 3), 10) << " Hz\n";
  o << "  BPFO   " << rpad(fixed(f.bpfo, 3), 10) << " Hz\n";
  o << "  BPFI   " << rpad(fixed(f.bpfi, 3), 10) << " Hz\n";
  o << "  BSF    " << rpad(fixed(f.bsf, 3), 10) << " Hz\n\n";

  const auto& ci = r.contact.inner;
  const auto& co = r.contact.outer;
  const auto& cal = c.model.calibration;
  if (cal)
    o << calibrated_law_text(*cal, r.contact);
  else
    o << "Hertz contact (method: " << name_of(kContactLaws, r.contact.method) << ")\n";
  o << "  " << pad("", 24) << rpad("inner", 14) << rpad("outer", 14) << "\n";
  const auto row = [&](const std::string& name, const std::string& unit, double a, double bb) {
    o << "  " << pad(name + " [" + unit + "]", 24) << rpad(num(a), 14) << rpad(num(bb), 14) << "\n";
  };
  row("sum rho", "1/m", ci.sum_rho, co.sum_rho);
  row("F(rho)", "-", ci.f_rho, co.f_rho);
  row("ellipticity a/b", "-", ci.shape.ellipticity, co.shape.ellipticity);
  row("delta*", "-", ci.shape.delta_star, co.shape.delta_star);
  if (cal) {
    row("K", "N/m^n", ci.K, co.K);
    row("exponent n", "-", ci.exponent, co.exponent);
    o << "  ball between both races: K = " << num(r.contact.K) << " N/m^" << num(r.contact.exponent)
      << ", n = " << num(r.contact.exponent) << "\n\n";
  } else {
    row("K", "N/m^1.5", ci.K, co.K);
    o << "  ball between both races: K = " << num(r.contact.K) << " N/m^1.5\n\n";
  }

  const auto& s = r.static_load;
  o << "Static load distribution\n";
  if (c.operation.load.norm() == 0.0) {
    o << "  no radial load: inner ring centred, no ball loaded\n";
  } else {
    // Fixed decimals: the solver's round-off (~1e-21 m) is not worth showing as "-1.3e-15 um".
    if (r.axial) o << "  under the radial load alone (the 2-DOF distribution):\n";
    o << "  inner-ring deflection x = " << fixed(s.deflection.x() * 1e6, 4)
      << " um, y = " << fixed(s.deflection.y() * 1e6, 4)
      << " um (|d| = " << fixed(s.deflection.norm() * 1e6, 4) << " um)\n";
    o << "  Q_max = " << num(s.q_max)
      << " N; Q_max Z / F_r = " << num(s.q_max * b.balls / c.operation.load.norm(), 4) << "\n";
  }
  // Loads the kind does not carry (run refuses them) are in the stiffness section alone.
  if (!r.axial && c.operation.axial_load != 0)
    o << "  operation.axial_load = " << num(c.operation.axial_load)
      << " N is not in this distribution nor in the peak pressure: model.kind = \""
      << name_of(kModelKinds, c.model.kind)
      << "\" does not carry it (run refuses it); the stiffness section carries every load\n";
  if (!c.operation.moment.isZero(0.0))
    o << "  operation.moment is carried by the stiffness section alone (run refuses it)\n";
  if (r.axial)
    o << "  axial load " << num(c.operation.axial_load) << " N alone: contact angle "
      << fixed(r.axial->contact_angle * 180.0 / pi, 3) << " deg, each ball "
      << num(r.axial->ball_load) << " N, ring at z = " << fixed(r.axial->z * 1e6, 4) << " um\n";
  if (r.peak_load > 0) {
    o << "  peak Hertz pressure at the most loaded ball (" << num(r.peak_load)
      << (r.axial ? " N, radial and axial loads together" : " N") << "): inner "
      << num(r.inner_peak_pressure * 1e-9, 4) << " GPa, outer "
      << num(r.outer_peak_pressure * 1e-9, 4) << " GPa (elastic limit "
      << num(kElasticPressureLimit * 1e-9, 2) << " GPa, ISO 76)\n";
    const std::string warning = elastic_limit_warning(r);
    if (!warning.empty()) o << "  WARNING: " << warning << "\n";
  }
  if (c.operation.load.norm() != 0.0) {
    o << "  " << rpad("ball", 6) << rpad("angle [deg]", 14) << rpad("approach [um]", 16)
      << rpad("load [N]", 14) << "\n";
    for (std::size_t j = 0; j < s.ball_loads.size(); ++j)
      o << "  " << rpad(std::to_string(j + 1), 6)
        << rpad(fixed(s.ball_angles[j] * 180.0 / pi, 1), 14)
        << rpad(fixed(s.ball_approach[j] * 1e6, 4), 16) << rpad(num(s.ball_loads[j]), 14) << "\n";
  }
  o << defects_text(r);
  o << housing_text(r);
  if (r.input.slip.enabled()) o << "\n" << slip_line(r.input.slip, r.frequencies.bpfo);
  if (r.film) o << film_text(*r.film, c.lubricant);
  o << stiffness_info_text(r);
  return o.str();
}

std::string elastic_limit_warning(const InfoReport& r) {
  const double p = std::max(r.inner_peak_pressure, r.outer_peak_pressure);
  if (!(p > kElasticPressureLimit)) return {};
  const auto gpa = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v * 1e-9);
    return std::string(text);
  };
  return "the most loaded ball's peak Hertz pressure, " + gpa(p) + " GPa (inner " +
         gpa(r.inner_peak_pressure) + ", outer " + gpa(r.outer_peak_pressure) +
         "), passes the elastic limit of " + gpa(kElasticPressureLimit) +
         " GPa (ISO 76): the contacts yield, and the model's elastic contact law does not hold "
         "there; reduce operation.load" +
         std::string(r.axial ? " or operation.axial_load" : "");
}

}  // namespace bearing
