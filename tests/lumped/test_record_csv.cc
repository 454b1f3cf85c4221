// CSV records (csv_record.h) from text written here: the header's names and units, the time
// column as the rate, the delimiters and the conventions of spreadsheets and numpy.savetxt, and
// the errors naming file, channel, line and column. Python's csv module writing a file that the
// reader reads back bit for bit: tests/records/check_readers.py.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bearing/errors.h"
#include "bearing/records/csv_record.h"

namespace bearing {
namespace {

template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

RawChannel csv(const std::string& text, const std::string& channel = "") {
  RecordOptions o;
  o.channel = channel;
  return parse_csv_record(text, "r.csv", o);
}

TEST(CsvRecord, HeaderNamesUnitsAndTheTimeColumn) {
  const RawChannel r = csv("t,DE [g],FE (m/s^2)\n0,1.5,2\n0.001,-2.5,3\n0.002,0.125,4\n", "DE");
  EXPECT_EQ(r.channel, "DE");
  EXPECT_EQ(r.values, (std::vector<double>{1.5, -2.5, 0.125}));
  ASSERT_TRUE(r.unit.has_value());
  EXPECT_EQ(*r.unit, "g");
  EXPECT_EQ(r.unit_origin, "the header of column DE");
  ASSERT_TRUE(r.rate.has_value());
  EXPECT_DOUBLE_EQ(*r.rate, 1000.0);
  EXPECT_EQ(r.rate_origin, "time column t");
  EXPECT_EQ(*csv("time [s],FE (m/s^2)\n0,2\n0.5,3\n", "FE").unit, "m/s^2");
}

TEST(CsvRecord, DelimitersQuotesBomCrlfCommentsAndSavetxtHeaders) {
  const std::vector<double> expected{1, 2};
  EXPECT_EQ(csv("\xEF\xBB\xBF\"Accel, DE\";x\r\n1;9\r\n\r\n2;9\r\n", "Accel, DE").values, expected);
  EXPECT_EQ(csv("a\tb\n1\t0\n2\t0\n", "a").values, expected);
  // numpy.savetxt: space-delimited, its header a comment right before the data.
  EXPECT_EQ(csv("# a b\n1.000000000000000000e+00 0\n2.000000000000000000e+00 0\n", "a").values,
            expected);
  // Other comment lines are skipped; a space-delimited header may carry a bracketed unit.
  const RawChannel spaced = csv("# logger 7\nDE [g]\n1\n# pause\n2\n");
  EXPECT_EQ(spaced.values, expected);
  EXPECT_EQ(*spaced.unit, "g");
  // Without a header, columns are numbered from 0 and there is no time column.
  const RawChannel bare = csv("5,1\n6,2\n", "1");
  EXPECT_EQ(bare.values, expected);
  EXPECT_EQ(bare.channel, "1");
  EXPECT_FALSE(bare.rate.has_value());
  EXPECT_EQ(csv("+1\n2e0\n").values, expected);
}

TEST(CsvRecord, ErrorsNameFileChannelLineAndColumn) {
  EXPECT_EQ(input_error([] { csv("t,DE\n0,1\n0.001,nan\n"); }),
            "r.csv: channel DE: line 3, column DE: \"nan\" is not a finite number");
  EXPECT_EQ(input_error([] { csv("t,DE\n0,1\n0.001,1,\n"); }),
            "r.csv: channel DE: line 3 has 3 fields, the header 2");
  EXPECT_EQ(input_error([] { csv("t,DE\n0,1\n,2\n"); }),
            "r.csv: channel DE: line 3, column t: \"\" is not a finite number");
  EXPECT_EQ(input_error([] { csv("t,DE,FE\n0,1,2\n"); }),
            "r.csv: 2 columns (DE, FE): choose one with --channel");
  EXPECT_EQ(input_error([] { csv("t,DE\n0,1\n", "XX"); }),
            "r.csv: channel XX: no such column; the file has DE");
  EXPECT_EQ(input_error([] { csv("time [ms],DE\n0,1\n"); }),
            "r.csv: time column time is in ms: it must be in s");
  EXPECT_EQ(input_error([] { csv("t,DE,DE\n0,1,1\n"); }),
            "r.csv: two columns of the header are named DE");
  EXPECT_EQ(input_error([] { csv(""); }), "r.csv: no samples: the file has no data line");
  EXPECT_NE(input_error([] {
              csv("t,DE\n0.000000,1\n0.001000,1\n0.002500,1\n0.003000,1\n");
            }).find("r.csv: channel DE: time column t: not uniform at sample 2 (from 0)"),
            std::string::npos);
  // A header and no data: no samples (finish_record says so); not an error of the parser.
  EXPECT_TRUE(csv("DE\n").values.empty());
}

}  // namespace
}  // namespace bearing
