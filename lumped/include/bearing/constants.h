#pragma once
// Mathematical and physical constants used across the toolkit (one definition each).

namespace bearing {

inline constexpr double pi = 3.14159265358979323846;
inline constexpr double two_pi = 2.0 * pi;
/// Standard gravity g [m/s²].
inline constexpr double standard_gravity = 9.80665;

}  // namespace bearing
