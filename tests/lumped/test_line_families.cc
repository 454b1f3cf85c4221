// Lines named by the physics that makes them (issue 28): excitation_families() turns on exactly the
// families each excitation of a case makes, and a run's peaks carry names from those families only.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/excitation_families.h"
#include "bearing/simulation.h"

namespace bearing {
namespace {

using Names = std::vector<std::string>;

Names families_of(ModelKind kind, const ModelInputs& in) {
  return line_family_names(excitation_families(kind, in));
}

// --- the families of each excitation ----------------------------------------------------------

TEST(ExcitationFamilies, IdenticalBallsMakeBallPassLinesOnly) {
  const ModelInputs perfect;
  EXPECT_EQ(families_of(ModelKind::two_dof, perfect), (Names{"BPFO", "BPFO/m"}));
  EXPECT_EQ(families_of(ModelKind::three_dof, perfect), (Names{"BPFO", "BPFO/m"}));
  // A quasi-static equilibrium follows the ball set's angle: it repeats every ball pass.
  EXPECT_EQ(families_of(ModelKind::quasi_static, perfect), (Names{"BPFO"}));
  // Each ball's own DOFs (spin, slip, radial motion) let the balls differ.
  EXPECT_EQ(families_of(ModelKind::balls, perfect), (Names{"FTF", "BPFO", "BPFO/m"}));
}

TEST(ExcitationFamilies, EachExcitationTurnsOnItsOwnFamilies) {
  const auto with = [](auto change) {
    ModelInputs in;
    change(in);
    return families_of(ModelKind::two_dof, in);
  };
  const Names base = {"BPFO", "BPFO/m"};
  EXPECT_EQ(with([](ModelInputs& in) {
              in.ball_size_errors = {0, 1e-6, -1e-6};
            }),
            (Names{"FTF", "BPFO", "BPFO/m"}));
  EXPECT_EQ(with([](ModelInputs& in) {
              in.defects = {{DefectLocation::ball, 0, 2, 1e-3, 1e-5}};
            }),
            (Names{"FTF", "BPFO", "BPFO/m", "BSF"}));
  EXPECT_EQ(with([](ModelInputs& in) {
              in.inner_waviness.harmonics = {{9, 0.5e-6, 0}};
            }),
            (Names{"fr", "BPFO", "BPFO/m", "BPFI"}));
  EXPECT_EQ(with([](ModelInputs& in) {
              in.defects = {{DefectLocation::inner, 0, 0, 1e-3, 1e-5}};
            }),
            (Names{"fr", "BPFO", "BPFO/m", "BPFI"}));
  EXPECT_EQ(with([](ModelInputs& in) { in.unbalance = 1e-5; }), (Names{"fr", "BPFO", "BPFO/m"}));
  // The outer race is fixed: its waviness and spalls meet the balls at the ball pass.
  EXPECT_EQ(with([](ModelInputs& in) { in.outer_waviness.harmonics = {{9, 0.5e-6, 0}}; }), base);
  EXPECT_EQ(with([](ModelInputs& in) {
              in.defects = {{DefectLocation::outer, 0, 0, 1e-3, 1e-5}};
            }),
            base);
  // An excitation of size zero makes no line.
  EXPECT_EQ(with([](ModelInputs& in) { in.ball_size_errors = {0, 0, 0}; }), base);
  EXPECT_EQ(with([](ModelInputs& in) { in.inner_waviness.harmonics = {{9, 0, 0}}; }), base);
}

TEST(ExcitationFamilies, RunSettingsTakeThemFromTheCase) {
  const auto families = [](std::vector<std::string> sets) {
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    return line_family_names(run_settings(default_case(o)).analysis.lines);
  };
  EXPECT_EQ(families({}), (Names{"BPFO", "BPFO/m"}));
  EXPECT_EQ(families({"ball_errors.band=2um", "ball_errors.seed=1"}),
            (Names{"FTF", "BPFO", "BPFO/m"}));
  EXPECT_EQ(families({"operation.unbalance=1e-5"}), (Names{"fr", "BPFO", "BPFO/m"}));
  EXPECT_EQ(families({"model.kind=balls"}), (Names{"FTF", "BPFO", "BPFO/m"}));
  // A signal whose excitations are unknown is named by every family.
  EXPECT_EQ(line_family_names(AnalysisSettings{}.lines), line_family_names(LineFamilies::all()));
}

// --- the names of a run's peaks -----------------------------------------------------------------

// A case with overrides ("key=value", as --set takes them) on `file` (empty: the default case).
Case case_of(const std::string& file, const std::vector<std::string>& sets) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return file.empty() ? default_case(o)
                      : read_case_file(std::string(BEARING_SOURCE_DIR) + "/" + file, o);
}

struct RunOutput {
  SimulationResult result;
  RunSummary summary;
  double bin = 0;  ///< the spectra's resolution [Hz]
};

RunOutput run(const Case& c) {
  RunOutput r;
  r.result = simulate(c);
  r.summary = summarize(c, r.result);
  r.bin = r.summary.spectra.at(0).resolution;
  return r;
}

// The name of (j/m)·BPFO in lowest terms, as a raw spectrum's peaks spell it: "BPFO", "3xBPFO",
// "5/2xBPFO", "4/3xBPFO".
std::string ball_pass_name(int j, int m) {
  const int g = std::gcd(j, m);
  j /= g, m /= g;
  if (m == 1) return j == 1 ? "BPFO" : std::to_string(j) + "xBPFO";
  return std::to_string(j) + "/" + std::to_string(m) + "xBPFO";
}

// A response that repeats every m ball passes has its lines at (j/m)·BPFO: every listed peak of
// the ring's displacement and acceleration must lie there within a bin (what the physics says,
// independent of the naming) and carry that name, with label_error its offset from it.
void expect_period_of_ball_passes(const RunOutput& r, int m, const char* what) {
  const double bpfo = r.result.frequencies.bpfo;
  for (const ChannelSummary& ch : r.summary.channels) {
    if (ch.name != "x" && ch.name != "y" && ch.name != "ax" && ch.name != "ay") continue;
    ASSERT_FALSE(ch.peaks.empty()) << what << " " << ch.name;
    for (const Peak& p : ch.peaks) {
      const int j = static_cast<int>(std::lround(p.frequency * m / bpfo));
      const double line = j * bpfo / m;
      ASSERT_LE(std::abs(p.frequency - line), 0.2 * r.bin)
          << what << " " << ch.name << ": " << p.frequency << " Hz is not a line (j/" << m
          << ")·BPFO";
      EXPECT_EQ(p.label, ball_pass_name(j, m)) << what << " " << ch.name << " " << p.frequency;
      EXPECT_NEAR(p.label_error, p.frequency - line, 1e-9 * bpfo) << what << " " << p.label;
    }
  }
}

bool has_peak_with(const RunSummary& s, const std::string& part) {
  for (const ChannelSummary& ch : s.channels)
    for (const Peak& p : ch.peaks)
      if (p.label.find(part) != std::string::npos) return true;
  return false;
}

// The README's picture: the default 6308 (2000 rpm, P_d 14 µm, 20 N) rattles in a period-2 orbit,
// lines at (k + ½)·BPFO between the BPFO harmonics. Its identical balls have no cage-periodic
// source: the half orders are 1/2xBPFO, 3/2xBPFO, …, never 4xFTF, 12xFTF, … (as Z = 8 made them
// before the names followed the case).
TEST(RunPeakNames, TheDefaultRunIsPeriodTwoAndHasNoCageName) {
  const RunOutput r = run(default_case());
  expect_period_of_ball_passes(r, 2, "default");
  EXPECT_TRUE(has_peak_with(r.summary, "/2xBPFO"));  // the half orders are among the largest
  EXPECT_FALSE(has_peak_with(r.summary, "FTF"));
}

// A healthy 6308 at 3000 rpm with 10 µm clearance (the README's second run) is period 2 too; the
// light-load 6308 at 4000 rpm, P_d 20 µm, 30 N is period 3, at 6000 rpm, 30 µm, 100 N period 4.
// Each is named by the ball pass alone.
TEST(RunPeakNames, SubharmonicRoutesAreNamedByTheBallPass) {
  expect_period_of_ball_passes(
      run(case_of("", {"operation.speed=3000 rpm", "bearing.clearance=10um"})), 2, "3000 rpm");
  expect_period_of_ball_passes(run(case_of("examples/seed003_6308.toml",
                                           {"operation.speed=3000 rpm", "bearing.clearance=10um"})),
                               2, "seed003_6308 at 3000 rpm");
  expect_period_of_ball_passes(
      run(case_of("", {"operation.speed=4000 rpm", "bearing.clearance=20um",
                       "operation.load=[\"0 N\", \"-30 N\"]"})),
      3, "period 3");
  expect_period_of_ball_passes(
      run(case_of("", {"operation.speed=6000 rpm", "bearing.clearance=30um",
                       "operation.load=[\"0 N\", \"-100 N\"]"})),
      4, "period 4");
}

// Seed 000's 608 (Z = 7): with ball-size errors (band 2 µm, seed 1) the balls differ and the ring
// moves at the cage rate, k·FTF with k no multiple of 7 (no ball-pass line): named so, and the
// largest line of x and of y. The same bearing with identical balls has no FTF name.
TEST(RunPeakNames, BallSizeErrorsBringCageLines) {
  const RunOutput r =
      run(case_of("examples/seed000_608.toml", {"ball_errors.band=2um", "ball_errors.seed=1"}));
  const double ftf = r.result.frequencies.ftf;
  const auto cage_line = [&](const Peak& p) {
    const long k = std::lround(p.frequency / ftf);
    return k % 7 != 0 && std::abs(p.frequency - k * ftf) <= 0.2 * r.bin ? k : 0L;
  };
  for (const ChannelSummary& ch : r.summary.channels) {
    if (ch.name != "x" && ch.name != "y") continue;
    ASSERT_FALSE(ch.peaks.empty());
    EXPECT_NE(cage_line(ch.peaks.front()), 0) << ch.name << " " << ch.peaks.front().frequency;
    for (const Peak& p : ch.peaks)
      if (const long k = cage_line(p)) {
        EXPECT_EQ(p.label, (k == 1 ? std::string() : std::to_string(k) + "x") + "FTF")
            << ch.name << " " << p.frequency;
        EXPECT_NEAR(p.label_error, p.frequency - k * ftf, 1e-9 * ftf);
      }
  }
  EXPECT_FALSE(has_peak_with(run(case_of("examples/seed000_608.toml", {})).summary, "FTF"));
}

// Unbalance turns with the shaft: lines at f_r and, where the rotating load meets the compliance
// varying at the ball pass, at k·BPFO ± f_r; still nothing at the cage rate or the inner race's.
TEST(RunPeakNames, UnbalanceBringsShaftLines) {
  Case c = case_of("", {"operation.unbalance=1e-5"});
  c.output.peaks = 25;
  const RunOutput r = run(c);
  const double fr = r.result.frequencies.shaft, bpfo = r.result.frequencies.bpfo;
  bool shaft = false, sideband = false;
  for (const ChannelSummary& ch : r.summary.channels)
    for (const Peak& p : ch.peaks) {
      EXPECT_EQ(p.label.find("FTF"), std::string::npos) << p.label;
      EXPECT_EQ(p.label.find("BPFI"), std::string::npos) << p.label;
      shaft = shaft || (p.label == "fr" && std::abs(p.frequency - fr) <= 0.2 * r.bin);
      const long k = std::lround((p.frequency + fr) / bpfo);  // a lower sideband k·BPFO − f_r
      if (std::abs(p.frequency - (k * bpfo - fr)) <= 0.2 * r.bin) {
        EXPECT_EQ(p.label, (k == 1 ? std::string() : std::to_string(k) + "x") + "BPFO-fr");
        sideband = true;
      }
    }
  EXPECT_TRUE(shaft);
  EXPECT_TRUE(sideband);
}

}  // namespace
}  // namespace bearing
