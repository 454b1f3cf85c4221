#pragma once
// Private to the lumped models (not installed).

namespace bearing::detail {

/// Largest ball count the lumped models accept (per-instant scratch lives on the stack).
constexpr int kMaxBalls = 256;

}  // namespace bearing::detail
