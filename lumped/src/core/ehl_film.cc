// The EHL film of one ball–race contact (ehl_film.h).

#include "bearing/ehl_film.h"

#include <cmath>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/material.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void require_load(double load) {
  if (!(std::isfinite(load) && load > 0))
    throw InputError("EHL film: normal load Q = " + format_number(load) +
                     " N must be finite and > 0");
}

// Hamrock & Dowson's ellipticity factors of h_c and h_min.
double central_k_factor(double k) {
  return 1.0 - 0.61 * std::exp(-0.73 * k);
}
double minimum_k_factor(double k) {
  return 1.0 - std::exp(-0.68 * k);
}

}  // namespace

double FilmContact::speed_parameter() const {
  return viscosity * entrainment_speed / (reduced_modulus * rx);
}

double FilmContact::material_parameter() const {
  return pressure_viscosity * reduced_modulus;
}

double FilmContact::load_parameter(double load) const {
  return load / (reduced_modulus * rx * rx);
}

double FilmContact::central_coefficient() const {
  // h_c = R_x 2.69 U^0.67 G^0.53 (Q/(E' R_x²))^−0.067 (1 − 0.61 e^{−0.73 k}) = C Q^−0.067.
  return rx * 2.69 * std::pow(speed_parameter(), 0.67) * std::pow(material_parameter(), 0.53) *
         std::pow(reduced_modulus * rx * rx, kCentralFilmLoadExponent) *
         central_k_factor(ellipticity);
}

double FilmContact::central_thickness(double load) const {
  require_load(load);
  return rx * 2.69 * std::pow(speed_parameter(), 0.67) * std::pow(material_parameter(), 0.53) *
         std::pow(load_parameter(load), -kCentralFilmLoadExponent) * central_k_factor(ellipticity);
}

double FilmContact::minimum_thickness(double load) const {
  require_load(load);
  return rx * 3.63 * std::pow(speed_parameter(), 0.68) * std::pow(material_parameter(), 0.49) *
         std::pow(load_parameter(load), -0.073) * minimum_k_factor(ellipticity);
}

double FilmContact::lambda(double load) const {
  return minimum_thickness(load) / roughness;
}

double FilmContact::stiffness(double load) const {
  return load / (kCentralFilmLoadExponent * central_thickness(load));
}

double FilmContact::damping(double load) const {
  // No entrainment, no film: the contact is dry, and has no squeeze film to damp it.
  if (entrainment_speed == 0.0) return 0.0;
  return 12.0 * pi * viscosity * std::pow(rx * ry, 1.5) / ((rx + ry) * central_thickness(load));
}

bool FilmContact::within_fit() const {
  return ellipticity >= 1.0 && ellipticity <= 8.0;
}

double entrainment_speed(const Bearing& b, Race race, double inner_speed, double cage_speed,
                         double contact_angle) {
  const double dcos = b.ball_diameter * std::cos(contact_angle);
  if (race == Race::inner)
    return std::fabs(inner_speed - cage_speed) * 0.5 * (b.pitch_diameter - dcos);
  return std::fabs(cage_speed) * 0.5 * (b.pitch_diameter + dcos);
}

FilmContact film_contact(const Bearing& b, Race race, const RaceContact& contact,
                         const Lubricant& lubricant, double speed) {
  lubricant.validate();
  if (!(std::isfinite(speed) && speed >= 0))
    throw InputError("EHL film: entrainment speed u = " + format_number(speed) +
                     " m/s must be finite and >= 0");
  const Curvatures c = race_curvatures(b, race);
  FilmContact f;
  f.rx = 1.0 / (c.ball_1 + c.race_1);
  f.ry = 1.0 / (c.ball_2 + c.race_2);
  f.ellipticity = contact.shape.ellipticity;
  f.reduced_modulus = 2.0 / contact.compliance;
  f.entrainment_speed = speed;
  f.viscosity = lubricant.operating_viscosity();
  f.pressure_viscosity = lubricant.pressure_viscosity;
  f.roughness = lubricant.roughness;
  return f;
}

BallFilms ball_films(const Bearing& b, const ContactConstants& c, const Lubricant& lubricant,
                     double inner_speed, double cage_speed) {
  const double a = b.contact_angle;
  return {film_contact(b, Race::inner, c.inner, lubricant,
                       entrainment_speed(b, Race::inner, inner_speed, cage_speed, a)),
          film_contact(b, Race::outer, c.outer, lubricant,
                       entrainment_speed(b, Race::outer, inner_speed, cage_speed, a))};
}

}  // namespace bearing
