// The line families that name a raw spectrum's peaks (line_names.h): each family switches on its
// own names only, the ball pass has subharmonics k/m·BPFO in lowest terms, and a line two families
// share goes to the lower order.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/line_names.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"

namespace bearing {
namespace {

// The default 6308 at 2000 rpm [Hz]: Z = 8, so 8·FTF = BPFO exactly.
constexpr double kFr = 2000.0 / 60, kBpfo = 102.398, kFtf = kBpfo / 8, kBpfi = 164.269,
                 kBsf = 67.967;

std::vector<NamedFrequency> names(const LineFamilies& families, double band = 2000) {
  return bearing_frequency_names_up_to(band, kFr, kFtf, kBpfo, kBpfi, kBsf, families);
}

// The family a label of bearing_frequency_names_up_to() is of, read from its spelling.
std::string family_of(const std::string& label) {
  if (label.find('/') != std::string::npos) return "BPFO/m";
  if (label.find("BPFO-") != std::string::npos || label.find("BPFO+") != std::string::npos)
    return "fr";  // the ball pass's shaft sidebands: shaft and outer
  if (label.find("BPFI") != std::string::npos) return "BPFI";  // with its ±fr sidebands
  for (const char* base : {"BPFO", "FTF", "BSF", "fr"})
    if (label.size() >= std::string(base).size() &&
        label.compare(label.size() - std::string(base).size(), std::string::npos, base) == 0)
      return base;
  return "?";
}

TEST(LineNames, EachFamilyNamesItsOwnLinesOnly) {
  EXPECT_TRUE(names(LineFamilies{}).empty());
  const struct {
    bool LineFamilies::*flag;
    const char* family;
  } families[] = {{&LineFamilies::shaft, "fr"},   {&LineFamilies::cage, "FTF"},
                  {&LineFamilies::outer, "BPFO"}, {&LineFamilies::outer_subharmonics, "BPFO/m"},
                  {&LineFamilies::inner, "BPFI"}, {&LineFamilies::spin, "BSF"}};
  std::size_t total = 0;
  for (const auto& f : families) {
    LineFamilies one;
    one.*f.flag = true;
    const auto list = names(one);
    EXPECT_FALSE(list.empty()) << f.family;
    for (const NamedFrequency& n : list) EXPECT_EQ(family_of(n.label), f.family) << n.label;
    EXPECT_EQ(line_family_names(one), std::vector<std::string>{f.family});
    total += list.size();
  }
  // all() is the union and the ball pass's shaft sidebands, each name once.
  const auto all = names(LineFamilies::all());
  std::set<std::string> labels;
  std::size_t sidebands = 0;
  for (const NamedFrequency& n : all) {
    EXPECT_TRUE(labels.insert(n.label).second) << n.label;
    sidebands +=
        n.label.find("BPFO-") != std::string::npos || n.label.find("BPFO+") != std::string::npos;
  }
  EXPECT_EQ(all.size(), total + sidebands);
  EXPECT_EQ(line_family_names(LineFamilies::all()),
            (std::vector<std::string>{"fr", "FTF", "BPFO", "BPFO/m", "BPFI", "BSF"}));
  // Frequencies are checked whether or not their family is asked for.
  EXPECT_THROW(bearing_frequency_names_up_to(2000, kFr, -1, kBpfo, kBpfi, kBsf, LineFamilies{}),
               InputError);
}

TEST(LineNames, ALoadTurningWithTheShaftModulatesTheBallPass) {
  LineFamilies shaft_and_outer;
  shaft_and_outer.shaft = shaft_and_outer.outer = true;
  const double band = 3.2 * kBpfo;
  std::vector<NamedFrequency> sidebands;
  for (const NamedFrequency& n : names(shaft_and_outer, band))
    if (n.label.find("BPFO-") != std::string::npos || n.label.find("BPFO+") != std::string::npos)
      sidebands.push_back(n);
  // k·BPFO ± f_r for k = 1, 2, 3, the lower sideband first, after every plain harmonic.
  const std::vector<std::string> expected = {"BPFO-fr",   "BPFO+fr",   "2xBPFO-fr",
                                             "2xBPFO+fr", "3xBPFO-fr", "3xBPFO+fr"};
  ASSERT_EQ(sidebands.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const int k = static_cast<int>(i / 2) + 1;
    EXPECT_EQ(sidebands[i].label, expected[i]);
    EXPECT_DOUBLE_EQ(sidebands[i].frequency, k * kBpfo + (i % 2 ? kFr : -kFr)) << expected[i];
    EXPECT_EQ(sidebands[i].harmonic, k);
  }
  EXPECT_EQ(names(shaft_and_outer, band).back().label, "3xBPFO+fr");
}

TEST(LineNames, SubharmonicsOfTheBallPassAreInLowestTermsAndNeverWhole) {
  LineFamilies sub;
  sub.outer_subharmonics = true;
  const double band = 3.2 * kBpfo;
  const auto list = names(sub, band);
  // By m, then k: k/2 (k odd), k/3 (k not a multiple of 3), k/4 (k odd), each k/m·BPFO ≤ band.
  std::vector<std::string> expected;
  for (int m : {2, 3, 4})
    for (int k = 1; k <= 3.2 * m; ++k)
      if (k % m != 0 && !(m == 4 && k % 2 == 0))
        expected.push_back(std::to_string(k) + "/" + std::to_string(m) + "xBPFO");
  ASSERT_EQ(list.size(), expected.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_EQ(list[i].label, expected[i]) << i;
    EXPECT_DOUBLE_EQ(list[i].frequency,
                     static_cast<double>(list[i].harmonic) * kBpfo / list[i].subharmonic)
        << list[i].label;
    EXPECT_LE(list[i].frequency, band);
    // No subharmonic coincides with a harmonic or with another subharmonic.
    EXPECT_GT(std::abs(list[i].frequency / kBpfo - std::round(list[i].frequency / kBpfo)), 0.2);
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GT(std::abs(list[i].frequency - list[j].frequency), 0.08 * kBpfo)
          << list[i].label << " " << list[j].label;
  }
  EXPECT_EQ(list.front().harmonic, 1);
  EXPECT_EQ(list.front().subharmonic, 2);
}

// 4 s at 20 kHz (0.25 Hz bins) of unit sines at `fs` [Hz].
Spectrum tones(const std::vector<double>& fs) {
  std::vector<double> x(80000, 0.0);
  for (double f : fs)
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] += std::sin(two_pi * f * static_cast<double>(i) / 20000 + 0.4);
  return amplitude_spectrum(x, 20000, Window::hann);
}

TEST(LineNames, APeakIsNamedOnlyAfterTheFamiliesAskedFor) {
  // A period-2 response of identical balls: lines at BPFO/2, 5/2·BPFO and 2·BPFO. With Z = 8 the
  // half orders are FTF harmonics too (4·FTF, 20·FTF): every family offers both names, the lower
  // order wins; the case's families (outer only) offer no FTF name at all.
  const Spectrum s = tones({0.5 * kBpfo, 2.5 * kBpfo, 2 * kBpfo});
  const auto labels = [&s](const LineFamilies& families) {
    std::set<std::string> out;
    for (const Peak& p : find_peaks(s, names(families), 3)) out.insert(p.label);
    return out;
  };
  LineFamilies outer;
  outer.outer = outer.outer_subharmonics = true;
  const std::set<std::string> expected = {"1/2xBPFO", "5/2xBPFO", "2xBPFO"};
  EXPECT_EQ(labels(outer), expected);
  EXPECT_EQ(labels(LineFamilies::all()), expected);
  // Without the subharmonics the half orders are FTF harmonics (ball-size errors) or nothing.
  LineFamilies balls = outer;
  balls.outer_subharmonics = false;
  balls.cage = true;
  EXPECT_EQ(labels(balls), (std::set<std::string>{"4xFTF", "20xFTF", "2xBPFO"}));
  outer.outer_subharmonics = false;
  EXPECT_EQ(labels(outer), (std::set<std::string>{"", "2xBPFO"}));
}

}  // namespace
}  // namespace bearing
