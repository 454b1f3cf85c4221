// Fuzz target: the calibration-file reader (calibration.json of `bearing-fem calibrate`, read
// back for model.contact = "calibrated"). The input is the file's text.
//
// After a successful parse it checks what calibration.h promises: the values it accepted are in
// their documented ranges, and the file calibration_text writes of them reads back to the same
// constants.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "bearing/calibration.h"
#include "fuzz_harness.h"

namespace {

constexpr const char* kTarget = "fuzz_calibration";

void check_ranges(const bearing::ContactCalibration& c) {
  for (const bearing::RaceLaw* r : {&c.inner, &c.outer})
    if (!(std::isfinite(r->K) && r->K > 0 && r->exponent >= 1 && r->exponent <= 3))
      bearing::fuzz::property_failed(kTarget, "a race law outside K > 0, n in [1, 3] was accepted");
  if (c.has_load_range() && !(c.load_min > 0 && c.load_min < c.load_max))
    bearing::fuzz::property_failed(kTarget, "a load_range without 0 < Q_min < Q_max was accepted");
}

void check_round_trip(const bearing::ContactCalibration& a) {
  bearing::CalibrationDocument doc;
  doc.calibration = a;
  const std::string text = bearing::calibration_text(doc);
  bearing::ContactCalibration b;
  try {
    b = bearing::parse_calibration(text, a.path, "written");
  } catch (const bearing::InputError& e) {
    bearing::fuzz::property_failed(
        kTarget, std::string("calibration_text does not read back: ") + e.what() + "\n" + text);
  }
  const bool same = b.inner.K == a.inner.K && b.inner.exponent == a.inner.exponent &&
                    b.outer.K == a.outer.K && b.outer.exponent == a.outer.exponent &&
                    b.load_min == a.load_min && b.load_max == a.load_max &&
                    b.bearing.ball_diameter == a.bearing.ball_diameter &&
                    b.bearing.contact_angle == a.bearing.contact_angle &&
                    b.bearing.ball.young == a.bearing.ball.young && b.geometry == a.geometry;
  if (!same)
    bearing::fuzz::property_failed(kTarget, "calibration_text reads back different:\n" + text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::expect_only_input_errors(kTarget, [&] {
    const bearing::ContactCalibration c =
        bearing::parse_calibration(text, "/fuzz/calibration.json", "model.calibration");
    check_ranges(c);
    check_round_trip(c);
  });
  return 0;
}
