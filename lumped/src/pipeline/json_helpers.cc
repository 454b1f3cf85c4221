#include "bearing/json_helpers.h"

#include <cmath>

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
