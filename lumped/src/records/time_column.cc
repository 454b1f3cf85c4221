#include "bearing/records/time_column.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "bearing/records/raw_channel.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The column's precision: its finest written time. (A writer that drops trailing zeros, or
// writes the shortest text that reads back, writes round times such as "0" or "0.5" with few
// digits although they are exact; a fixed-format writer gives every time the same digits.)
double finest(const std::vector<double>& quantum) {
  return *std::min_element(quantum.begin(), quantum.end());
}

}  // namespace

bool is_time_column_name(std::string_view name) {
  std::string lower;
  for (const char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "t" || lower == "time";
}

TimeColumnRate time_column_rate(const std::vector<double>& t, const std::vector<double>& quantum,
                                const std::string& file, std::string_view channel,
                                std::string_view column) {
  const std::string col = "time column " + std::string(column);
  const std::size_t n = t.size();
  if (n < 2)
    throw record_error(file, channel,
                       col + ": a rate needs at least 2 times, it has " + std::to_string(n));
  for (const double v : t)
    if (!std::isfinite(v)) throw record_error(file, channel, col + ": a time is not finite");
  const double span = t[n - 1] - t[0];
  if (!(span > 0))
    throw record_error(file, channel,
                       col + ": the times must increase (first " + format_number(t[0]) +
                           " s, last " + format_number(t[n - 1]) + " s)");

  // Least-squares line through (i, t[i]), about the centres so that the sums stay small.
  const double mi = 0.5 * static_cast<double>(n - 1);
  double mt = 0;
  for (const double v : t) mt += v;
  mt /= static_cast<double>(n);
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) - mi;
    sxy += x * (t[i] - mt);
    sxx += x * x;
  }
  const double dt = sxy / sxx;
  if (!(dt > 0 && std::isfinite(dt)))
    throw record_error(file, channel, col + ": the times must increase");

  const double q = finest(quantum);
  const double eps = std::numeric_limits<double>::epsilon();
  // The sample furthest off the grid, relative to what it is allowed, names the problem.
  std::size_t worst = 0;
  double worst_ratio = 0, worst_expected = 0, worst_allowed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double expected = mt + (static_cast<double>(i) - mi) * dt;
    const double allowed =
        0.5 * (quantum[i] + q) + 0.01 * dt + 4 * eps * std::max(std::abs(t[i]), std::abs(expected));
    const double ratio = std::abs(t[i] - expected) / allowed;
    if (ratio > worst_ratio) {
      worst = i;
      worst_ratio = ratio;
      worst_expected = expected;
      worst_allowed = allowed;
    }
  }
  if (worst_ratio > 1)
    throw record_error(file, channel,
                       col + ": not uniform at sample " + std::to_string(worst) +
                           " (from 0): " + format_number(t[worst]) + " s, where the mean step " +
                           format_number(dt) + " s puts " + format_number(worst_expected) +
                           " s (± " + format_number(worst_allowed) + " s)");
  return {1.0 / dt, (q + 0.01 * dt) / span + 8 * eps};
}

}  // namespace bearing
