#pragma once
// `bearing-sim info`'s EHL film section (issue 43): each race's film (ehl_film.h) at the most
// loaded ball of the 5-DOF static solution, as JSON and text. Only with [lubricant].

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/contact.h"

namespace bearing {

/// One race's film at its most loaded contact.
struct FilmRaceInfo {
  double load = 0;               ///< Q of the most loaded contact [N]
  double entrainment_speed = 0;  ///< u [m/s]
  double central_thickness = 0;  ///< h_c [m]
  double minimum_thickness = 0;  ///< h_min [m]
  double lambda = 0;             ///< Λ = h_min / σ [-] (NaN for σ = 0: written as null)
  double stiffness = 0;          ///< k_f = Q / (0.067 h_c) [N/m]
  double damping = 0;            ///< the squeeze film's c [N s/m]
  bool within_fit = false;  ///< k inside Hamrock & Dowson's runs, 1 … 8 (FilmContact::within_fit)
};

/// Both races' films; a race without a loaded contact or without entrainment (at rest) has none,
/// with the reason in `note`.
struct FilmInfo {
  std::optional<FilmRaceInfo> inner, outer;
  std::string note;
};

/// The films of `c` (c.lubricant on) with the contact constants `contact`, at operation.speed and
/// the pure-rolling cage speed, the inner race's under `inner_load` and the outer's under
/// `outer_load` [N] (the 5-DOF solution's largest inner and outer contact loads). Throws
/// InputError for an invalid lubricant.
FilmInfo film_info(const Case& c, const ContactConstants& contact, double inner_load,
                   double outer_load);

/// {"inner": {load, entrainment_speed, central_thickness, minimum_thickness, lambda, stiffness,
/// damping, ellipticity_within_fit}, "outer": {…}} (a race without a film: {"note": …}).
nlohmann::json film_json(const FilmInfo& f);

/// Adds film.* units to info's `units` map.
void add_film_units(nlohmann::json& units);

/// The text section, its lines started by two spaces.
std::string film_text(const FilmInfo& f, const Lubricant& lubricant);

}  // namespace bearing
