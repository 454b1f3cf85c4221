#pragma once
// The report of `bearing-verify calibrate`: every contact law against the FE-calibrated one over
// the calibrated load range (per race), and the lumped response under each law.

#include <string>
#include <vector>

#include "bearing/analysis.h"
#include "bearing/bearing.h"
#include "bearing/calibration.h"
#include "bearing/contact.h"

namespace bearing::verify {

/// An FE force–approach curve.
struct FeCurve {
  std::string label;
  std::vector<double> approach;  ///< δ [m]
  std::vector<double> force;     ///< Q [N]
};

struct RaceStudy {
  Race race = Race::inner;
  std::vector<FeCurve> curves;  ///< the calibrated geometry's first, then the other
};

/// The lumped run of the case under one contact law.
struct LawResponse {
  std::string law;  ///< model.contact
  RunSummary summary;
  ContactConstants contact;
};

struct CalibrationStudy {
  std::string case_path;
  Bearing bearing;
  ContactCalibration calibration;
  std::string geometry;  ///< the FE geometry the calibration is fitted to
  std::string mesh;
  std::vector<RaceStudy> races;
  std::vector<LawResponse> responses;  ///< empty for a static case
  bool static_case = false;            ///< operation.speed = 0: nothing vibrates to compare
};

/// Writes DIR/calibration_report.{html,md,json} and DIR/figures/ (each file complete or absent).
void write_calibration_report(const CalibrationStudy& study, const std::string& dir);

}  // namespace bearing::verify
