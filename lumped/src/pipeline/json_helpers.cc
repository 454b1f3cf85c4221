#include "bearing/json_helpers.h"

#include <cmath>
#include <cstdio>

#include "bearing/errors.h"

namespace bearing {

nlohmann::json calibration_json(const ContactCalibration& cal, const ContactConstants& cc) {
  using nlohmann::json;
  const auto residual = [](double v) { return v >= 0 ? json(v) : json(nullptr); };
  json j = {
      {"file", cal.path},
      {"designation", cal.bearing.designation},
      {"geometry", cal.geometry},
      {"method", cal.method},
      {"mesh", cal.mesh},
      {"date", cal.date},
      {"load_range", cal.has_load_range() ? json{cal.load_min, cal.load_max} : json(nullptr)},
      {"fit_residual",
       {{"inner", residual(cal.inner.fit_residual)}, {"outer", residual(cal.outer.fit_residual)}}},
      {"series_fit_residual", cc.series_fit_residual}};
  return j;
}

nlohmann::json housing_json(const Housing& h) {
  using nlohmann::json;
  if (!h.modal())
    return {{"mass", h.mass},
            {"frequency", h.frequency},
            {"damping_ratio", h.damping_ratio},
            {"stiffness", h.stiffness()},
            {"damping", h.damping()}};
  const StructureModes& m = *h.modes;
  json zeta = json::array(), sensors = json::array();
  for (int k = 0; k < m.count(); ++k) zeta.push_back(h.mode_damping_ratio(k));
  for (const StructureSensor* s : h.written_sensors())
    sensors.push_back({{"name", s->name}, {"point", s->point}});
  return {{"structure", m.path},
          {"frequencies", m.frequencies},
          {"damping_ratios", zeta},
          {"sensors", sensors}};
}

void add_housing_units(const Housing& h, nlohmann::json& units) {
  if (!h.modal()) {
    units["housing.mass"] = "kg";
    units["housing.frequency"] = "Hz";
    units["housing.damping_ratio"] = "1";
    units["housing.stiffness"] = "N/m";
    units["housing.damping"] = "N s/m";
    return;
  }
  units["housing.frequencies"] = "Hz";
  units["housing.damping_ratios"] = "1";
  units["housing.sensors.point"] = "m";
}

nlohmann::json slip_json(const RandomSlip& slip, double bpfo) {
  const bool given = slip.correlation_time > 0;
  return {{"rms", slip.rms},
          {"correlation_time", given ? slip.correlation_time : 1.0 / bpfo},
          {"correlation_time_source", given ? "given" : "one ball pass"},
          {"seed", slip.seed}};
}

void add_slip_units(nlohmann::json& units) {
  units["slip.rms"] = "1";
  units["slip.correlation_time"] = "s";
}

std::string slip_line(const RandomSlip& slip, double bpfo) {
  const bool given = slip.correlation_time > 0;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "Slip: the cage speed fluctuates by %.4g %% RMS, correlation time %.4g s%s, "
                "seed %d\n",
                100 * slip.rms, given ? slip.correlation_time : 1.0 / bpfo,
                given ? "" : " (one ball pass)", slip.seed);
  return buf;
}

void require_finite(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw SolverError("result " + path + " is not finite (" + std::to_string(j.get<double>()) +
                      "); nothing was written");
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it)
      require_finite(*it, path.empty() ? it.key() : path + "." + it.key());
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      require_finite(j[i], path + "[" + std::to_string(i) + "]");
}

}  // namespace bearing
