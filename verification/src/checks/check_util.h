#pragma once
// Small helpers every check table uses: printf-style text for details and descriptions, and the
// least-squares slope that fitted orders and decay exponents are read from.

#include <cstdio>
#include <string>
#include <vector>

namespace bearing::verify {

/// printf into a std::string (any length). Every argument is passed as a double, so the
/// conversions are %f, %e, %g (a ball count prints with %.0f).
template <typename... Args>
std::string fmt(const char* format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, static_cast<double>(args)...);
  std::string s(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::snprintf(s.data(), s.size() + 1, format, static_cast<double>(args)...);
  return s;
}

/// Least-squares slope of y against x (pass logarithms for an order or an exponent).
inline double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace bearing::verify
