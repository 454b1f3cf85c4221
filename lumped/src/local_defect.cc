#include "bearing/local_defect.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void check(const char* key, double value) {
  if (!(std::isfinite(value) && value >= 0))
    throw InputError(std::string(key) + " = " + format_number(value) +
                     " m: must be finite and not negative");
}

void check_all(double ball_diameter, Race race, double race_radius, double width, double depth) {
  check("bearing.ball_diameter", ball_diameter);
  check("race radius", race_radius);
  check("defects.width", width);
  check("defects.depth", depth);
  if (race == Race::outer && !(race_radius > 0.5 * ball_diameter))
    throw InputError("race radius = " + format_number(race_radius) +
                     " m: an outer race must be larger than the ball (D/2 = " +
                     format_number(0.5 * ball_diameter) + " m)");
}

// How far the ball lies below the intact race when it pivots on an edge at angle phi (header).
double pivot_drop(double r, Race race, double rho, double phi, double depth) {
  const double a = rho * std::sin(phi);
  if (a >= r) return depth;  // the ball reaches the floor
  const double race_sag = rho * (1 - std::cos(phi));
  const double drop = (r - std::sqrt(r * r - a * a)) + (race == Race::inner ? race_sag : -race_sag);
  return std::min(std::max(drop, 0.0), depth);
}

}  // namespace

double defect_drop(double ball_diameter, Race race, double race_radius, double width, double depth,
                   double u) {
  check_all(ball_diameter, race, race_radius, width, depth);
  if (!(u > 0 && u < width)) return 0.0;
  const double r = 0.5 * ball_diameter;
  return std::min(pivot_drop(r, race, race_radius, u / race_radius, depth),
                  pivot_drop(r, race, race_radius, (width - u) / race_radius, depth));
}

double defect_max_drop(double ball_diameter, Race race, double race_radius, double width,
                       double depth) {
  if (width <= 0) {
    check_all(ball_diameter, race, race_radius, width, depth);
    return 0.0;
  }
  return defect_drop(ball_diameter, race, race_radius, width, depth, 0.5 * width);
}

}  // namespace bearing
