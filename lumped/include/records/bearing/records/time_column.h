#pragma once
// A time column (a CSV's "t" or "time [s]", a column "t" of an HDF5 table) as the record's rate:
// the samples must lie on a uniform grid, to the precision the times were written with.

#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// The uniform rate a time column states, and how well it states it.
struct TimeColumnRate {
  double rate = 0;       ///< [Hz]: (n − 1) / (t_last − t_0)
  double tolerance = 0;  ///< relative: a rate within rate·(1 ± tolerance) agrees with the column
};

/// Whether `name` (a header cell's name, its unit already split off) names a time column:
/// "t" or "time", any case.
bool is_time_column_name(std::string_view name);

/// The rate of the times `t` [s]. `quantum[i]` is the place value of t[i]'s last written digit
/// (0.000083 → 1e-6; 0 for binary values), so t[i] is within quantum[i]/2 of the time it
/// stands for. The grid is the least-squares line t̄ + (i − ī)·dt through all times (a round
/// first time such as "0", whose written precision says little, does not anchor it), good to
/// Q/2, Q the column's precision: its finest quantum (a writer of shortest or %g text writes
/// exact round times with few digits, so the coarsest says little). Uniform means every t[i]
/// lies within 0.5·(quantum[i] + Q) + 0.01·dt (+ 4 ulp) of the grid: the times as written, plus a
/// hundredth of a step of jitter. A rate agrees with the column when its grid stays within
/// Q + 0.01·dt of the line over the span: `tolerance` = (Q + 0.01·dt) / span.
/// InputError (record_error: `file`, `channel`) naming the column `column` when there are fewer
/// than 2 times, a time is not finite, they do not increase, or they are not uniform (naming the
/// sample furthest off the grid for its allowance, from 0).
TimeColumnRate time_column_rate(const std::vector<double>& t, const std::vector<double>& quantum,
                                const std::string& file, std::string_view channel,
                                std::string_view column);

}  // namespace bearing
