// Fuzz target: the modes-file reader (modes.json of `bearing-fem modes`, read back for
// `[housing] modes = "..."`). The input is the file's text.
//
// After a successful parse it checks what structure_modes.h promises: 1 to kMaxStructureModes
// modes, frequencies finite, positive and ascending, the seat's and each sensor's shapes one
// finite value per mode, and sensor names of letters, digits and '_', each once.

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>

#include "bearing/structure_modes.h"
#include "fuzz_harness.h"

namespace {

constexpr const char* kTarget = "fuzz_structure_modes";

void check_shapes(const std::array<std::vector<double>, 3>& shape, std::size_t modes) {
  for (const auto& axis : shape) {
    if (axis.size() != modes)
      bearing::fuzz::property_failed(kTarget, "a shape without one value per mode was accepted");
    for (double v : axis)
      if (!std::isfinite(v)) bearing::fuzz::property_failed(kTarget, "a shape value not finite");
  }
}

void check(const bearing::StructureModes& m) {
  const std::size_t n = m.frequencies.size();
  if (n < 1 || n > static_cast<std::size_t>(bearing::kMaxStructureModes))
    bearing::fuzz::property_failed(kTarget, "a mode count outside 1..500 was accepted");
  for (std::size_t k = 0; k < n; ++k)
    if (!(std::isfinite(m.frequencies[k]) && m.frequencies[k] > 0 &&
          (k == 0 || m.frequencies[k] >= m.frequencies[k - 1])))
      bearing::fuzz::property_failed(kTarget, "frequencies not positive, finite and ascending");
  check_shapes(m.seat, n);
  std::set<std::string> names;
  for (const bearing::StructureSensor& s : m.sensors) {
    check_shapes(s.shape, n);
    bool valid = !s.name.empty() && names.insert(s.name).second;
    for (const char ch : s.name)
      valid = valid && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
    if (!valid)
      bearing::fuzz::property_failed(kTarget, "a sensor name invalid or twice: " + s.name);
    for (double x : s.point)
      if (!std::isfinite(x)) bearing::fuzz::property_failed(kTarget, "a sensor point not finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::expect_only_input_errors(kTarget, [&] {
    check(bearing::parse_structure_modes(text, "/fuzz/modes.json", "housing.modes"));
  });
  return 0;
}
