// The names of a local fault's envelope lines: the plain bearing families, the inner race's second
// shaft sidebands and the ball's cage sidebands; the nearest name wins, a tie the lower harmonic.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"

namespace bearing {
namespace {

// 4 s at 20 kHz (0.25 Hz bins) of a unit sine at f [Hz].
std::vector<double> tone(double f) {
  std::vector<double> x(80000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(two_pi * f * i / 20000 + 0.4);
  return x;
}

TEST(FaultNames, AddSecondShaftSidebandsAndBallCageSidebands) {
  const double fr = 25, ftf = 10, bpfo = 89.5, bpfi = 135.5, bsf = 59;
  const auto names = fault_frequency_names_up_to(300, fr, ftf, bpfo, bpfi, bsf);
  // They begin with a raw spectrum's names of every family up to the band but the ball pass's
  // shaft sidebands and subharmonics (a spall strikes at whole multiples of its own rate).
  std::vector<std::string> plain;
  for (const auto& n :
       bearing_frequency_names_up_to(300, fr, ftf, bpfo, bpfi, bsf, LineFamilies::all()))
    if (n.label.find('/') == std::string::npos && n.label.find("BPFO-") == std::string::npos &&
        n.label.find("BPFO+") == std::string::npos)
      plain.push_back(n.label);
  ASSERT_GT(names.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) EXPECT_EQ(names[i].label, plain[i]) << i;
  for (const auto& n : names) EXPECT_EQ(n.label.find("BPFO+"), std::string::npos) << n.label;
  const auto find = [&](const std::string& label) -> const NamedFrequency* {
    for (const auto& n : names)
      if (n.label == label) return &n;
    return nullptr;
  };
  struct Expected {
    const char* label;
    double frequency;
    int harmonic;
  };
  for (const Expected& e :
       {Expected{"BPFI-2fr", bpfi - 2 * fr, 1}, Expected{"2xBPFI+2fr", 2 * bpfi + 2 * fr, 2},
        Expected{"BPFI+fr", bpfi + fr, 1}, Expected{"2xBSF", 2 * bsf, 2},
        Expected{"2xBSF-FTF", 2 * bsf - ftf, 2}, Expected{"2xBSF+2FTF", 2 * bsf + 2 * ftf, 2},
        Expected{"4xBSF+FTF", 4 * bsf + ftf, 4}, Expected{"4xBSF-2FTF", 4 * bsf - 2 * ftf, 4}}) {
    const NamedFrequency* n = find(e.label);
    ASSERT_NE(n, nullptr) << e.label;
    EXPECT_DOUBLE_EQ(n->frequency, e.frequency) << e.label;
    EXPECT_EQ(n->harmonic, e.harmonic) << e.label;
  }
  // Ball sidebands only on even harmonics of BSF, each name once.
  EXPECT_EQ(find("BSF+FTF"), nullptr);
  EXPECT_EQ(find("3xBSF-FTF"), nullptr);
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j) EXPECT_NE(names[i].label, names[j].label);
  EXPECT_THROW(fault_frequency_names_up_to(0, fr, ftf, bpfo, bpfi, bsf), InputError);
  EXPECT_THROW(fault_frequency_names_up_to(300, fr, -1, bpfo, bpfi, bsf), InputError);
}

// Envelope lines of a ball fault and of an inner-race fault get their own names: the nearest wins,
// a tie the lower harmonic.
TEST(FaultNames, LabelEnvelopeLinesOfBallAndInnerRaceFaults) {
  // The default 6308 at 2000 rpm (Z = 8: 8·FTF = BPFO exactly, so 3·BPFO is 24·FTF too).
  const double fr = 2000.0 / 60, bpfo = 102.398, ftf = bpfo / 8, bpfi = 164.269, bsf = 67.967;
  const auto names = fault_frequency_names_up_to(10000, fr, ftf, bpfo, bpfi, bsf);
  const auto label_of = [&](double f) {
    const Spectrum s = amplitude_spectrum(tone(f), 20000, Window::hann);  // 0.25 Hz
    return find_peaks(s, names, 1).at(0).label;
  };
  EXPECT_EQ(label_of(2 * bsf - ftf), "2xBSF-FTF");
  EXPECT_EQ(label_of(2 * bsf + 2 * ftf), "2xBSF+2FTF");
  EXPECT_EQ(label_of(4 * bsf), "4xBSF");
  EXPECT_EQ(label_of(bpfi + 2 * fr), "BPFI+2fr");
  EXPECT_EQ(label_of(2 * bpfi - fr), "2xBPFI-fr");
  EXPECT_EQ(label_of(3 * bpfo), "3xBPFO");
}

}  // namespace
}  // namespace bearing
