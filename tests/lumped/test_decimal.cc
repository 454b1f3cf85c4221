// write_decimal(): printf's %.<digits>g layout, digits correctly rounded except within
// 5e-16·10^digits units of a last-digit tie (decimal.h), checked against glibc's exact printf.

#include "bearing/decimal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace {

std::string ours(double v, int digits = 12) {
  char buf[bearing::kDecimalBufferSize];
  return std::string(buf, bearing::write_decimal(buf, v, digits));
}

std::string printf_g(double v, int digits = 12) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

TEST(Decimal, LayoutOfRepresentativeValues) {
  EXPECT_EQ(ours(0.0), "0");
  EXPECT_EQ(ours(-0.0), "-0");
  EXPECT_EQ(ours(5e-05), "5e-05");
  EXPECT_EQ(ours(0.0001), "0.0001");
  EXPECT_EQ(ours(1.2), "1.2");
  EXPECT_EQ(ours(100.0), "100");
  EXPECT_EQ(ours(123456789012.0), "123456789012");
  EXPECT_EQ(ours(1234567890123.0), "1.23456789012e+12");
  EXPECT_EQ(ours(-8.345708919563202e-06), "-8.34570891956e-06");
  EXPECT_EQ(ours(9.9999999999995), "10");  // rounds up to the next power of ten
  EXPECT_EQ(ours(0.99999999999996), "1");
  EXPECT_EQ(ours(1e-300), "1e-300");  // outside the fast range: snprintf
  EXPECT_EQ(ours(std::numeric_limits<double>::denorm_min()), printf_g(4.9406564584124654e-324));
  EXPECT_EQ(ours(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(ours(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(ours(1.0 / 3.0, 1), "0.3");
  EXPECT_EQ(ours(2.0 / 3.0, 15), "0.666666666666667");
}

TEST(Decimal, RejectsDigitsOutOfRange) {
  char buf[bearing::kDecimalBufferSize];
  EXPECT_THROW(bearing::write_decimal(buf, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(bearing::write_decimal(buf, 1.0, 16), std::invalid_argument);
}

// Random values over 10^-60 … 10^60 at every precision: the same text as printf or, near a tie,
// a number within 0.5 + 5e-16·10^digits units of the last digit (the documented bound).
TEST(Decimal, MatchesPrintfExceptWithinTheDocumentedBoundOfATie) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> exponent(-60.0, 60.0), sign(-1.0, 1.0);
  long compared = 0, near_ties = 0;  // for digits <= 12
  for (int digits = 1; digits <= bearing::kMaxDecimalDigits; ++digits) {
    for (int i = 0; i < 20000; ++i) {
      const double v = std::copysign(std::pow(10.0, exponent(rng)), sign(rng));
      const std::string a = ours(v, digits), b = printf_g(v, digits);
      if (digits <= 12) ++compared, near_ties += a != b;
      if (a == b) continue;
      // Within the bound of the exact value (long double: 64-bit mantissa).
      const long double unit = std::pow(
          10.0L, std::floor(std::log10(std::fabs(static_cast<long double>(v)))) - (digits - 1));
      const long double ours_error = std::fabs(std::strtold(a.c_str(), nullptr) - v) / unit;
      EXPECT_LE(ours_error, 0.5L + 5e-16L * std::pow(10.0L, digits))
          << v << " digits " << digits << ": " << a << " vs " << b;
    }
  }
  // Up to 12 digits the tie zone is at most 5e-4 units wide: mismatches are rare.
  EXPECT_LT(near_ties, compared / 100) << near_ties << " of " << compared;
}

// Integers of 15 digits are exact and unscaled, so every digit must match printf: this exercises
// the two 8-digit halves (all digit values in every position) without any rounding question.
TEST(Decimal, FifteenDigitIntegersExactly) {
  std::mt19937_64 rng(15);
  std::uniform_int_distribution<long long> u(100000000000000LL, 999999999999999LL);
  for (int i = 0; i < 300000; ++i) {
    const double v = static_cast<double>(u(rng));
    ASSERT_EQ(ours(v, 15), printf_g(v, 15));
  }
  for (long long k = 0; k < 100000; ++k) {  // runs of trailing zeros and repeated digits
    const double v = 100000000000000.0 + 9999999999.0 * static_cast<double>(k % 90000) +
                     static_cast<double>(k % 10) * 1e13;
    ASSERT_EQ(ours(v, 15), printf_g(v, 15));
  }
}

// Sample times 5e-05·k print as printf prints them, and printing what was read back gives the same
// text; a double written with 15 digits reads back within 0.94 units of the 15th digit.
TEST(Decimal, ReadsBack) {
  for (int k = 0; k <= 24000; ++k) {
    const double t = 5e-05 * k;
    const double back = std::strtod(ours(t).c_str(), nullptr);
    EXPECT_EQ(ours(back), ours(t));
    EXPECT_EQ(ours(t), printf_g(t));
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    const double v = u(rng) * 1e-6;
    EXPECT_NEAR(std::strtod(ours(v, 15).c_str(), nullptr), v, 1e-14 * std::fabs(v));
  }
}

}  // namespace
