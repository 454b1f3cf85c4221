#pragma once
// The FE-calibrated contact law (`[model] contact = "calibrated"`, docs/case-files.md): the
// load–deflection law Q = K δ^n of each race, fitted by `bearing-fem calibrate` to a finite-element
// force–approach curve (docs/model.md §9), written by it as calibration.json (calibration_text) and
// read back from it (read_calibration): the file's keys live in calibration.cc alone.
//
// The file (SI units; numbers in their shortest exact form):
//   {"format": "bearing-fem calibration 1",
//    "bearing": {"designation", "ball_diameter", "pitch_diameter", "inner_conformity",
//                "outer_conformity", "contact_angle",
//                "material": {"ball": {"young", "poisson"}, "rings": {"young", "poisson"}}},
//    "inner": {"K", "exponent", "fit_residual", "K_three_halves", "hertz_K", "details"},
//    "outer": {...}, "load_range": [Q_min, Q_max], "geometry": "hertz" | "groove",
//    "method": "...", "mesh": "...", "case": "...", "date": "...", "units": {...}}
// K_three_halves, hertz_K, details and case are a record for people and are not read back.
// The constants belong to one contact geometry: a case whose ball diameter, pitch diameter,
// conformities, contact angle or elastic constants differ from the file's is rejected. Clearance,
// ball count, density and the rotor do not enter the contact constants and are not compared.
//
// Only K and n come from the file. The curvatures, F(ρ), the ellipse shape and the semi-axes stay
// those of the exact Hertz solution (the FE constants correct the stiffness, not the geometry).
//
// The ball between both races carries the same load Q through both contacts and the approaches
// add, δ(Q) = (Q/K_i)^{1/n_i} + (Q/K_o)^{1/n_o}. For n_i = n_o = n this is again a power law,
// K = (K_i^{−1/n} + K_o^{−1/n})^{−n}. For n_i ≠ n_o it is not: the models need one law Q = K δ^n
// per ball, so K and n are fitted by least squares of ln Q on ln δ over 50 log-spaced loads of the
// file's load_range (the loads the FE fit itself covered), and the fit's relative RMS residual is
// recorded and shown.

#include <string>
#include <string_view>

#include "bearing/bearing.h"
#include "bearing/contact.h"

namespace bearing {

/// The `format` string of the calibration files this version reads.
inline constexpr std::string_view kCalibrationFormat = "bearing-fem calibration 1";

/// One race's fitted law Q = K δ^n.
struct RaceLaw {
  double K = 0;              ///< load–deflection constant [N/m^n]
  double exponent = 1.5;     ///< n [-], in [1, 3]
  double fit_residual = -1;  ///< residual of the FE fit as bearing-fem reports it (−1: not given)
};

/// A validated calibration file, SI units.
struct ContactCalibration {
  std::string path;      ///< absolute path of the file read
  Bearing bearing;       ///< designation, D, d_m, f_i, f_o, α and E, ν of balls and rings the
                         ///< constants were computed for (the other fields are unset)
  RaceLaw inner;         ///< ball on the inner race
  RaceLaw outer;         ///< ball on the outer race
  double load_min = 0;   ///< load_range[0]: smallest ball load the FE fit covered [N] (0: none)
  double load_max = 0;   ///< load_range[1]: largest [N] (0: none)
  std::string geometry;  ///< "hertz" (Hertz-reduced bodies) or "groove" (real groove); "" if absent
  std::string method;    ///< free text: the FE method ("" if absent)
  std::string mesh;      ///< free text: the mesh ("" if absent)
  std::string date;      ///< when it was computed, ISO 8601 ("" if absent)

  bool has_load_range() const { return load_max > 0; }
};

/// What the file records of one race's FE fit besides its law, for people: not read back.
struct RaceFitRecord {
  double K_three_halves = 0;  ///< the FE constant refitted with n = 1.5 [N/m^1.5]
  double hertz_K = 0;         ///< exact Hertz constant of the same contact [N/m^1.5]
  std::string details;        ///< folder of the race's contact.json, beside the file
};

/// A calibration file's whole content, as `bearing-fem calibrate` writes it.
struct CalibrationDocument {
  ContactCalibration calibration;  ///< what parse_calibration reads back (`path` is not written;
                                   ///< of `bearing` the fields it compares and the designation)
  RaceFitRecord inner_fit;         ///< inner.{K_three_halves, hertz_K, details}
  RaceFitRecord outer_fit;         ///< outer.{...}
  std::string case_source;         ///< `case`: the case the bearing came from (Case::source)
};

/// The file's text: JSON indented by 2, keys sorted, numbers in their shortest exact form, a
/// final newline. What parse_calibration gives for an absent key is written as absent: a race's
/// fit_residual of −1 (not given), a load range of [0, 0] (none) and an empty geometry.
std::string calibration_text(const CalibrationDocument& doc);

/// Parses and validates calibration JSON. `shown` names the input in messages, e.g.
/// `model.calibration = "cal.json"`; `path` is stored as is. Throws InputError ("<shown>: <key> =
/// <value>: <what is allowed>") for invalid JSON, a wrong `format`, a missing, non-numeric,
/// non-positive or non-finite K, an exponent outside [1, 3], a missing or invalid bearing field,
/// a bad load_range (needed when the exponents differ), geometry or units.
ContactCalibration parse_calibration(std::string_view json_text, const std::string& path,
                                     const std::string& shown);

/// Reads `path` and parses it as parse_calibration does (the stored path is made absolute).
/// Throws InputError naming `shown` and the path if the file cannot be read.
ContactCalibration read_calibration(const std::string& path, const std::string& shown);

/// Throws InputError if `cal` was computed for another contact geometry than `b`: the first of
/// ball_diameter, pitch_diameter, inner_conformity, outer_conformity (relative tolerance 1e-9),
/// contact_angle (absolute 1e-12 rad), material.{ball,rings}.{young,poisson} (relative 1e-9) that
/// differs is named with both values and their units.
void check_calibration_bearing(const ContactCalibration& cal, const Bearing& b,
                               const std::string& shown);

/// The law Q = K δ^n of a ball between both races.
struct SeriesLaw {
  double K = 0;           ///< [N/m^n]
  double exponent = 1.5;  ///< n [-]
  double residual = 0;    ///< relative RMS residual of the load, (K δ_k^n − Q_k)/Q_k (0: exact)
};

/// The series law of a ball between two races: the closed form for equal exponents, else
/// fit_series_law over [load_min, load_max] (then 0 < load_min < load_max is required).
SeriesLaw series_law(const RaceLaw& inner, const RaceLaw& outer, double load_min, double load_max);

/// Least-squares fit of ln Q = ln K + n ln δ to δ(Q) = (Q/K_i)^{1/n_i} + (Q/K_o)^{1/n_o} at
/// `points` ≥ 2 loads spaced logarithmically from load_min to load_max [N] (both included). For
/// equal exponents it reproduces the closed form to rounding.
SeriesLaw fit_series_law(const RaceLaw& inner, const RaceLaw& outer, double load_min,
                         double load_max, int points = 50);

/// Contact constants of `b` with the calibrated law: per race the file's K and n with the
/// curvatures, F(ρ) and shape of the exact Hertz solution; the ball by series_law.
ContactConstants calibrated_contact_constants(const Bearing& b, const ContactCalibration& cal);

}  // namespace bearing
