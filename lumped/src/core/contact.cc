// Hertz load–deflection constants of a ball on each race and of the ball between both races
// (docs/model.md §3).

#include "bearing/contact.h"

#include <cmath>
#include <sstream>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/material.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The contact formulas need a valid bearing; Bearing::validate holds the rules (one place).
void require_contact_geometry(const Bearing& b) {
  b.validate();
}

void require_load(double load, const char* what) {
  if (!(std::isfinite(load) && load >= 0))
    throw InputError(std::string(what) + ": normal load Q = " + format_number(load) +
                     " N must be finite and >= 0");
}

}  // namespace

const char* to_string(Race race) {
  return race == Race::inner ? "inner" : "outer";
}

Curvatures race_curvatures(const Bearing& b, Race race) {
  require_contact_geometry(b);
  const double D = b.ball_diameter;
  const double g = D * std::cos(b.contact_angle) / b.pitch_diameter;
  const double f = race == Race::inner ? b.inner_conformity : b.outer_conformity;
  Curvatures c;
  c.ball_1 = 2.0 / D;
  c.ball_2 = 2.0 / D;
  // Rolling direction: the inner raceway is convex, the outer concave (for α = 0 these are
  // 2/d_i and −2/d_o with d_i = d_m − D, d_o = d_m + D).
  c.race_1 = race == Race::inner ? (2.0 / D) * g / (1.0 - g) : -(2.0 / D) * g / (1.0 + g);
  c.race_2 = -1.0 / (f * D);  // the groove, concave on both races
  return c;
}

// From δ = δ* (Σρ/2) (3Qη / (2Σρ))^{2/3}:
//   δ^{3/2} = δ*^{3/2} (Σρ/2)^{3/2} · 3Qη / (2Σρ) = Q · 3η δ*^{3/2} Σρ^{1/2} / 2^{5/2},
// so K = Q / δ^{3/2} = 2^{5/2} / (3 η δ*^{3/2} Σρ^{1/2}), independent of Q.
// (For steel, η = 8.75e-12 1/Pa, this is Harris's 2.15e5 N/mm^1.5 · Σρ[1/mm]^{−1/2} δ*^{−3/2}.)
RaceContact race_contact(const Bearing& b, Race race, const HertzSolution& method) {
  const Curvatures c = race_curvatures(b, race);
  RaceContact rc;
  rc.sum_rho = c.sum();
  // F < 0 would mean the major axis lies along the rolling direction (a groove flatter than the
  // raceway); the shape depends on |F| only. In practice this catches rounding around F = 0.
  rc.f_rho = std::abs(c.difference());
  rc.compliance = contact_compliance(b.ball, b.rings);
  if (!(std::isfinite(rc.compliance) && rc.compliance > 0))
    throw InputError(
        std::string("material: contact compliance (1-nu_b^2)/E_b + (1-nu_r^2)/E_r = ") +
        format_number(rc.compliance) + " 1/Pa must be positive; check young and poisson");
  if (!(rc.sum_rho > 0))
    throw InputError(std::string(to_string(race)) + " race: curvature sum " +
                     format_number(rc.sum_rho) +
                     " 1/m is not positive; check the conformity and diameters");
  rc.shape = method.shape(rc.f_rho);
  rc.K = std::pow(2.0, 2.5) /
         (3.0 * rc.compliance * std::pow(rc.shape.delta_star, 1.5) * std::sqrt(rc.sum_rho));
  rc.exponent = 1.5;
  return rc;
}

double RaceContact::approach(double load) const {
  require_load(load, "RaceContact::approach");
  return std::pow(load / K, 1.0 / exponent);
}

namespace {
// (3Qη / (2Σρ))^{1/3} [m], the length scale of the contact ellipse.
double ellipse_scale(const RaceContact& rc, double load) {
  return std::cbrt(3.0 * load * rc.compliance / (2.0 * rc.sum_rho));
}
}  // namespace

double RaceContact::semi_major(double load) const {
  require_load(load, "RaceContact::semi_major");
  return shape.a_star * ellipse_scale(*this, load);
}

double RaceContact::semi_minor(double load) const {
  require_load(load, "RaceContact::semi_minor");
  return shape.b_star * ellipse_scale(*this, load);
}

double RaceContact::peak_pressure(double load) const {
  require_load(load, "RaceContact::peak_pressure");
  if (load == 0) return 0.0;  // no contact ellipse; avoid 0/0
  return 3.0 * load / (two_pi * semi_major(load) * semi_minor(load));
}

double series_stiffness(double k_inner, double k_outer) {
  if (!(std::isfinite(k_inner) && k_inner > 0 && std::isfinite(k_outer) && k_outer > 0))
    throw InputError("series_stiffness: K_i = " + format_number(k_inner) + ", K_o = " +
                     format_number(k_outer) + " N/m^1.5 must both be positive and finite");
  // The same Q passes through both contacts and the approaches add: (Q/K)^{2/3} = Σ (Q/K_r)^{2/3}.
  return std::pow(std::pow(k_inner, -2.0 / 3.0) + std::pow(k_outer, -2.0 / 3.0), -1.5);
}

double series_stiffness(double k_inner, double k_outer, double exponent) {
  if (exponent == 1.5) return series_stiffness(k_inner, k_outer);
  if (!(std::isfinite(k_inner) && k_inner > 0 && std::isfinite(k_outer) && k_outer > 0 &&
        std::isfinite(exponent) && exponent > 0))
    throw InputError(
        "series_stiffness: K_i = " + format_number(k_inner) + ", K_o = " + format_number(k_outer) +
        " N/m^n and n = " + format_number(exponent) + " must all be positive and finite");
  return std::pow(std::pow(k_inner, -1.0 / exponent) + std::pow(k_outer, -1.0 / exponent),
                  -exponent);
}

ContactLaw contact_law(HertzMethod method) {
  switch (method) {
    case HertzMethod::hamrock_brewe:
      return ContactLaw::hamrock_brewe;
    case HertzMethod::harris_table:
      return ContactLaw::harris_table;
    case HertzMethod::exact:
      break;
  }
  return ContactLaw::exact;
}

HertzMethod hertz_shape_method(ContactLaw law) {
  switch (law) {
    case ContactLaw::hamrock_brewe:
      return HertzMethod::hamrock_brewe;
    case ContactLaw::harris_table:
      return HertzMethod::harris_table;
    case ContactLaw::exact:
    case ContactLaw::calibrated:
      break;
  }
  return HertzMethod::exact;
}

ContactConstants contact_constants(const Bearing& b, const HertzSolution& method) {
  ContactConstants cc;
  cc.method = contact_law(method.method());
  cc.inner = race_contact(b, Race::inner, method);
  cc.outer = race_contact(b, Race::outer, method);
  cc.K = series_stiffness(cc.inner.K, cc.outer.K);
  cc.exponent = 1.5;
  return cc;
}

}  // namespace bearing
