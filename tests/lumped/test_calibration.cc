// The FE-calibrated contact law (`[model] contact = "calibrated"`): the text of calibration.json
// read back, rejecting a file computed for another bearing, and the law of a ball between
// two calibrated races (closed form for equal exponents, least-squares fit otherwise).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/calibration.h"
#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/presets.h"
#include "bearing/units.h"
#include "calibration_files.h"

namespace bearing {
namespace {

using nlohmann::json;
using test::calibration_doc;
using test::hertz_calibration_doc;
using test::write_calibration;
using test::write_test_file;

// The 6308 as a case resolves it (preset), so the file's numbers are the case's to the bit.
Bearing case_bearing() {
  return parse_case("[bearing]\npreset = \"6308\"\n", "t.toml").bearing;
}

std::string calibrated_case(const std::string& calibration_path) {
  return "[bearing]\npreset = \"6308\"\n[operation]\nspeed = \"2000 rpm\"\nload = [0, -20]\n"
         "[model]\ncontact = \"calibrated\"\ncalibration = \"" +
         calibration_path + "\"\n";
}

Case parse_with(const json& doc, const std::string& name = "cal.json",
                const std::vector<std::string>& sets = {}) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return parse_case(calibrated_case(write_calibration(name, doc)), "t.toml", o);
}

double rel(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// (a) The exact Hertz constants written as a calibration with n = 1.5 give the exact law: the
// same K per race and for the ball, and the same curvatures and shape.
TEST(Calibration, HertzConstantsGiveTheExactLaw) {
  const Case cal = parse_with(hertz_calibration_doc(case_bearing()));
  Case exact = cal;
  exact.model.contact = ContactLaw::exact;
  exact.model.calibration.reset();
  const ContactConstants a = contact_constants(cal), b = contact_constants(exact);
  EXPECT_EQ(a.method, ContactLaw::calibrated);
  EXPECT_EQ(b.method, ContactLaw::exact);
  EXPECT_LE(rel(a.K, b.K), 1e-12);
  EXPECT_LE(rel(a.inner.K, b.inner.K), 1e-12);
  EXPECT_LE(rel(a.outer.K, b.outer.K), 1e-12);
  EXPECT_EQ(a.exponent, 1.5);
  EXPECT_EQ(a.inner.exponent, 1.5);
  EXPECT_EQ(a.series_fit_residual, 0.0);
  EXPECT_EQ(a.inner.sum_rho, b.inner.sum_rho);
  EXPECT_EQ(a.outer.f_rho, b.outer.f_rho);
  EXPECT_EQ(a.inner.shape.ellipticity, b.inner.shape.ellipticity);
  EXPECT_EQ(a.outer.semi_major(100.0), b.outer.semi_major(100.0));  // Hertz ellipse kept
  EXPECT_EQ(hertz_shape_method(cal.model), HertzMethod::exact);
}

// The file's values reach the Case: constants, provenance, the absolute path.
TEST(Calibration, CaseStoresTheParsedFile) {
  json doc = calibration_doc(case_bearing(), 1.23e10, 1.5012, 1.31e10, 1.4996);
  const Case c = parse_with(doc);
  ASSERT_TRUE(c.model.calibration.has_value());
  const ContactCalibration& k = *c.model.calibration;
  EXPECT_TRUE(std::filesystem::path(k.path).is_absolute()) << k.path;
  EXPECT_EQ(std::filesystem::path(k.path).filename(), "cal.json");
  EXPECT_EQ(k.inner.K, 1.23e10);
  EXPECT_EQ(k.inner.exponent, 1.5012);
  EXPECT_EQ(k.outer.K, 1.31e10);
  EXPECT_EQ(k.outer.exponent, 1.4996);
  EXPECT_EQ(k.inner.fit_residual, 3e-4);
  EXPECT_EQ(k.load_min, 1.0);
  EXPECT_EQ(k.load_max, 2500.0);
  EXPECT_EQ(k.geometry, "hertz");
  EXPECT_EQ(k.method, "test: Hertz-reduced FE");
  EXPECT_EQ(k.mesh, "test: 12k cells");
  EXPECT_EQ(k.date, "2026-11-22T06:00:00Z");
  EXPECT_EQ(k.bearing.designation, "6308");
  const ContactConstants cc = contact_constants(c);
  EXPECT_EQ(cc.inner.K, 1.23e10);
  EXPECT_EQ(cc.inner.exponent, 1.5012);
  EXPECT_EQ(cc.outer.exponent, 1.4996);
  EXPECT_GT(cc.exponent, 1.4996);
  EXPECT_LT(cc.exponent, 1.5012);
  EXPECT_GT(cc.series_fit_residual, 0.0);
  EXPECT_LT(cc.series_fit_residual, 1e-5);
  // The approach uses the race's own exponent.
  EXPECT_DOUBLE_EQ(cc.inner.approach(100.0), std::pow(100.0 / 1.23e10, 1.0 / 1.5012));

  // Optional keys may be left out when the exponents are equal.
  doc = calibration_doc(case_bearing(), 1.23e10, 1.45, 1.31e10, 1.45);
  for (const char* k : {"load_range", "geometry", "method", "mesh", "date", "units"}) doc.erase(k);
  doc["inner"].erase("fit_residual");
  const Case d = parse_with(doc, "minimal.json");
  EXPECT_FALSE(d.model.calibration->has_load_range());
  EXPECT_EQ(d.model.calibration->inner.fit_residual, -1);
  EXPECT_EQ(contact_constants(d).exponent, 1.45);
}

// (b) Equal exponents: K = (K_i^{-1/n} + K_o^{-1/n})^{-n}, checked against the two approaches
// added by hand for given loads, and against the load found by splitting a given total approach
// between the races (bisection on K_i δ_i^n = K_o (δ − δ_i)^n).
TEST(Calibration, EqualExponentsClosedFormIsTheSeriesOfTheTwoContacts) {
  const double Ki = 3.1e10, Ko = 3.7e10;
  for (double n : {1.0, 1.42, 1.5, 2.3}) {
    const double K = series_stiffness(Ki, Ko, n);
    for (double Q : {0.5, 20.0, 800.0, 3000.0}) {
      const double delta = std::pow(Q / Ki, 1 / n) + std::pow(Q / Ko, 1 / n);
      EXPECT_LE(rel(K * std::pow(delta, n), Q), 1e-12) << "n = " << n << ", Q = " << Q;
    }
    const double total = 7e-6;
    double lo = 0, hi = total;
    for (int i = 0; i < 200; ++i) {
      const double di = 0.5 * (lo + hi);
      (Ki * std::pow(di, n) < Ko * std::pow(total - di, n) ? lo : hi) = di;
    }
    const double Q = Ki * std::pow(0.5 * (lo + hi), n);
    EXPECT_LE(rel(K * std::pow(total, n), Q), 1e-12) << "n = " << n;
    const SeriesLaw law = series_law({Ki, n}, {Ko, n}, 0, 0);  // no load range needed
    EXPECT_EQ(law.K, K);
    EXPECT_EQ(law.exponent, n);
    EXPECT_EQ(law.residual, 0.0);
  }
  EXPECT_EQ(series_stiffness(Ki, Ko, 1.5), series_stiffness(Ki, Ko));  // the Hertz formula
}

// (c) Different exponents: the fitted law reproduces the series deflection inside the load range
// to within the residual it reports, and the fit reduces to the closed form for equal exponents.
TEST(Calibration, UnequalExponentsFitReproducesTheSeriesDeflection) {
  const RaceLaw inner{3.5e10, 1.45}, outer{3.7e10, 1.56};
  const double q0 = 1.0, q1 = 2500.0;
  const SeriesLaw law = series_law(inner, outer, q0, q1);
  EXPECT_GT(law.exponent, 1.45);
  EXPECT_LT(law.exponent, 1.56);
  EXPECT_GT(law.residual, 0.0);
  EXPECT_LT(law.residual, 1e-2);
  // Deflection error at 400 loads spaced between the fit's own (relative load error r gives a
  // relative deflection error r/n): RMS within the residual, every point within 3 times it.
  double sum = 0, worst = 0;
  const int m = 400;
  for (int k = 0; k < m; ++k) {
    const double Q = q0 * std::pow(q1 / q0, (k + 0.5) / m);
    const double series =
        std::pow(Q / inner.K, 1 / inner.exponent) + std::pow(Q / outer.K, 1 / outer.exponent);
    const double fitted = std::pow(Q / law.K, 1 / law.exponent);
    const double e = fitted / series - 1;
    sum += e * e;
    worst = std::max(worst, std::abs(e));
  }
  EXPECT_LE(std::sqrt(sum / m), law.residual);
  EXPECT_LE(worst, 3 * law.residual);
  EXPECT_GT(worst, 0.1 * law.residual);  // the residual is not a loose bound

  // Nearly equal exponents (the 1.5012 / 1.4996): a close power law.
  EXPECT_LT(series_law({1.23e10, 1.5012}, {1.31e10, 1.4996}, q0, q1).residual, 1e-5);

  // Equal exponents through the fit: the closed form, to rounding.
  for (double n : {1.2, 1.5, 1.8}) {
    const SeriesLaw fit = fit_series_law({3.5e10, n}, {3.7e10, n}, q0, q1);
    EXPECT_LE(rel(fit.K, series_stiffness(3.5e10, 3.7e10, n)), 1e-12) << n;
    EXPECT_NEAR(fit.exponent, n, 1e-13);
    EXPECT_LT(fit.residual, 1e-13);
  }
  // ... and the law is continuous as the exponents meet.
  const SeriesLaw near = series_law({3.5e10, 1.5 + 1e-9}, {3.7e10, 1.5}, q0, q1);
  EXPECT_LE(rel(near.K, series_stiffness(3.5e10, 3.7e10)), 1e-6);
}

// (d) Every malformed calibration gets one line naming the file, the field and the value.
struct BadFile {
  const char* what;
  std::string text;                 // the file's content
  std::vector<std::string> expect;  // substrings of the message
};

std::vector<BadFile> bad_files() {
  const json good = hertz_calibration_doc(case_bearing());
  const auto with = [&](auto change) {
    json d = good;
    change(d);
    return d.dump();
  };
  std::string inf_text = with([](json& d) { d["inner"]["K"] = 12345.5; });
  inf_text.replace(inf_text.find("12345.5"), 7, "1e999");
  return {
      {"invalid JSON", "{\"format\": ", {"not valid JSON"}},
      {"not an object", "[1, 2]", {"expected a JSON object", "array"}},
      {"wrong format",
       with([](json& d) { d["format"] = "bearing-fem calibration 2"; }),
       {"format", "bearing-fem calibration 2", "expected \"bearing-fem calibration 1\""}},
      {"missing format",
       with([](json& d) { d.erase("format"); }),
       {"format is missing", "bearing-fem calibration 1"}},
      {"missing K",
       with([](json& d) { d["inner"].erase("K"); }),
       {"inner.K", "missing", "N/m^1.5"}},
      {"K not a number",
       with([](json& d) { d["outer"]["K"] = "3.7e10"; }),
       {"outer.K", "\"3.7e10\"", "expected a number", "string"}},
      {"negative K",
       with([](json& d) { d["outer"]["K"] = -3e10; }),
       {"outer.K = -30000000000 N/m^1.5", "positive"}},
      {"zero K", with([](json& d) { d["inner"]["K"] = 0.0; }), {"inner.K", "= 0 ", "positive"}},
      {"infinite K", inf_text, {"inner.K", "1e999", "finite"}},
      {"exponent too large",
       with([](json& d) { d["inner"]["exponent"] = 3.5; }),
       {"inner.exponent", "3.5", "[1, 3]"}},
      {"exponent too small",
       with([](json& d) { d["outer"]["exponent"] = 0.9; }),
       {"outer.exponent", "0.9", "[1, 3]"}},
      {"exponent missing",
       with([](json& d) { d["inner"].erase("exponent"); }),
       {"inner.exponent", "missing"}},
      {"bearing missing", with([](json& d) { d.erase("bearing"); }), {"bearing", "missing"}},
      {"bearing field not a number",
       with([](json& d) { d["bearing"]["ball_diameter"] = "15.081 mm"; }),
       {"bearing.ball_diameter", "15.081 mm", "expected a number in m"}},
      {"material field missing",
       with([](json& d) { d["bearing"]["material"]["ball"].erase("young"); }),
       {"bearing.material.ball.young", "missing"}},
      {"load range reversed",
       with([](json& d) {
         d["load_range"] = {5.0, 1.0};
       }),
       {"load_range", "[5.0,1.0]", "0 < Q_min < Q_max"}},
      {"load range missing for unequal exponents",
       with([](json& d) {
         d.erase("load_range");
         d["inner"]["exponent"] = 1.45;
         d["outer"]["exponent"] = 1.55;
       }),
       {"load_range is missing", "1.45", "1.55"}},
      {"unknown geometry",
       with([](json& d) { d["geometry"] = "mesh"; }),
       {"geometry", "mesh", "hertz, groove"}},
      {"not SI",
       with([](json& d) { d["units"]["lengths"] = "mm"; }),
       {"units.lengths", "mm", "SI"}},
      {"method not text", with([](json& d) { d["method"] = 42; }), {"method", "42", "string"}},
      {"negative fit residual",
       with([](json& d) { d["inner"]["fit_residual"] = -1.0; }),
       {"inner.fit_residual", "-1", ">= 0"}},
      // Found by tests/fuzz/: printing this value in the message overflowed the stack.
      {"nested too deep",
       "{\"format\": " + std::string(100000, '[') + std::string(100000, ']') + "}",
       {"format is nested deeper than 64 levels"}},
  };
}

void expect_message(const std::string& what, const std::string& toml,
                    const std::vector<std::string>& expect) {
  try {
    parse_case(toml, "t.toml");
    ADD_FAILURE() << what << ": no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("t.toml", 0), 0u) << what << ": message does not name the case: " << m;
    for (const auto& s : expect)
      EXPECT_NE(m.find(s), std::string::npos) << what << ": message lacks \"" << s << "\": " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << what << ": not one line: " << m;
  }
}

TEST(Calibration, EachMalformedFileGetsAClearMessage) {
  for (const auto& bad : bad_files()) {
    const std::string path = write_test_file("bad_cal.json", bad.text);
    std::vector<std::string> expect = bad.expect;
    expect.push_back("model.calibration = \"" + path + "\"");
    expect_message(bad.what, calibrated_case(path), expect);
  }
}

TEST(Calibration, CaseLevelErrors) {
  const std::string good = write_calibration("good.json", hertz_calibration_doc(case_bearing()));
  const std::string preset = "[bearing]\npreset = \"6308\"\n";
  expect_message("calibrated without calibration", preset + "[model]\ncontact = \"calibrated\"\n",
                 {"model.contact = \"calibrated\"", "needs model.calibration"});
  expect_message(
      "calibration without calibrated", preset + "[model]\ncalibration = \"" + good + "\"\n",
      {"model.calibration = \"" + good + "\"", "model.contact = \"exact\"", "\"calibrated\""});
  expect_message("calibration with another method",
                 preset + "[model]\ncontact = \"hamrock-brewe\"\ncalibration = \"" + good + "\"\n",
                 {"model.calibration", "model.contact = \"hamrock-brewe\""});
  expect_message(
      "unreadable file", calibrated_case("/nonexistent/cal.json"),
      {"model.calibration = \"/nonexistent/cal.json\"", "cannot read", "/nonexistent/cal.json"});
  expect_message("calibration not a string", preset + "[model]\ncalibration = 3\n",
                 {"model.calibration", "3", "string"});
  expect_message("misspelt method", preset + "[model]\ncontact = \"calibrate\"\n",
                 {"model.contact", "calibrate", "did you mean \"calibrated\""});
  // An empty calibration switches a calibrated case back to a Hertz method.
  const Case c =
      parse_case(calibrated_case(good), "t.toml",
                 {parse_override("model.contact=exact"), parse_override("model.calibration=\"\"")});
  EXPECT_EQ(c.model.contact, ContactLaw::exact);
  EXPECT_FALSE(c.model.calibration.has_value());
}

// (e) A file computed for another contact geometry is rejected, naming the field and both values;
// one that differs only in what the contact constants do not depend on is accepted.
TEST(Calibration, RejectsAFileForAnotherBearing) {
  const Bearing b = case_bearing();
  struct Change {
    std::vector<std::string> path;  // JSON path under "bearing"
    double value;
    std::vector<std::string> expect;
  };
  const auto mm = [](double v) { return format_quantity(v, "mm", Dimension::length); };
  const std::vector<Change> changes = {
      {{"ball_diameter"}, 15.875e-3, {"bearing.ball_diameter = 15.875 mm", "15.081 mm"}},
      {{"pitch_diameter"},
       b.pitch_diameter * (1 + 2e-9),
       {"bearing.pitch_diameter = " + mm(b.pitch_diameter * (1 + 2e-9)), mm(b.pitch_diameter)}},
      {{"inner_conformity"}, 0.53, {"bearing.inner_conformity = 0.53", "has 0.52"}},
      {{"outer_conformity"}, 0.51, {"bearing.outer_conformity = 0.51", "has 0.52"}},
      {{"contact_angle"}, 0.1, {"bearing.contact_angle = 5.72957795", "has 0 deg"}},
      {{"material", "ball", "young"}, 3.15e11, {"material.ball.young = 315 GPa", "has 208 GPa"}},
      {{"material", "ball", "poisson"}, 0.26, {"material.ball.poisson = 0.26", "has 0.3"}},
      {{"material", "rings", "young"}, 2.1e11, {"material.rings.young = 210 GPa", "has 208 GPa"}},
      {{"material", "rings", "poisson"}, 0.29, {"material.rings.poisson = 0.29", "has 0.3"}},
  };
  for (const auto& ch : changes) {
    json doc = hertz_calibration_doc(b);
    json* node = &doc["bearing"];
    for (const auto& p : ch.path) node = &(*node)[p];
    *node = ch.value;
    if (ch.path.front() == "ball_diameter") doc["bearing"]["designation"] = "6304";
    const std::string path = write_calibration("other_bearing.json", doc);
    std::vector<std::string> expect = ch.expect;
    expect.push_back("model.calibration = \"" + path + "\": computed for");
    expect.push_back("recompute it with bearing-fem calibrate for this case");
    if (ch.path.front() == "ball_diameter") expect.push_back("(designation 6304)");
    expect_message(ch.path.back(), calibrated_case(path), expect);
  }

  // Within the tolerances (1e-9 relative, 1e-12 rad): the same bearing.
  json close = hertz_calibration_doc(b);
  close["bearing"]["ball_diameter"] = b.ball_diameter * (1 + 1e-11);
  close["bearing"]["contact_angle"] = 1e-13;
  close["bearing"]["material"]["rings"]["young"] = b.rings.young * (1 - 5e-10);
  EXPECT_NO_THROW(parse_with(close, "close.json"));
}

TEST(Calibration, AcceptsAFileDifferingOnlyInClearanceBallsAndRotor) {
  json doc = hertz_calibration_doc(case_bearing());
  doc["bearing"]["balls"] = 9;  // extra keys a writer may add: not contact geometry
  doc["bearing"]["clearance"] = 2e-5;
  doc["bearing"]["material"]["ball"]["density"] = 3200.0;
  const Case c = parse_with(doc, "extra.json",
                            {"bearing.clearance=20um", "bearing.balls=9", "material.density=3200",
                             "rotor.mass=1.5kg", "operation.speed=3000rpm"});
  EXPECT_EQ(c.bearing.balls, 9);
  EXPECT_EQ(contact_constants(c).method, ContactLaw::calibrated);
}

// Paths: relative to the case file's folder in the file, to the working directory on the command
// line; case_to_toml writes the absolute path and reads back the same calibration.
TEST(Calibration, PathsAndTheResolvedCase) {
  namespace fs = std::filesystem;
  const fs::path dir = test::test_dir() / "cal_paths";
  fs::remove_all(dir);
  write_calibration("cal_paths/cases/near.json", hertz_calibration_doc(case_bearing()));
  write_calibration("cal_paths/cwd/here.json", hertz_calibration_doc(case_bearing()));
  const std::string case_path =
      write_test_file("cal_paths/cases/case.toml", calibrated_case("near.json"));

  const Case a = read_case_file(case_path);
  EXPECT_EQ(fs::path(a.model.calibration->path), (dir / "cases" / "near.json").lexically_normal());

  const fs::path old = fs::current_path();
  fs::current_path(dir / "cwd");
  const Case b = read_case_file(case_path, {parse_override("model.calibration=here.json")});
  fs::current_path(old);
  EXPECT_EQ(fs::path(b.model.calibration->path), (dir / "cwd" / "here.json").lexically_normal());

  const std::string toml = case_to_toml(a);
  EXPECT_NE(toml.find("contact = \"calibrated\""), std::string::npos) << toml;
  EXPECT_NE(toml.find("calibration = \"" + a.model.calibration->path + "\""), std::string::npos)
      << toml;
  const Case r = parse_case(toml, "resolved.toml", {}, "/somewhere/else");
  ASSERT_TRUE(r.model.calibration.has_value());
  EXPECT_EQ(r.model.calibration->path, a.model.calibration->path);
  EXPECT_EQ(contact_constants(r).K, contact_constants(a).K);
}

// The file's text (what bearing-fem calibrate writes) and the reader agree on every field, to the
// bit; the record for people (K_three_halves, hertz_K, details, case) is in the file too.
TEST(Calibration, WrittenFileReadsBackExactly) {
  CalibrationDocument doc;
  ContactCalibration& cal = doc.calibration;
  cal.bearing = case_bearing();
  cal.bearing.designation = "6308-test";
  cal.bearing.ball_diameter = 1.0 / 66.0;  // numbers without a short decimal form
  cal.bearing.inner_conformity = 0.1 + 0.42;
  cal.bearing.contact_angle = std::nextafter(0.2, 1.0);
  cal.bearing.rings.poisson = std::nextafter(0.3, 0.0);
  cal.inner = {35996868626.91724, 1.5015359213753956, 0.0003496142744503277};
  cal.outer = {38661719399.47691, 1.0 + 1.0 / 3.0, 4.2e-4};
  cal.load_min = 1.9999999999999987;
  cal.load_max = 19.999999999999986;
  cal.geometry = "groove";
  cal.method = "test: \"quoted\" method, \u00e9";
  cal.mesh = "test: 35883 cells";
  cal.date = "2026-11-22T05:40:52Z";
  doc.inner_fit = {35179326229.21373, 35066601758.29305, "cal_inner"};
  doc.outer_fit = {37601800818.32296, 37473288750.74463, "cal_outer"};
  doc.case_source = "examples/seed003_6308.toml";

  namespace fs = std::filesystem;
  const std::string path = write_test_file("written.json", calibration_text(doc));
  const ContactCalibration back = read_calibration(path, "written.json");

  EXPECT_EQ(back.path, fs::absolute(path).lexically_normal().string());
  const Bearing &b = back.bearing, &w = cal.bearing;
  EXPECT_EQ(b.designation, w.designation);
  EXPECT_EQ(b.ball_diameter, w.ball_diameter);
  EXPECT_EQ(b.pitch_diameter, w.pitch_diameter);
  EXPECT_EQ(b.inner_conformity, w.inner_conformity);
  EXPECT_EQ(b.outer_conformity, w.outer_conformity);
  EXPECT_EQ(b.contact_angle, w.contact_angle);
  EXPECT_EQ(b.ball.young, w.ball.young);
  EXPECT_EQ(b.ball.poisson, w.ball.poisson);
  EXPECT_EQ(b.rings.young, w.rings.young);
  EXPECT_EQ(b.rings.poisson, w.rings.poisson);
  for (const auto& [got, wrote] : {std::pair{back.inner, cal.inner}, {back.outer, cal.outer}}) {
    EXPECT_EQ(got.K, wrote.K);
    EXPECT_EQ(got.exponent, wrote.exponent);
    EXPECT_EQ(got.fit_residual, wrote.fit_residual);
  }
  EXPECT_EQ(back.load_min, cal.load_min);
  EXPECT_EQ(back.load_max, cal.load_max);
  EXPECT_EQ(back.geometry, cal.geometry);
  EXPECT_EQ(back.method, cal.method);
  EXPECT_EQ(back.mesh, cal.mesh);
  EXPECT_EQ(back.date, cal.date);
  check_calibration_bearing(back, w, "written.json");  // the same contact geometry

  const json file = json::parse(std::ifstream(path));
  EXPECT_EQ(file["inner"]["K_three_halves"], 35179326229.21373);
  EXPECT_EQ(file["outer"]["hertz_K"], 37473288750.74463);
  EXPECT_EQ(file["inner"]["details"], "cal_inner");
  EXPECT_EQ(file["case"], "examples/seed003_6308.toml");
  EXPECT_EQ(file.dump(2) + "\n", calibration_text(doc));
}

// A residual not given, no load range (equal exponents) and no geometry are written as absent,
// which is how the reader reads them.
TEST(Calibration, WrittenFileLeavesOutWhatIsNotGiven) {
  CalibrationDocument doc;
  doc.calibration.bearing = case_bearing();
  doc.calibration.inner = {3.1e10, 1.45};
  doc.calibration.outer = {3.7e10, 1.45};
  const std::string text = calibration_text(doc);
  const json file = json::parse(text);
  for (const json* where : {&file, &file["inner"], &file["outer"]})
    for (const char* key : {"fit_residual", "load_range", "geometry"})
      EXPECT_FALSE(where->contains(key)) << key << " in\n" << text;
  const ContactCalibration back = parse_calibration(text, "mem.json", "mem.json");
  EXPECT_EQ(back.inner.fit_residual, -1);
  EXPECT_EQ(back.outer.fit_residual, -1);
  EXPECT_FALSE(back.has_load_range());
  EXPECT_EQ(back.geometry, "");
  EXPECT_EQ(back.outer.K, 3.7e10);
}

// The committed example was written by bearing-fem calibrate before the writer moved here: the
// same document gives the same bytes.
TEST(Calibration, WriterReproducesTheExampleFile) {
  const std::string path =
      std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308_calibration.json";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const json file = json::parse(text);
  CalibrationDocument doc;
  doc.calibration = parse_calibration(text, path, "example");
  const auto record = [&](const char* race) {
    const json& r = file[race];
    return RaceFitRecord{r["K_three_halves"], r["hertz_K"], r["details"]};
  };
  doc.inner_fit = record("inner");
  doc.outer_fit = record("outer");
  doc.case_source = file["case"];
  EXPECT_EQ(calibration_text(doc), text);
}

}  // namespace
}  // namespace bearing
