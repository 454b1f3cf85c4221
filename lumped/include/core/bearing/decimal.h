#pragma once
// Fast decimal formatting of doubles for the large CSV files (response.csv, spectrum.csv).
//
// std::to_chars's shortest round-trip form costs ~45 ns per number here and, for simulated data,
// always needs 16–17 digits; a whole run writes ~240 000 numbers. write_decimal() prints a fixed
// number of significant digits in printf's %.<digits>g layout (fixed notation for exponents −5 to
// digits − 1, scientific otherwise, trailing zeros removed) at ~10 ns per number.
//
// Accuracy: the value is scaled by exactly representable powers of ten (one multiplication or
// division; two when |exponent| > 22 − digits) and rounded to an integer, an error of at most
// ε = 5e-16 relative before the rounding. So the printed digits are the correctly rounded ones
// unless the exact value lies within ε·10^digits units of the last digit from a rounding tie, and
// the printed number is always within 0.5 + ε·10^digits units of its last digit of the double:
// for the 12 digits the CSV files use, 0.5005 units (relative difference < 5.005e-12).
// Exponents beyond the fast range (about ±30) and non-finite values go through snprintf (exact).

#include <cstddef>

namespace bearing {

/// Most significant digits write_decimal() accepts (the rounded mantissa must be exact in a
/// double).
constexpr int kMaxDecimalDigits = 15;

/// Room write_decimal() needs at `out`: it stores digits 16 bytes at a time, so up to 40 bytes
/// are touched although at most 23 characters are the result.
constexpr std::size_t kDecimalBufferSize = 40;

/// Writes `value` with `digits` significant digits (1 … kMaxDecimalDigits) to `out`, which has room
/// for kDecimalBufferSize characters, and returns the end (no terminating NUL). Same layout as
/// printf("%.<digits>g"): "5e-05", "0.0001", "1.2", "-8.34570891956e-06", "inf", "nan".
char* write_decimal(char* out, double value, int digits = 12);

}  // namespace bearing
