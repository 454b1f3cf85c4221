#pragma once
// Private to fem/modes/ (deal.II): the seat's harmonic response by a direct solve
// (harmonic_response.cc), for `bearing-fem modes --frf`.

#include <vector>

#include "modes/elastic_modes.h"

namespace bearing::fem::modes {

class ElasticProblem;

/// The seat's rigid fit of u for (K − ω²M) u = F_d at each frequency [Hz], F_d a unit force
/// along x (d = 0) and y (d = 1) spread uniformly over the seat; with `fixed` also K u = F_d.
/// Collective.
HarmonicResponse harmonic_response(const ElasticProblem& e, const std::vector<double>& frequencies,
                                   bool fixed);

}  // namespace bearing::fem::modes
