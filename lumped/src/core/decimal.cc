#include "bearing/decimal.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace bearing {

namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "write_decimal stores digit words little-endian");
__extension__ typedef unsigned __int128 Uint128;  // GCC/Clang; __extension__: no -Wpedantic note

// 10^k for k = 0 … 22: every one exact in a double.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// a·10^s with at most two correctly rounded operations by exact powers; false outside |s| ≤ 44.
bool scale(double a, int s, double& out) {
  if (s >= 0) {
    if (s <= 22) return out = a * kPow10[s], true;
    if (s <= 44) return out = (a * 1e22) * kPow10[s - 22], true;
  } else {
    if (s >= -22) return out = a / kPow10[-s], true;
    if (s >= -44) return out = (a / 1e22) / kPow10[-s - 22], true;
  }
  return false;
}

char* fallback(char* out, double value, int digits) {
  const int n = std::snprintf(out, kDecimalBufferSize, "%.*g", digits, value);
  return out + n;
}

// The 8 decimal digits of u < 10^8 as the byte values 0…9 of a little-endian word, most
// significant digit in the lowest byte: u = hi·10^4 + lo split into lanes, each lane into two
// pairs (÷100 as ×10486 >> 20), each pair into two digits (÷10 as ×103 >> 10), all in one
// 64-bit register (exact for every u < 10^8: checked against snprintf for all of them once, and
// by the 15-digit integer test in tests/lumped/test_decimal.cc).
std::uint64_t eight_digits(std::uint32_t u) {
  const std::uint64_t merged = (u / 10000) | (static_cast<std::uint64_t>(u % 10000) << 32);
  const std::uint64_t top = ((merged * 10486) >> 20) & ((0x7FULL << 32) | 0x7FULL);
  const std::uint64_t hundreds = ((merged - 100 * top) << 16) + top;
  std::uint64_t tens = (hundreds * 103) >> 10;
  tens &= (0xFULL << 48) | (0xFULL << 32) | (0xFULL << 16) | 0xFULL;
  return tens + ((hundreds - 10 * tens) << 8);
}

char* write_exponent(char* p, int e) {
  *p++ = 'e';
  *p++ = e < 0 ? '-' : '+';
  unsigned u = static_cast<unsigned>(e < 0 ? -e : e);
  if (u >= 100) {
    *p++ = static_cast<char>('0' + u / 100);
    u %= 100;
  }
  *p++ = static_cast<char>('0' + u / 10);
  *p++ = static_cast<char>('0' + u % 10);
  return p;
}

}  // namespace

char* write_decimal(char* out, double value, int digits) {
  if (digits < 1 || digits > kMaxDecimalDigits)
    throw std::invalid_argument("write_decimal: digits = " + std::to_string(digits) +
                                " (allowed 1 to " + std::to_string(kMaxDecimalDigits) + ")");
  if (!std::isfinite(value)) return fallback(out, value, digits);
  char* p = out;
  double a = value;
  if (std::signbit(a)) {
    *p++ = '-';
    a = -a;
  }
  if (a == 0) {
    *p++ = '0';
    return p;
  }
  // a = f 2^e with f in [1, 2): the decimal exponent is floor(e log10 2) or one above it
  // (78913 / 2^18 is log10 2 to enough bits for every double exponent). Subnormals: snprintf.
  std::uint64_t bits = 0;
  std::memcpy(&bits, &a, sizeof bits);
  const int e2 = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  if (e2 == -1023) return fallback(out, value, digits);
  int e10 = (e2 * 78913) >> 18;       // arithmetic shift: floor for negative e2 too
  const double top = kPow10[digits];  // the rounded mantissa lies in [10^(digits−1), 10^digits)
  double m = 0;
  if (!scale(a, digits - 1 - e10, m)) return fallback(out, value, digits);
  if (m >= top) {
    ++e10;
    if (!scale(a, digits - 1 - e10, m)) return fallback(out, value, digits);
  }
  // Round half to even, as printf does for an exactly representable tie (m < 2^53: m + 0.5 and
  // the truncation are exact).
  auto u = static_cast<std::uint64_t>(m + 0.5);
  if (static_cast<double>(u) - m == 0.5 && (u & 1)) --u;
  if (static_cast<double>(u) >= top) {  // 9.99…5 rounded up to the next power of ten
    u = static_cast<std::uint64_t>(kPow10[digits - 1]);
    ++e10;
  }
  // The digits of u as 16 characters in one 128-bit value (first character in the lowest byte),
  // shifted so the first significant digit comes first; the pieces are stored 16 bytes at a time
  // (`out` has room) and the pointer advanced by the real length. Trailing zero digits are zero
  // bytes at the top of the digit values.
  const std::uint64_t hi = eight_digits(static_cast<std::uint32_t>(u / 100000000));
  const std::uint64_t lo = eight_digits(static_cast<std::uint32_t>(u % 100000000));
  const int zeros = lo != 0 ? __builtin_clzll(lo) / 8 : 8 + __builtin_clzll(hi) / 8;
  const int n = digits - zeros;  // significant digits left (u >= 10^(digits−1): n >= 1)
  constexpr std::uint64_t kAscii = 0x3030303030303030ULL;
  const Uint128 text =
      ((static_cast<Uint128>(lo + kAscii) << 64) | (hi + kAscii)) >> (8 * (16 - digits));

  if (e10 < -4 || e10 >= digits) {  // scientific, as %g: d.ddd e±XX
    const Uint128 rest = text >> 8;
    *p = static_cast<char>(text & 0xff);
    p[1] = '.';
    std::memcpy(p + 2, &rest, 16);
    p += n > 1 ? n + 1 : 1;
    return write_exponent(p, e10);
  }
  if (e10 < 0) {  // 0.000ddd (e10 >= −4)
    std::memcpy(p, "0.000000", 8);
    p += 1 - e10;
    std::memcpy(p, &text, 16);
    return p + n;
  }
  // ddd.ddd: e10 < digits, so the integer part is all in the text.
  std::memcpy(p, &text, 16);
  if (n <= e10 + 1) return p + e10 + 1;
  const Uint128 fraction = text >> (8 * (e10 + 1));
  p[e10 + 1] = '.';
  std::memcpy(p + e10 + 2, &fraction, 16);
  return p + n + 1;
}

}  // namespace bearing
