// `info`'s EHL film section (film_report.h).

#include "bearing/film_report.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "bearing/ehl_film.h"
#include "bearing/kinematics.h"

namespace bearing {

namespace {

std::optional<FilmRaceInfo> race_info(const FilmContact& f, double load) {
  // No load or no entrainment: no film to report (the contact is dry, or open).
  if (!(load > 0) || !(f.entrainment_speed > 0)) return std::nullopt;
  FilmRaceInfo r;
  r.load = load;
  r.entrainment_speed = f.entrainment_speed;
  r.central_thickness = f.central_thickness(load);
  r.minimum_thickness = f.minimum_thickness(load);
  r.lambda = f.roughness > 0 ? f.lambda(load) : std::numeric_limits<double>::quiet_NaN();
  r.stiffness = f.stiffness(load);
  r.damping = f.damping(load);
  r.within_fit = f.within_fit();
  return r;
}

nlohmann::json race_json(const std::optional<FilmRaceInfo>& r, const std::string& note) {
  using nlohmann::json;
  if (!r) return {{"note", note}};
  return {{"load", r->load},
          {"entrainment_speed", r->entrainment_speed},
          {"central_thickness", r->central_thickness},
          {"minimum_thickness", r->minimum_thickness},
          {"lambda", std::isfinite(r->lambda) ? json(r->lambda) : json(nullptr)},
          {"stiffness", r->stiffness},
          {"damping", r->damping},
          {"ellipticity_within_fit", r->within_fit}};
}

std::string num(double v, int sig = 5) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", sig, v);
  return buf;
}

}  // namespace

FilmInfo film_info(const Case& c, const ContactConstants& contact, double inner_load,
                   double outer_load) {
  const Bearing& b = c.bearing;
  const double speed = c.operation.speed;
  const BallFilms films = ball_films(b, contact, c.lubricant, speed, cage_speed(b, speed));
  FilmInfo f;
  f.inner = race_info(films.inner, inner_load);
  f.outer = race_info(films.outer, outer_load);
  if (!f.inner || !f.outer)
    f.note = speed == 0 ? "no entrainment at rest (operation.speed = 0): the contacts are dry"
                        : "no loaded contact: no film to report";
  return f;
}

nlohmann::json film_json(const FilmInfo& f) {
  return {{"inner", race_json(f.inner, f.note)}, {"outer", race_json(f.outer, f.note)}};
}

void add_film_units(nlohmann::json& units) {
  units["film.load"] = "N";
  units["film.entrainment_speed"] = "m/s";
  units["film.central_thickness"] = "m";
  units["film.minimum_thickness"] = "m";
  units["film.lambda"] = "1";
  units["film.stiffness"] = "N/m";
  units["film.damping"] = "N*s/m";
}

std::string film_text(const FilmInfo& f, const Lubricant& lubricant) {
  std::ostringstream o;
  o << "\nEHL film at the most loaded ball (Hamrock-Dowson, fully flooded, isothermal; eta0 = "
    << num(lubricant.operating_viscosity())
    << " Pa*s, alpha = " << num(lubricant.pressure_viscosity)
    << " 1/Pa, sigma = " << num(lubricant.roughness * 1e6) << " um)\n";
  if (!f.inner && !f.outer) return o.str() + "  " + f.note + "\n";
  const auto cell = [](const std::optional<FilmRaceInfo>& r, auto get) {
    std::string s = r ? get(*r) : std::string("-");
    return s.size() >= 14 ? s : s + std::string(14 - s.size(), ' ');
  };
  const auto row = [&](const std::string& name, auto get) {
    std::string label = name.size() >= 28 ? name : name + std::string(28 - name.size(), ' ');
    std::string line = "  " + label + cell(f.inner, get) + cell(f.outer, get);
    line.erase(line.find_last_not_of(' ') + 1);  // no trailing blanks
    o << line << "\n";
  };
  o << "  " << std::string(28, ' ') << "inner         outer\n";
  row("load [N]", [](const FilmRaceInfo& r) { return num(r.load); });
  row("entrainment speed [m/s]", [](const FilmRaceInfo& r) { return num(r.entrainment_speed); });
  row("central film h_c [um]",
      [](const FilmRaceInfo& r) { return num(r.central_thickness * 1e6); });
  row("minimum film h_min [um]",
      [](const FilmRaceInfo& r) { return num(r.minimum_thickness * 1e6); });
  row("lambda h_min/sigma [-]", [](const FilmRaceInfo& r) {
    return std::isfinite(r.lambda) ? num(r.lambda, 4) : std::string("- (sigma = 0)");
  });
  row("film stiffness [N/m]", [](const FilmRaceInfo& r) { return num(r.stiffness); });
  row("squeeze damping [N*s/m]", [](const FilmRaceInfo& r) { return num(r.damping); });
  row("ellipticity k in H-D 1...8",
      [](const FilmRaceInfo& r) { return std::string(r.within_fit ? "yes" : "no (k factor ~1)"); });
  if (!f.note.empty()) o << "  " << f.note << "\n";
  return o.str();
}

}  // namespace bearing
