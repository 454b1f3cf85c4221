// Fuzz target: the structure-file reader of `bearing-fem modes` (fem/modes/structure_file.h, no
// deal.II). The input is the file's text, parsed by parse_structure.
//
// After a successful parse it checks the ranges structure_file.h documents: E in (0, 1e13] Pa,
// nu in [0, 0.5), rho in (0, 1e5] kg/m^3, a count in [1, 500] or a maximum frequency in
// (0, 1e7] Hz, a seat named, a mesh named, mesh_unit m or mm, sensors named [A-Za-z0-9_]+ at
// finite points.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_harness.h"
#include "modes/structure_file.h"

namespace {

constexpr const char* kTarget = "fuzz_structure_file";

void check(const bearing::fem::StructureFile& s) {
  using bearing::fuzz::property_failed;
  if (!(s.young > 0 && s.young <= 1e13)) property_failed(kTarget, "young out of range accepted");
  if (!(s.poisson >= 0 && s.poisson < 0.5)) property_failed(kTarget, "poisson out of range");
  if (!(s.density > 0 && s.density <= 1e5)) property_failed(kTarget, "density out of range");
  if (s.count > 500 || (s.count == 0 && !(s.max_frequency > 0)))
    property_failed(kTarget, "neither a count in [1, 500] nor a maximum frequency");
  if (!(s.max_frequency >= 0 && s.max_frequency <= 1e7))
    property_failed(kTarget, "max_frequency out of range");
  if (s.seat.empty() || s.mesh.empty()) property_failed(kTarget, "no seat or no mesh");
  if (s.mesh_unit != "m" && s.mesh_unit != "mm") property_failed(kTarget, "mesh_unit");
  for (const auto& sensor : s.sensors) {
    if (sensor.name.empty()) property_failed(kTarget, "an unnamed sensor");
    for (char c : sensor.name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        property_failed(kTarget, "a sensor name outside [A-Za-z0-9_]+: " + sensor.name);
    for (double x : sensor.point)
      if (!std::isfinite(x)) property_failed(kTarget, "a sensor point that is not finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::expect_only_input_errors(
      kTarget, [&] { check(bearing::fem::parse_structure(text, "fuzz/structure.toml")); });
  return 0;
}
