// The modes file of `bearing-fem modes` read back (structure_modes.h): what it keeps, and every
// fault refused with the key, the value and what is allowed.

#include <string>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "bearing/structure_modes.h"

namespace bearing {
namespace {

// A valid file: 3 modes, one sensor.
std::string modes_text(const std::string& frequencies = "[1200.5, 3400, 3400]",
                       const std::string& sensors =
                           "[{\"name\": \"top\", \"point\": [0, 0.06, 0], \"x\": [0.1, 0.2, "
                           "0.3], \"y\": [-0.1, 0, 1e-3], \"z\": [0, 0, 0]}]",
                       const std::string& boundary = "{\"free\": false, \"fixed\": [\"bolts\"]}") {
  return "{\"format\": \"bearing-fem modes\", \"version\": 1, \"boundary\": " + boundary +
         ", \"frequencies\": " + frequencies +
         ", \"seat\": {\"x\": [0.5, 0, -0.25], \"y\": [0, 0.5, 0.125], \"z\": [0, 0, 0.01], "
         "\"tilt_x\": [0, 0, 0]}, \"sensors\": " +
         sensors + ", \"units\": {\"frequency\": \"Hz\", \"shape\": \"kg^-1/2\"}}";
}

std::string refusal(const std::string& text) {
  try {
    parse_structure_modes(text, "/x/modes.json", "housing.modes = \"modes.json\"");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StructureModes, ReadsWhatTheModelUses) {
  const StructureModes m =
      parse_structure_modes(modes_text(), "/x/modes.json", "housing.modes = \"modes.json\"");
  EXPECT_EQ(m.path, "/x/modes.json");
  EXPECT_FALSE(m.free);
  ASSERT_EQ(m.count(), 3);
  EXPECT_EQ(m.frequencies[0], 1200.5);
  EXPECT_EQ(m.seat[0][2], -0.25);
  EXPECT_EQ(m.seat[1][2], 0.125);
  EXPECT_EQ(m.seat[2][2], 0.01);
  ASSERT_EQ(m.sensors.size(), 1u);
  EXPECT_EQ(m.sensors[0].name, "top");
  EXPECT_EQ(m.sensors[0].point[1], 0.06);
  EXPECT_EQ(m.sensors[0].shape[1][2], 1e-3);
  EXPECT_NE(m.sensor("top"), nullptr);
  EXPECT_EQ(m.sensor("bottom"), nullptr);
  // No sensors at all is a valid file (the run then writes none).
  EXPECT_TRUE(parse_structure_modes(modes_text("[1, 2, 3]", "[]"), "", "m").sensors.empty());
}

TEST(StructureModes, RefusesWhatItCannotUse) {
  const auto has = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };
  EXPECT_TRUE(has(refusal("[1, 2]"), "expected a JSON object"));
  EXPECT_TRUE(has(refusal("{\"format\": \"bearing-fem calibration 1\"}"),
                  "format = \"bearing-fem calibration 1\": expected \"bearing-fem modes\""));
  EXPECT_TRUE(has(refusal("{\"format\": \"bearing-fem modes\", \"version\": 2}"),
                  "version = 2: this program reads version 1"));
  EXPECT_TRUE(has(refusal(modes_text("[]")), "frequencies has 0 entries: expected 1 to 500"));
  EXPECT_TRUE(has(refusal(modes_text("[3400, 1200, 5000]")),
                  "frequencies[1] = 1200 Hz: below frequencies[0] = 3400 Hz"));
  EXPECT_TRUE(
      has(refusal(modes_text("[0, 1200, 5000]")), "frequencies[0] = 0 Hz: must be positive"));
  EXPECT_TRUE(
      has(refusal(modes_text("[1, 2, \"3\"]")), "frequencies[2] = \"3\": expected a number"));
  EXPECT_TRUE(has(refusal(modes_text("[1, 2]")), "seat.x has 3 entries: expected 2"));
  EXPECT_TRUE(has(refusal(modes_text("[1, 2, 3]",
                                     "[{\"name\": \"a b\", \"point\": [0, 0, 0], "
                                     "\"x\": [0, 0, 0], \"y\": [0, 0, 0], \"z\": [0, "
                                     "0, 0]}]")),
                  "sensors[0].name = \"a b\": a sensor's name is 1 to 64 letters"));
  const std::string twice =
      "[{\"name\": \"a\", \"point\": [0, 0, 0], \"x\": [0, 0, 0], \"y\": [0, 0, 0], \"z\": [0, 0, "
      "0]}, {\"name\": \"a\", \"point\": [0, 0, 0], \"x\": [0, 0, 0], \"y\": [0, 0, 0], \"z\": "
      "[0, 0, 0]}]";
  EXPECT_TRUE(has(refusal(modes_text("[1, 2, 3]", twice)), "two sensors have this name"));
  EXPECT_TRUE(has(refusal(modes_text("[1, 2, 3]",
                                     "[{\"name\": \"a\", \"point\": [0, 0], \"x\": "
                                     "[0, 0, 0], \"y\": [0, 0, 0], \"z\": [0, 0, 0]}]")),
                  "sensors[0].point has 2 entries: expected 3"));
  EXPECT_TRUE(has(refusal(modes_text("[1, 2, 3]", "[]", "{}")), "boundary.free = (missing)"));
  EXPECT_TRUE(has(refusal(modes_text("[1, 2, 3]", "[]", "{\"free\": 0}")),
                  "boundary.free = 0: expected true or false"));
  std::string mm = modes_text();
  mm.replace(mm.find("\"kg^-1/2\""), 9, "\"mm/kg\"");
  EXPECT_TRUE(has(refusal(mm), "units.shape = \"mm/kg\": expected \"kg^-1/2\""));
  std::string huge = modes_text();
  huge.replace(huge.find("1200.5"), 6, "1e999");
  EXPECT_TRUE(has(refusal(huge), "frequencies: "));
  EXPECT_TRUE(has(refusal(std::string(100, '[')), "nested deeper than 64 levels"));
  EXPECT_TRUE(has(refusal("{\"format\": "), "not valid JSON"));
}

TEST(StructureModes, UnreadableFileNamesIt) {
  try {
    read_structure_modes("/nonexistent/modes.json", "housing.modes = \"x\"");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("housing.modes = \"x\": cannot read /nonexistent/modes.json"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace bearing
