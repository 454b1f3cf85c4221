#pragma once
// Calibration files for the tests: the JSON `bearing-fem calibrate` writes (lumped/include/
// bearing/calibration.h), built from a bearing and chosen constants and written into the test's
// temporary directory.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/bearing.h"
#include "bearing/contact.h"
#include "bearing/hertz.h"

namespace bearing::test {

/// A complete calibration of bearing `b` with Q = K_i δ^{n_i} (inner) and K_o δ^{n_o} (outer).
inline nlohmann::json calibration_doc(const Bearing& b, double k_inner, double n_inner,
                                      double k_outer, double n_outer) {
  using nlohmann::json;
  const auto material = [](const Material& m) {
    return json{{"young", m.young}, {"poisson", m.poisson}};
  };
  return json{{"format", "bearing-fem calibration 1"},
              {"bearing",
               {{"designation", b.designation},
                {"ball_diameter", b.ball_diameter},
                {"pitch_diameter", b.pitch_diameter},
                {"inner_conformity", b.inner_conformity},
                {"outer_conformity", b.outer_conformity},
                {"contact_angle", b.contact_angle},
                {"material", {{"ball", material(b.ball)}, {"rings", material(b.rings)}}}}},
              {"inner", {{"K", k_inner}, {"exponent", n_inner}, {"fit_residual", 3e-4}}},
              {"outer", {{"K", k_outer}, {"exponent", n_outer}, {"fit_residual", 2e-4}}},
              {"load_range", {1.0, 2500.0}},
              {"geometry", "hertz"},
              {"method", "test: Hertz-reduced FE"},
              {"mesh", "test: 12k cells"},
              {"date", "2026-11-22T06:00:00Z"},
              {"units",
               {{"K", "N/m^exponent"},
                {"lengths", "m"},
                {"young", "Pa"},
                {"contact_angle", "rad"},
                {"load_range", "N"}}}};
}

/// The exact Hertz constants of `b` as a calibration (exponent 1.5 on both races).
inline nlohmann::json hertz_calibration_doc(const Bearing& b) {
  const ContactConstants cc = contact_constants(b, *make_exact_hertz());
  return calibration_doc(b, cc.inner.K, 1.5, cc.outer.K, 1.5);
}

/// A folder of the temporary directory for the running test alone (ctest runs tests in
/// parallel, each in its own process): <temporary directory>/<suite>.<test>.
inline std::filesystem::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::filesystem::path(::testing::TempDir()) /
         (std::string(info->test_suite_name()) + "." + info->name());
}

/// Writes `text` to test_dir()/<name> and returns the path.
inline std::string write_test_file(const std::string& name, const std::string& text) {
  const std::filesystem::path p = test_dir() / name;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

/// Writes `doc` as JSON (numbers round-trip exactly, as bearing-fem's 17 digits do).
inline std::string write_calibration(const std::string& name, const nlohmann::json& doc) {
  return write_test_file(name, doc.dump(2) + "\n");
}

}  // namespace bearing::test
