// Fuzz target: the waviness CSV table reader ([[waviness.inner]] table = "file.csv"). The input
// is the table's text, parsed by parse_waviness_table (read_waviness_table without the file).
//
// After a successful parse it checks what excitation.h promises of the rows it accepted: order
// >= 1, amplitude finite and >= 0, phase finite.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "bearing/excitation.h"
#include "fuzz_harness.h"

namespace {

constexpr const char* kTarget = "fuzz_waviness";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::expect_only_input_errors(kTarget, [&] {
    const auto rows = bearing::parse_waviness_table(text, "fuzz.csv", "waviness.inner[0].table");
    if (rows.empty()) bearing::fuzz::property_failed(kTarget, "an empty table was accepted");
    for (const bearing::WavinessHarmonic& h : rows)
      if (!(h.order >= 1 && std::isfinite(h.amplitude) && h.amplitude >= 0 &&
            std::isfinite(h.phase)))
        bearing::fuzz::property_failed(
            kTarget,
            "a row outside order >= 1, finite amplitude >= 0, finite phase was accepted: "
            "order " +
                std::to_string(h.order) + ", amplitude " + std::to_string(h.amplitude) +
                " m, phase " + std::to_string(h.phase) + " rad");
  });
  return 0;
}
