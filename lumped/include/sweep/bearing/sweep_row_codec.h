#pragma once
// A SweepRow as bytes and back, for sending rows between processes (MPI sweeps, issue 20).

#include <cstddef>
#include <string>
#include <string_view>

#include "bearing/sweep.h"

namespace bearing {

/// Case `index` and its row as bytes: every field of the row (values, ok, error, each channel's
/// name, unit, group, statistics and peaks, each microphone's levels, each envelope's figures, the
/// diagnosis, and `--save`'s tables when the row carries them), doubles as their raw 8
/// bytes, so the row decodes bit for bit on a machine of the same byte order and double format
/// (a homogeneous cluster). Appends to `out`.
void encode_sweep_row(std::size_t index, const SweepRow& row, std::string& out);

/// The case index and row of encode_sweep_row's bytes. Throws std::runtime_error if `bytes` is
/// not exactly one encoded row (truncated, or trailing bytes).
SweepRow decode_sweep_row(std::string_view bytes, std::size_t& index);

}  // namespace bearing
