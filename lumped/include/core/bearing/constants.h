#pragma once
// Mathematical and physical constants, defined once for lumped/, fem/, tests/ and bench/.
//
// Each value is the double nearest to the exact constant, so an expression written with these
// names rounds exactly as it did with a literal or M_PI (2π is the exact double of π).

namespace bearing {

/// π [-].
inline constexpr double pi = 3.14159265358979323846264338327950288;

/// 2π [-] (one turn in rad).
inline constexpr double two_pi = 2 * pi;

/// π in long double, for tables built above double precision (models/phasor.h) [-].
inline constexpr long double pi_long = 3.14159265358979323846264338327950288L;

/// Standard gravity g_n [m/s²] (3rd CGPM, 1901).
inline constexpr double standard_gravity = 9.80665;

}  // namespace bearing
