#pragma once
// How the models' per-ball contact loop is computed: vectorised over the balls (the default) or
// one ball at a time (kept for checking; the two give the same bits, tests/lumped/test_simd.cc).

#include <string>

#include "bearing/choice.h"

namespace bearing {

enum class ContactLoop {
  simd,    ///< over the balls in SIMD lanes, instruction set chosen at run time (Highway)
  scalar,  ///< one ball at a time
};

inline constexpr Named<ContactLoop> kContactLoops[] = {
    {ContactLoop::simd, "simd"},
    {ContactLoop::scalar, "scalar"},
};

/// The instruction set the `simd` contact loop runs with on this machine ("AVX3", "AVX2",
/// "SSE4", "EMU128", ...), or "scalar (built without Highway)". Defined by the models library
/// (lumped/src/models/contact_kernels.cc), which holds the loop.
std::string simd_target();

}  // namespace bearing
