#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

using bearing::Dimension;
using bearing::format_quantity;
using bearing::InputError;
using bearing::parse_quantity;
using bearing::pi;
using bearing::two_pi;

namespace {}

TEST(Units, ParsesTheDesignExamples) {
  EXPECT_DOUBLE_EQ(parse_quantity("15.081 mm", Dimension::length, "k"), 15.081e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("2 um", Dimension::length, "k"), 2e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("2000 rpm", Dimension::angular_speed, "k"), 2000 * two_pi / 60);
  EXPECT_DOUBLE_EQ(parse_quantity("0.05 kN", Dimension::force, "k"), 50.0);
  EXPECT_DOUBLE_EQ(parse_quantity("208 GPa", Dimension::pressure, "k"), 2.08e11);
  EXPECT_DOUBLE_EQ(parse_quantity("30 deg", Dimension::angle, "k"), pi / 6);
  EXPECT_DOUBLE_EQ(parse_quantity("5 us", Dimension::time, "k"), 5e-6);
}

TEST(Units, AcceptsSpellingsOfTheSameUnit) {
  const double two_um = 2e-6;
  EXPECT_DOUBLE_EQ(parse_quantity("2um", Dimension::length, "k"), two_um);
  EXPECT_DOUBLE_EQ(parse_quantity("2 \xC2\xB5m", Dimension::length, "k"), two_um);  // micro sign
  EXPECT_DOUBLE_EQ(parse_quantity("2 \xCE\xBCm", Dimension::length, "k"), two_um);  // Greek mu
  EXPECT_DOUBLE_EQ(parse_quantity("30\xC2\xB0", Dimension::angle, "k"), pi / 6);    // degree sign
  EXPECT_DOUBLE_EQ(parse_quantity("200 N s/m", Dimension::damping, "k"), 200.0);
  EXPECT_DOUBLE_EQ(parse_quantity("200 N*s/m", Dimension::damping, "k"), 200.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7.85 g/cm^3", Dimension::density, "k"), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1 in", Dimension::length, "k"), 0.0254);
  EXPECT_DOUBLE_EQ(parse_quantity("-20 N", Dimension::force, "k"), -20.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1e3 N", Dimension::force, "k"), 1000.0);
  EXPECT_DOUBLE_EQ(parse_quantity("33.3 Hz", Dimension::angular_speed, "k"), 33.3 * two_pi);
  EXPECT_DOUBLE_EQ(parse_quantity("0.52", Dimension::dimensionless, "k"), 0.52);
  EXPECT_EQ(parse_quantity("2 N*m", Dimension::moment, "k"), 2.0);
  EXPECT_EQ(parse_quantity("2 N m", Dimension::moment, "k"), 2.0);
  EXPECT_EQ(parse_quantity("1.5 kN m", Dimension::moment, "k"), 1500.0);
  EXPECT_EQ(parse_quantity("300 N mm", Dimension::moment, "k"), 0.3);  // exactly the double 0.3
  EXPECT_DOUBLE_EQ(parse_quantity("1 lbf in", Dimension::moment, "k"), 0.1129848290276167);
}

TEST(Units, RoundTripsThroughText) {
  struct Case {
    double si;
    const char* unit;
    Dimension dim;
  };
  const Case cases[] = {{0.015081, "mm", Dimension::length},
                        {1.4e-5, "um", Dimension::length},
                        {3.969e-3, "in", Dimension::length},
                        {209.43951023931953, "rpm", Dimension::angular_speed},
                        {209.43951023931953, "rad/s", Dimension::angular_speed},
                        {0.5235987755982988, "deg", Dimension::angle},
                        {2.07e11, "GPa", Dimension::pressure},
                        {-1234.5, "kN", Dimension::force},
                        {7850, "g/cm^3", Dimension::density},
                        {5e-6, "us", Dimension::time},
                        {350, "N s/m", Dimension::damping}};
  for (const auto& c : cases) {
    const std::string text = format_quantity(c.si, c.unit, c.dim);
    const double back = parse_quantity(text, c.dim, "k");
    // The decimal text is the shortest that parses back; unit factors that are not exact in
    // binary (deg, rpm, in) may leave one rounding of the product, hence DOUBLE_EQ (4 ulp).
    EXPECT_DOUBLE_EQ(back, c.si) << text;
  }
  EXPECT_EQ(format_quantity(0.015081, "mm", Dimension::length), "15.081 mm");
  EXPECT_EQ(format_quantity(2000 * two_pi / 60, "rpm", Dimension::angular_speed), "2000 rpm");
}

TEST(Units, RejectsWhatIsNotAQuantity) {
  EXPECT_THROW(parse_quantity("", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("mm", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("nan mm", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("inf N", Dimension::force, "k"), InputError);
  EXPECT_THROW(parse_quantity("0x10 mm", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("1e999 mm", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("2 furlongs", Dimension::length, "k"), InputError);
  EXPECT_THROW(parse_quantity("2 mm", Dimension::force, "k"), InputError);
  EXPECT_THROW(parse_quantity("2 mm", Dimension::dimensionless, "k"), InputError);
  // Bare numbers: ambiguous for angles and speeds (deg or rad? rpm or rad/s?).
  EXPECT_THROW(parse_quantity("30", Dimension::angle, "k"), InputError);
  EXPECT_THROW(parse_quantity("2000", Dimension::angular_speed, "k"), InputError);
  EXPECT_DOUBLE_EQ(parse_quantity("0", Dimension::angle, "k"), 0.0);
}

TEST(Units, MessagesNameKeyValueAndAllowedUnits) {
  try {
    parse_quantity("2 furlongs", Dimension::length, "bearing.ball_diameter");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bearing.ball_diameter"), std::string::npos) << m;
    EXPECT_NE(m.find("furlongs"), std::string::npos) << m;
    EXPECT_NE(m.find("mm"), std::string::npos) << m;
  }
  try {
    parse_quantity("2000 mm", Dimension::angular_speed, "operation.speed");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unit of length"), std::string::npos) << m;
    EXPECT_NE(m.find("rpm"), std::string::npos) << m;
  }
}

// Sub-multiples divide by an exact power of ten, so a decimal in mm or um gives the double the
// user wrote (10 * 1e-6 would be 9.999999999999999e-06).
TEST(Units, DecimalSubMultiplesAreExact) {
  EXPECT_EQ(parse_quantity("10 um", Dimension::length, "k"), 1e-5);
  EXPECT_EQ(parse_quantity("15.081 mm", Dimension::length, "k"), 0.015081);
  EXPECT_EQ(parse_quantity("14 um", Dimension::length, "k"), 14e-6);
  EXPECT_EQ(parse_quantity("5 us", Dimension::time, "k"), 5e-6);
  EXPECT_EQ(bearing::to_si(0.3, "um", Dimension::length, "k"), 3e-7);
  EXPECT_EQ(parse_quantity("0.05 kN", Dimension::force, "k"), 50.0);
}

// An exponent beyond a long on a zero ("0e99999999999999999999 kN") is zero, not a signed
// overflow in the exponent shift (found by tests/fuzz/ under UBSan).
TEST(Units, HugeExponentsOfZeroAreZero) {
  EXPECT_EQ(parse_quantity("0e99999999999999999999 kN", Dimension::force, "k"), 0.0);
  EXPECT_EQ(parse_quantity("0e-99999999999999999999 mN", Dimension::force, "k"), 0.0);
  EXPECT_EQ(parse_quantity("0.0e400 um", Dimension::length, "k"), 0.0);
  EXPECT_EQ(parse_quantity("1.5e2 kN", Dimension::force, "k"), 150e3);
}

// The lubricant's dimensions (issue 43): viscosity, 1/pressure, temperature (degC an offset unit:
// 80 degC = 353.15 K) and 1/temperature; a bare temperature is refused (K or degC?).
TEST(Units, LubricantDimensions) {
  EXPECT_DOUBLE_EQ(parse_quantity("20 mPa s", Dimension::viscosity, "k"), 0.02);
  EXPECT_DOUBLE_EQ(parse_quantity("0.02 Pa s", Dimension::viscosity, "k"), 0.02);
  EXPECT_DOUBLE_EQ(parse_quantity("20 cP", Dimension::viscosity, "k"), 0.02);
  EXPECT_DOUBLE_EQ(parse_quantity("0.2 P", Dimension::viscosity, "k"), 0.02);
  EXPECT_DOUBLE_EQ(parse_quantity("2e-8 1/Pa", Dimension::inverse_pressure, "k"), 2e-8);
  EXPECT_DOUBLE_EQ(parse_quantity("20 1/GPa", Dimension::inverse_pressure, "k"), 2e-8);
  EXPECT_DOUBLE_EQ(parse_quantity("0.02 mm^2/N", Dimension::inverse_pressure, "k"), 2e-8);
  EXPECT_DOUBLE_EQ(parse_quantity("80 degC", Dimension::temperature, "k"), 353.15);
  EXPECT_DOUBLE_EQ(parse_quantity("-40 degC", Dimension::temperature, "k"), 233.15);
  EXPECT_DOUBLE_EQ(parse_quantity("300 K", Dimension::temperature, "k"), 300.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.03 1/K", Dimension::inverse_temperature, "k"), 0.03);
  try {
    parse_quantity("80", Dimension::temperature, "lubricant.temperature");
    FAIL() << "a bare temperature was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("lubricant.temperature"), std::string::npos) << m;
    EXPECT_NE(m.find("degC"), std::string::npos) << m;
  }
  EXPECT_THROW(parse_quantity("20 mPa", Dimension::viscosity, "k"), InputError);  // a pressure
  EXPECT_THROW(parse_quantity("2e-8 Pa", Dimension::inverse_pressure, "k"), InputError);
  // Written in degC and read back: the kelvin value to its 10 significant digits' rounding.
  const std::string t = format_quantity(353.15, "degC", Dimension::temperature);
  EXPECT_NEAR(parse_quantity(t, Dimension::temperature, "k"), 353.15, 1e-9) << t;
}
