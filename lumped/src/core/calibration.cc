// The FE-calibrated contact law: the text of calibration.json and reading it back (its keys are
// spelled here alone), checking it belongs to the case's bearing, and the law of a ball between
// two calibrated races (calibration.h).

#include "bearing/calibration.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/units.h"
#include "json_document.h"

namespace bearing {

namespace {

using json_document::article;
using json_document::json;
using json_document::Reader;
using json_document::shown_json;

// The `units` object: written as is, and a file declaring other units is refused.
constexpr std::pair<const char*, const char*> kUnits[] = {{"K", "N/m^exponent"},
                                                          {"lengths", "m"},
                                                          {"young", "Pa"},
                                                          {"contact_angle", "rad"},
                                                          {"load_range", "N"}};

// The contact geometry the constants belong to, as check_calibration_bearing compares it.
json bearing_json(const Bearing& b) {
  const auto material = [](const Material& m) {
    return json{{"young", m.young}, {"poisson", m.poisson}};
  };
  return {{"designation", b.designation},
          {"ball_diameter", b.ball_diameter},
          {"pitch_diameter", b.pitch_diameter},
          {"inner_conformity", b.inner_conformity},
          {"outer_conformity", b.outer_conformity},
          {"contact_angle", b.contact_angle},
          {"material", {{"ball", material(b.ball)}, {"rings", material(b.rings)}}}};
}

json race_json(const RaceLaw& law, const RaceFitRecord& fit) {
  json j = {{"K", law.K},
            {"exponent", law.exponent},
            {"K_three_halves", fit.K_three_halves},
            {"hertz_K", fit.hertz_K},
            {"details", fit.details}};
  if (law.fit_residual != -1) j["fit_residual"] = law.fit_residual;  // −1: not given
  return j;
}

// What a calibration file is, for messages.
const std::string kWhatFile = "a calibration file written by bearing-fem calibrate";

RaceLaw read_race(const Reader& top, const char* race) {
  const Reader r = top.object(race);
  RaceLaw law;
  law.exponent = r.number("exponent", "");
  if (!(law.exponent >= 1.0 && law.exponent <= 3.0))
    r.fail(r.name("exponent") + " = " + format_number(law.exponent) +
           ": the load-deflection exponent n must lie in [1, 3] (Hertz: 1.5)");
  const std::string unit = "N/m^" + format_number(law.exponent);
  law.K = r.number("K", unit);
  if (!(law.K > 0))
    r.fail(r.name("K") + " = " + format_number(law.K) + " " + unit +
           ": the load-deflection constant must be positive");
  if (r.get("fit_residual")) {
    law.fit_residual = r.number("fit_residual", "");
    if (!(law.fit_residual >= 0))
      r.fail(r.name("fit_residual") + " = " + format_number(law.fit_residual) + ": must be >= 0");
  }
  return law;
}

Material read_material(const Reader& materials, const char* which) {
  const Reader m = materials.object(which);
  Material out;
  out.young = m.number("young", "Pa");
  if (!(out.young > 0))
    m.fail(m.name("young") + " = " + format_number(out.young) + " Pa: must be positive");
  out.poisson = m.number("poisson", "");
  if (!(out.poisson > -1 && out.poisson < 0.5))
    m.fail(m.name("poisson") + " = " + format_number(out.poisson) + ": must lie in (-1, 0.5)");
  return out;
}

Bearing read_bearing(const Reader& top) {
  const Reader r = top.object("bearing");
  Bearing b;
  if (const json* d = r.get("designation"))
    b.designation = d->is_string() ? d->get<std::string>() : d->dump();
  const auto positive = [&](const char* key, const std::string& unit) {
    const double v = r.number(key, unit);
    if (!(v > 0))
      r.fail(r.name(key) + " = " + format_number(v) + (unit.empty() ? "" : " " + unit) +
             ": must be positive");
    return v;
  };
  b.ball_diameter = positive("ball_diameter", "m");
  b.pitch_diameter = positive("pitch_diameter", "m");
  b.inner_conformity = positive("inner_conformity", "");
  b.outer_conformity = positive("outer_conformity", "");
  b.contact_angle = r.number("contact_angle", "rad");
  if (!(b.contact_angle >= 0 && b.contact_angle < pi / 2))
    r.fail(r.name("contact_angle") + " = " + format_number(b.contact_angle) +
           " rad: must lie in [0, pi/2)");
  const Reader materials = r.object("material");
  b.ball = read_material(materials, "ball");
  b.rings = read_material(materials, "rings");
  return b;
}

// The units the file declares, if it does: this version reads SI files only.
void check_units(const Reader& top) {
  const json* u = top.get("units");
  if (!u) return;
  if (!u->is_object())
    top.fail("units = " + shown_json(*u) + ": expected an object, got " + article(*u));
  const Reader units = top.object("units");
  for (const auto& [key, unit] : kUnits) {
    const json* v = units.get(key);
    if (v && !(v->is_string() && v->get<std::string>() == unit))
      top.fail(std::string("units.") + key + " = " + shown_json(*v) + ": expected \"" + unit +
               "\" (calibration files are in SI units)");
  }
}

}  // namespace

std::string calibration_text(const CalibrationDocument& doc) {
  const ContactCalibration& cal = doc.calibration;
  json j = {{"format", std::string(kCalibrationFormat)},
            {"bearing", bearing_json(cal.bearing)},
            {"inner", race_json(cal.inner, doc.inner_fit)},
            {"outer", race_json(cal.outer, doc.outer_fit)},
            {"method", cal.method},
            {"mesh", cal.mesh},
            {"case", doc.case_source},
            {"date", cal.date},
            {"units", json::object()}};
  for (const auto& [key, unit] : kUnits) j["units"][key] = unit;
  // What parse_calibration reads for an absent key is written as one.
  if (cal.load_min != 0 || cal.load_max != 0) j["load_range"] = {cal.load_min, cal.load_max};
  if (!cal.geometry.empty()) j["geometry"] = cal.geometry;
  // Keys sorted (nlohmann's default object); numbers in their shortest exact form.
  return j.dump(2) + "\n";
}

ContactCalibration parse_calibration(std::string_view json_text, const std::string& path,
                                     const std::string& shown) {
  // A file is 4 levels deep.
  const json doc = json_document::parse(json_text, shown, kWhatFile, 4);
  const Reader top(doc, "", shown, kWhatFile);

  const json* format = top.get("format");
  if (!format)
    top.fail("format is missing: expected \"" + std::string(kCalibrationFormat) +
             "\" (a calibration file written by bearing-fem calibrate)");
  if (!(format->is_string() && format->get<std::string>() == kCalibrationFormat))
    top.fail("format = " + shown_json(*format) + ": expected \"" + std::string(kCalibrationFormat) +
             "\" (a calibration file written by bearing-fem calibrate)");
  check_units(top);

  ContactCalibration cal;
  cal.path = path;
  cal.bearing = read_bearing(top);
  cal.inner = read_race(top, "inner");
  cal.outer = read_race(top, "outer");

  if (const json* range = top.get("load_range")) {
    const std::string allowed =
        ": expected [Q_min, Q_max], the ball loads in N the fit covered, with 0 < Q_min < Q_max";
    if (!(range->is_array() && range->size() == 2 && (*range)[0].is_number() &&
          (*range)[1].is_number()))
      top.fail("load_range = " + shown_json(*range) + allowed);
    cal.load_min = (*range)[0].get<double>();
    cal.load_max = (*range)[1].get<double>();
    if (!(std::isfinite(cal.load_min) && std::isfinite(cal.load_max) && cal.load_min > 0 &&
          cal.load_min < cal.load_max))
      top.fail("load_range = " + shown_json(*range) + allowed);
  } else if (cal.inner.exponent != cal.outer.exponent) {
    top.fail("load_range is missing: the exponents differ (inner " +
             format_number(cal.inner.exponent) + ", outer " + format_number(cal.outer.exponent) +
             "), so the ball's law between both races is fitted over the calibrated loads; give "
             "load_range = [Q_min, Q_max] in N");
  }

  cal.geometry = top.text("geometry");
  if (top.get("geometry") && cal.geometry != "hertz" && cal.geometry != "groove")
    top.fail("geometry = \"" + cal.geometry + "\": allowed: hertz, groove");
  cal.method = top.text("method");
  cal.mesh = top.text("mesh");
  cal.date = top.text("date");
  return cal;
}

ContactCalibration read_calibration(const std::string& path, const std::string& shown) {
  std::string absolute;
  const std::string text = json_document::read_text(path, shown, absolute);
  return parse_calibration(text, absolute, shown);
}

void check_calibration_bearing(const ContactCalibration& cal, const Bearing& b,
                               const std::string& shown) {
  enum class Kind { length, ratio, angle, modulus };
  struct Field {
    const char* key;
    double file;
    double actual;
    Kind kind;
  };
  const Bearing& f = cal.bearing;
  const Field fields[] = {
      {"bearing.ball_diameter", f.ball_diameter, b.ball_diameter, Kind::length},
      {"bearing.pitch_diameter", f.pitch_diameter, b.pitch_diameter, Kind::length},
      {"bearing.inner_conformity", f.inner_conformity, b.inner_conformity, Kind::ratio},
      {"bearing.outer_conformity", f.outer_conformity, b.outer_conformity, Kind::ratio},
      {"bearing.contact_angle", f.contact_angle, b.contact_angle, Kind::angle},
      {"material.ball.young", f.ball.young, b.ball.young, Kind::modulus},
      {"material.ball.poisson", f.ball.poisson, b.ball.poisson, Kind::ratio},
      {"material.rings.young", f.rings.young, b.rings.young, Kind::modulus},
      {"material.rings.poisson", f.rings.poisson, b.rings.poisson, Kind::ratio},
  };
  const auto show = [](double v, Kind kind) {
    switch (kind) {
      case Kind::length:
        return format_quantity(v, "mm", Dimension::length);
      case Kind::angle:
        return format_quantity(v, "deg", Dimension::angle);
      case Kind::modulus:
        return format_quantity(v, "GPa", Dimension::pressure);
      case Kind::ratio:
        break;
    }
    return format_number(v);
  };
  for (const Field& x : fields) {
    const double diff = std::abs(x.file - x.actual);
    const bool same = x.kind == Kind::angle
                          ? diff <= 1e-12
                          : diff <= 1e-9 * std::max(std::abs(x.file), std::abs(x.actual));
    if (same) continue;
    throw InputError(shown + ": computed for " + x.key + " = " + show(x.file, x.kind) +
                     (f.designation.empty() ? "" : " (designation " + f.designation + ")") +
                     ", but the case has " + show(x.actual, x.kind) +
                     "; recompute it with bearing-fem calibrate for this case");
  }
}

SeriesLaw fit_series_law(const RaceLaw& inner, const RaceLaw& outer, double load_min,
                         double load_max, int points) {
  for (const RaceLaw* r : {&inner, &outer})
    if (!(std::isfinite(r->K) && r->K > 0 && std::isfinite(r->exponent) && r->exponent > 0))
      throw InputError("fit_series_law: K = " + format_number(r->K) + " N/m^n and n = " +
                       format_number(r->exponent) + " must be positive and finite");
  if (!(std::isfinite(load_min) && std::isfinite(load_max) && load_min > 0 && load_min < load_max))
    throw InputError("fit_series_law: load range [" + format_number(load_min) + ", " +
                     format_number(load_max) + "] N: needs 0 < Q_min < Q_max");
  if (points < 2)
    throw InputError("fit_series_law: " + std::to_string(points) + " loads: at least 2 needed");

  // x_k = ln δ(Q_k), y_k = ln Q_k; the line y = ln K + n x by least squares.
  std::vector<double> x(points), y(points);
  const double a = std::log(load_min), b = std::log(load_max);
  for (int k = 0; k < points; ++k) {
    const double Q = k == 0            ? load_min
                     : k + 1 == points ? load_max
                                       : std::exp(a + (b - a) * k / (points - 1.0));
    const double delta =
        std::pow(Q / inner.K, 1.0 / inner.exponent) + std::pow(Q / outer.K, 1.0 / outer.exponent);
    x[k] = std::log(delta);
    y[k] = std::log(Q);
  }
  double mx = 0, my = 0;
  for (int k = 0; k < points; ++k) mx += x[k] / points, my += y[k] / points;
  double sxx = 0, sxy = 0;
  for (int k = 0; k < points; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  SeriesLaw law;
  law.exponent = sxy / sxx;
  const double log_k = my - law.exponent * mx;
  law.K = std::exp(log_k);
  // Relative load residual (K δ_k^n − Q_k)/Q_k = exp(ln K + n x_k − y_k) − 1.
  double sum = 0;
  for (int k = 0; k < points; ++k) {
    const double r = std::expm1(log_k + law.exponent * x[k] - y[k]);
    sum += r * r;
  }
  law.residual = std::sqrt(sum / points);
  if (!(std::isfinite(law.K) && law.K > 0 && std::isfinite(law.exponent)))
    throw SolverError("fit_series_law: the fit of the ball's series law failed (K = " +
                      format_number(law.K) + ", n = " + format_number(law.exponent) + ")");
  return law;
}

SeriesLaw series_law(const RaceLaw& inner, const RaceLaw& outer, double load_min, double load_max) {
  if (inner.exponent == outer.exponent) {
    SeriesLaw law;
    law.exponent = inner.exponent;
    law.K = series_stiffness(inner.K, outer.K, inner.exponent);
    return law;
  }
  return fit_series_law(inner, outer, load_min, load_max);
}

ContactConstants calibrated_contact_constants(const Bearing& b, const ContactCalibration& cal) {
  const auto exact = make_exact_hertz();
  ContactConstants cc;
  cc.method = ContactLaw::calibrated;
  cc.inner = race_contact(b, Race::inner, *exact);
  cc.outer = race_contact(b, Race::outer, *exact);
  cc.inner.K = cal.inner.K;
  cc.inner.exponent = cal.inner.exponent;
  cc.outer.K = cal.outer.K;
  cc.outer.exponent = cal.outer.exponent;
  const SeriesLaw ball = series_law(cal.inner, cal.outer, cal.load_min, cal.load_max);
  cc.K = ball.K;
  cc.exponent = ball.exponent;
  cc.series_fit_residual = ball.residual;
  return cc;
}

}  // namespace bearing
