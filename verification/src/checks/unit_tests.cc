// What the project's unit tests establish about the physics, in the report a reviewer reads: each
// physics suite of the GoogleTest programs (tests/lumped, tests/verification's build folder) run
// as a row — the closed forms, convergence orders, conservation laws and reductions those tests
// assert, each with the bound its test source derives. A one-line bug in an equation that a unit
// test catches then fails the report too, not only ctest (issue 30). The rows read no knob of the
// Context: the Context's mutations cannot reach compiled tests, code mutants (mutate --source)
// can. A program that was not built (BEARING_BUILD_TESTS=OFF) makes its rows skipped, with why.

#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../context.h"
#include "../families.h"

namespace bearing::verify {

namespace {

namespace fs = std::filesystem;

struct TestProgram {
  const char* program;  // the GoogleTest program in the build's tests folder
  const char* sources;  // where its tests are written, for the reader
  std::vector<const char*> suites;
};

// The physics suites only: parsing, files, command lines and thread bookkeeping stay in ctest.
const std::vector<TestProgram>& programs() {
  static const std::vector<TestProgram> table = {
      {"core_tests",
       "tests/lumped/test_contact.cc, test_kinematics.cc, test_static_load.cc, test_ehl_film.cc, …",
       {"HertzExact", "HertzMethods", "HertzHarrisTable", "HertzHamrockBrewe", "ContactCurvatures",
        "ContactSteelShortcut", "ContactSeries", "ContactRace", "Calibration", "Kinematics",
        "Traction", "StaticLoad", "LocalDefect", "StructureModes", "EhlFilm", "FilmLaw",
        "Lubricant"}},
      {"solver_tests",
       "tests/lumped/test_integrators.cc, test_events.cc",
       {"IntegratorLinear", "IntegratorHertz", "IntegratorEnergy", "IntegratorStiff",
        "IntegratorDense", "IntegratorCyclic", "IntegratorStability", "IntegratorStepControl",
        "IntegratorOutput", "EventLocation", "StepControl"}},
      {"model_tests",
       "tests/lumped/test_models.cc, test_excitation.cc, …",
       {"ExcitationWaviness", "ExcitationTable", "ExcitationBallErrors", "TwoDof", "ThreeDof",
        "TwoDofPhasor", "BallDofs", "ContactKernels", "CurvatureComplianceTable", "OuterBallMotion",
        "StaticRk4", "FiveDofStatic", "BallPassStiffness", "SupportKernels"}},
      {"dynamics_tests",
       "tests/lumped/test_dynamics.cc, test_ball_dynamics.cc, test_housing*.cc, "
       "test_random_slip.cc, …",
       {"Dynamics", "ExcitationFamilies", "BallDynamics", "CalibratedDynamics", "QuasiStatic",
        "BallMotion", "BallApproach", "Noise", "DefectModels", "DefectRuns", "FaultDiagnosis",
        "ContactLoop", "EventDynamics", "Housing", "HousingModes", "RandomSlip"}},
      {"acoustics_tests",
       "tests/lumped/test_acoustics*.cc",
       {"RealFft", "Sources", "Pressure", "PeriodicInterpolator", "Microphones"}},
      {"signal_tests",
       "tests/lumped/test_signal*.cc, test_prewhitening.cc, …",
       {"SignalStatistics", "SignalSpectrum", "SignalPeaks", "SignalEnvelope", "SpectralKurtosis",
        "Kurtogram", "ComplexFft", "Prewhitening", "SquaredEnvelope", "LineFloor", "CombThreshold",
        "HarmonicComb", "FundamentalEstimate"}},
      {"envelope_tests",
       "tests/lumped/test_envelope_analysis.cc, test_record_analysis.cc, "
       "test_coherence_diagnosis.cc",
       {"FaultFamily", "Diagnosis", "EnvelopeAnalysis", "RecordAnalysis", "CoherenceBands",
        "FamilyTest", "CoherenceDiagnosis"}},
  };
  return table;
}

// "HertzExact" → "hertz-exact": check ids are lower case.
std::string kebab(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isupper(static_cast<unsigned char>(c)) && !out.empty()) out += '-';
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Seconds a suite may run: the slowest takes ~3 s alone; a hundred times that is a hang.
constexpr int kSuiteTimeout = 300;

// Runs `program --gtest_filter=SUITE.*` and returns the failed test count; the detail names them.
Outcome run_suite(const std::string& program, const std::string& suite) {
  const fs::path path = fs::path(BEARING_TEST_PROGRAM_DIR) / program;
  if (!fs::exists(path))
    throw Skipped(path.string() + " was not built (BEARING_BUILD_TESTS=OFF or not yet built)");
  const fs::path json = fs::temp_directory_path() / ("bearing-verify-" + std::to_string(getpid()) +
                                                     "-" + program + "-" + suite + ".json");
  // coreutils' timeout: a suite that hangs (an integrator that never reaches the end, say) fails
  // its row after kSuiteTimeout instead of stopping the report.
  const std::string command = "timeout --kill-after=10 " + std::to_string(kSuiteTimeout) + " " +
                              quoted(path.string()) + " --gtest_filter=" + quoted(suite + ".*") +
                              " --gtest_output=json:" + quoted(json.string()) + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  nlohmann::json report;
  {
    std::ifstream in(json);
    if (!in && (code == 124 || code == 137))
      throw std::runtime_error(program + " --gtest_filter=" + suite + ".*: timed out after " +
                               std::to_string(kSuiteTimeout) + " s");
    if (!in)
      throw std::runtime_error(program + " wrote no result (exit status " + std::to_string(code) +
                               "): it crashed or was killed");
    in >> report;
  }
  fs::remove(json);
  const int tests = report.value("tests", 0);
  if (tests == 0) throw std::runtime_error(program + ": no test in suite " + suite);
  int failed = 0;
  std::string names;
  for (const auto& s : report["testsuites"])
    for (const auto& t : s["testsuite"])
      if (t.contains("failures")) {
        ++failed;
        names += (names.empty() ? "" : ", ") + t.value("name", std::string("?"));
      }
  return {static_cast<double>(failed),
          0.0,
          std::to_string(tests - failed) + " of " + std::to_string(tests) + " tests passed" +
              (failed ? "; failed: " + names : std::string()),
          {}};
}

}  // namespace

std::vector<Check> unit_test_checks() {
  std::vector<Check> out;
  for (const TestProgram& p : programs())
    for (const char* suite : p.suites) {
      Check c;
      const std::string program = p.program;
      c.id = "unit." + program.substr(0, program.size() - 6) + "." + kebab(suite);
      c.family = "unit";
      c.reference = ReferenceKind::unit_test;
      c.compares = "value: failed tests of `" + program + " --gtest_filter=" + suite + ".*` (" +
                   p.sources +
                   "; each test asserts a closed form, an order, a "
                   "conservation law or a reduction with the bound its source derives); "
                   "reference: 0";
      c.quantity = "failed tests";
      c.unit = "-";
      c.tolerance = absolute(0,
                             "every test of the suite must pass: each carries its own derived "
                             "bound, written beside its assertion");
      c.level = Level::quick;
      c.cost = 0.3;
      c.measure = [program, s = std::string(suite)](const Context&) {
        return run_suite(program, s);
      };
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace bearing::verify
