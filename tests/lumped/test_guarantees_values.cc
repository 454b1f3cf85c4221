// Issue 21, item 3, the values: every model kind gives byte-identical files run after run, across
// `sweep --jobs 1/2` and when `run DIR/case.toml` repeats a run; no NaN or Inf in any file of any
// example case, nor of 200 random valid cases (fixed seed) drawn within the documented ranges.

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <random>

#include <gtest/gtest.h>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/contact_loop.h"
#include "bearing/limits.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_registry.h"
#include "bearing/presets.h"
#include "bearing/signal/spectrum.h"
#include "bearing/solvers/integrator.h"
#include "guarantee_helpers.h"

namespace {

namespace fs = std::filesystem;
using namespace bearing::test;
using bearing::name_of;

// A short case any model kind runs (quasistatic needs |F| above ~63 N on the default 6308),
// writing every optional file and channel: ball loads and motion, the envelope analysis
// (envelope.*) and a microphone (pressure.*).
std::string kind_case(const char* kind, const char* format) {
  return std::string(" --set model.kind=") + kind + " --set output.format=" + format +
         " --set solver.duration=0.1 --set solver.transient=0.02 --set "
         "\"operation.load=[0, -300]\" --set output.ball_loads=true --set "
         "output.ball_motion=true --set output.envelope_band=auto --set "
         "'acoustics.microphones=[[\"0.5 m\", \"30 deg\"]]' --quiet";
}

// Every kind of the model registry (a new kind is covered without touching this test): two runs,
// and the run of the first run's case.toml, give the same files byte for byte (summary.json's
// case.source and case.toml's "# Source:" comment name the file read, and are blanked); a sweep
// over the kind gives the same sweep.csv with --jobs 1 and 2 (`run` has no --jobs: one case is
// one thread).
TEST(Guarantees, EveryModelKindIsReproducibleByteForByte) {
  for (const bearing::ModelDescriptor& d : bearing::model_registry()) {
    const char* kind = name_of(bearing::kModelKinds, d.kind);
    for (const char* format : {"csv", "npy"}) {
      SCOPED_TRACE(std::string(kind) + ", " + format);
      const std::string args = kind_case(kind, format);
      const fs::path a = fresh_dir("g_rep_a"), b = fresh_dir("g_rep_b"), c = fresh_dir("g_rep_c");
      std::string out;
      ASSERT_EQ(sim("run --out " + a.string() + args, &out), 0) << out;
      ASSERT_EQ(sim("run --out " + b.string() + args), 0);
      const auto first = results_of(a);
      EXPECT_EQ(first.size(), std::string(format) == "npy" ? 7u : 6u);
      EXPECT_TRUE(results_of(b) == first) << "two runs differ";
      ASSERT_EQ(sim("run " + (a / "case.toml").string() + " --out " + c.string() + " --quiet"), 0);
      const auto again = results_of(c);
      ASSERT_EQ(again.size(), first.size());
      for (const auto& [name, bytes] : first) {
        const bool named = name == "summary.json" || name == "case.toml";
        const std::string& other = again.count(name) ? again.at(name) : "";
        EXPECT_TRUE(named ? without_source(other) == without_source(bytes) : other == bytes)
            << name << " of run DIR/case.toml differs";
      }
    }
    SCOPED_TRACE(kind);
    const std::string sweep =
        "sweep --vary operation.speed=1000rpm:3000rpm:4" + kind_case(kind, "csv") + " --out ";
    const fs::path s1 = fresh_dir("g_rep_s1"), s2 = fresh_dir("g_rep_s2");
    ASSERT_EQ(sim(sweep + s1.string() + " --jobs 1"), 0);
    ASSERT_EQ(sim(sweep + s2.string() + " --jobs 2"), 0);
    EXPECT_EQ(read(s1 / "sweep.csv"), read(s2 / "sweep.csv"));
    EXPECT_EQ(read(s1 / "sweep.csv").find(",failed,"), std::string::npos);
  }
}

// Every example case, shortened, in both output formats: every file is finite.
TEST(Guarantees, ExampleOutputsAreFinite) {
  int cases = 0;
  for (const auto& e : fs::directory_iterator(std::string(BEARING_SOURCE_DIR) + "/examples")) {
    if (e.path().extension() != ".toml") continue;
    for (const char* format : {"csv", "npy"}) {
      SCOPED_TRACE(e.path().filename().string() + ", " + format);
      const fs::path d = fresh_dir("g_example");
      std::string out;
      ASSERT_EQ(sim("run " + e.path().string() + " --out " + d.string() +
                        " --set solver.duration=0.1 --set solver.transient=0.02 --quiet --set "
                        "output.format=" +
                        format,
                    &out),
                0)
          << out;
      const auto files = results_of(d);
      EXPECT_GE(files.size(), 4u);
      for (const auto& [name, bytes] : files) EXPECT_EQ(non_finite_in(name, bytes), "");
    }
    ++cases;
  }
  EXPECT_GE(cases, 12);
}

// ---- 200 random valid cases -------------------------------------------------------------------

// A draw within a range; `log` for ranges over decades.
struct Range {
  const char* key;
  double lo, hi;
  bool log;
  const bearing::Limit* limit;  ///< the schema's range of the key (bearing/limits.h), if shared
};

// The drawn ranges (SI, speeds rad/s). Where the schema's own range is open (a mass > 0, a
// damping >= 0) a physically sensible part of it; each lies inside the schema's range, checked
// below against bearing/limits.h where the key has a shared limit.
const Range kRanges[] = {
    {"bearing.clearance", 0, 50e-6, false, nullptr},
    {"bearing.inner_conformity", 0.505, 0.57, false, nullptr},
    {"bearing.outer_conformity", 0.505, 0.57, false, nullptr},
    {"bearing.contact_angle", 0, 15 * M_PI / 180, false, nullptr},
    {"material.young", 150e9, 450e9, true, nullptr},
    {"material.poisson", 0.2, 0.35, false, nullptr},
    {"material.density", 3000, 8000, false, nullptr},
    {"rotor.mass", 0.1, 5, true, &bearing::limits::rotor_mass},
    {"rotor.damping", 0, 2000, false, &bearing::limits::rotor_damping},
    {"rotor.axial_mass", 0.1, 5, true, &bearing::limits::rotor_axial_mass},
    {"rotor.axial_damping", 0, 2000, false, &bearing::limits::rotor_axial_damping},
    {"ball.damping", 0, 2000, false, &bearing::limits::ball_damping},
    {"solver.max_displacement", 1e-4, 1e-2, true, &bearing::limits::solver_max_displacement},
    {"operation.speed", 0, 10000 * M_PI / 30, false, &bearing::limits::operation_speed},
    {"operation.unbalance", 0, 20e-6, false, &bearing::limits::operation_unbalance},
    {"cage.slip", 0, 0.05, false, &bearing::limits::cage_slip},
    {"cage.friction", 0, 0.1, false, &bearing::limits::cage_friction},
    {"cage.slide_speed", 0.01, 1, true, &bearing::limits::cage_slide_speed},
    {"solver.dt", 0.5e-6, 5e-6, true, &bearing::limits::solver_dt},
    {"solver.tolerance", 1e-8, 1e-4, true, &bearing::limits::solver_tolerance},
    {"housing.mass", 0.05, 5, true, &bearing::limits::housing_mass},
    {"housing.frequency", 500, 10e3, true, &bearing::limits::housing_frequency},
    {"housing.damping_ratio", 0, 0.3, false, &bearing::limits::housing_damping_ratio},
};

class CaseDraw {
 public:
  explicit CaseDraw(std::uint64_t seed) : rng_(seed), housing_rng_(seed + 1), slip_rng_(seed + 2) {}

  double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool coin(double p) { return u(0, 1) < p; }
  double draw(const char* key) {
    for (const Range& r : kRanges)
      if (std::string(key) == r.key)
        return r.log ? std::exp(u(std::log(r.lo), std::log(r.hi))) : u(r.lo, r.hi);
    ADD_FAILURE() << "no range for " << key;
    return 0;
  }
  template <class E, std::size_t N>
  const char* pick(const bearing::Named<E> (&table)[N]) {
    return table[integer(0, N - 1)].name;
  }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[integer(0, static_cast<int>(v.size()) - 1)];
  }

  // One case file's text: a catalogue bearing, every table's keys drawn (the tables a kind does
  // not read only for the kinds that do, as the registry says), optional parts by a coin.
  std::string next();

 private:
  // [housing] for a kind that carries it, from a stream of its own: the draws of the other keys
  // stay those made before the table existed.
  std::string housing(const bearing::ModelDescriptor& kind);
  // [slip] for a turning cage (every kind), likewise from its own stream.
  std::string slip(bool turning);

  std::mt19937_64 rng_;
  std::mt19937_64 housing_rng_;
  std::mt19937_64 slip_rng_;
};

std::string num(double v);

std::string CaseDraw::housing(const bearing::ModelDescriptor& kind) {
  const auto u = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(housing_rng_);
  };
  if (!kind.housing() || u(0, 1) >= 0.3) return "";
  std::ostringstream t;
  t << "[housing]\n";
  for (const char* key : {"housing.mass", "housing.frequency", "housing.damping_ratio"})
    for (const Range& r : kRanges)
      if (std::string(key) == r.key)
        t << std::string(key).substr(8) << " = "
          << num(r.log ? std::exp(u(std::log(r.lo), std::log(r.hi))) : u(r.lo, r.hi)) << "\n";
  return t.str();
}

// rms up to 5 %; the correlation time its default, or drawn between 0.2 ms and 50 ms (log).
std::string CaseDraw::slip(bool turning) {
  const auto u = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(slip_rng_);
  };
  if (!turning || u(0, 1) >= 0.3) return "";
  std::ostringstream t;
  t << "[slip]\nrms = " << num(u(0, 0.05)) << "\nseed = " << static_cast<int>(u(0, 1000)) << "\n";
  if (u(0, 1) < 0.5)
    t << "correlation_time = " << num(std::exp(u(std::log(0.2e-3), std::log(50e-3)))) << "\n";
  return t.str();
}

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

std::string CaseDraw::next() {
  std::ostringstream t;
  const bearing::ModelDescriptor& kind = pick(bearing::model_registry());
  t << "[bearing]\npreset = \"" << pick(bearing::preset_names()) << "\"\n";
  for (const char* key :
       {"bearing.clearance", "bearing.inner_conformity", "bearing.outer_conformity"})
    if (coin(0.5)) t << std::string(key).substr(8) << " = " << num(draw(key)) << "\n";
  if (coin(0.3)) t << "balls = " << integer(3, 16) << "\n";  // >= 3; too many overlap
  if (coin(0.3)) t << "contact_angle = \"" << num(draw("bearing.contact_angle")) << " rad\"\n";
  if (coin(0.3))
    t << "[material]\nyoung = " << num(draw("material.young"))
      << "\npoisson = " << num(draw("material.poisson"))
      << "\ndensity = " << num(draw("material.density")) << "\n";
  for (const char* part : {"ball", "rings"})
    if (coin(0.15))
      t << "[material." << part << "]\nyoung = " << num(draw("material.young"))
        << "\npoisson = " << num(draw("material.poisson"))
        << "\ndensity = " << num(draw("material.density")) << "\n";
  t << "[rotor]\nmass = " << num(draw("rotor.mass")) << "\ndamping = " << num(draw("rotor.damping"))
    << "\n";
  if (coin(0.3))
    t << "axial_mass = " << num(draw("rotor.axial_mass"))
      << "\naxial_damping = " << num(draw("rotor.axial_damping")) << "\n";
  const bool still = coin(0.05);
  t << "[operation]\nspeed = \"" << (still ? std::string("0") : num(draw("operation.speed")))
    << " rad/s\"\nload = [" << num(u(-200, 200)) << ", "
    << num(-std::exp(u(std::log(10), std::log(5000)))) << "]\n";
  if (coin(0.3)) t << "axial_load = " << num(u(0, 2000)) << "\n";
  if (coin(0.3)) t << "unbalance = " << num(draw("operation.unbalance")) << "\n";
  if (coin(0.2)) t << "gravity = true\n";
  for (const char* race : {"inner", "outer"})
    for (int i = integer(0, 2); i > 0; --i)
      t << "[[waviness." << race << "]]\norder = " << integer(1, 40)
        << "\namplitude = " << num(std::exp(u(std::log(0.01e-6), std::log(5e-6)))) << "\nphase = \""
        << num(u(0, 360)) << " deg\"\n";
  if (coin(0.3))
    t << "[ball_errors]\nband = " << num(u(0, 2e-6)) << "\nseed = " << integer(1, 99) << "\n";
  if (kind.dynamic && coin(0.25)) {
    const std::string location = pick(bearing::kDefectLocations);
    t << "[[defects]]\nlocation = \"" << location << "\"\nwidth = " << num(u(0.1e-3, 1e-3))
      << "\ndepth = " << num(u(0.02e-3, 0.5e-3)) << "\nprofile = \""
      << pick(bearing::kDefectProfiles) << "\"\n";
    if (location == "ball")
      t << "ball = " << integer(0, 4) << "\n";
    else
      t << "position = \"" << num(u(0, 360)) << " deg\"\n";
  }
  std::string contact;
  do contact = pick(bearing::kContactLaws);  // "calibrated" needs an FE file of this bearing
  while (contact == "calibrated");
  t << "[model]\nkind = \"" << name_of(bearing::kModelKinds, kind.kind) << "\"\ncontact = \""
    << contact << "\"\nwaviness_stiffness = " << (coin(0.3) ? "true" : "false") << "\n";
  if (kind.owns("cage"))
    t << "[cage]\nslip = " << num(draw("cage.slip"))
      << "\nfriction = " << num(draw("cage.friction"))
      << "\nslide_speed = " << num(draw("cage.slide_speed")) << "\n";
  if (kind.owns("ball")) {
    t << "[ball]\ncentrifugal = " << (coin(0.5) ? "true" : "false") << "\n";
    // ball.mass and ball.inertia keep their defaults from the drawn density: a free draw gives
    // a 6308's ball a 608's inertia, and its spin needs 1e5 steps.
    if (coin(0.3)) t << "damping = " << num(draw("ball.damping")) << "\n";
  }
  const double rate = u(10e3, 40e3);
  t << "[solver]\nmethod = \"" << pick(bearing::kIntegratorMethods)
    << "\"\ndt = " << num(draw("solver.dt")) << "\ntolerance = " << num(draw("solver.tolerance"))
    << "\nduration = " << num(u(0.04, 0.08)) << "\ntransient = " << num(u(0.01, 0.02))
    << "\noutput_rate = " << num(rate) << "\ncontact_loop = \"" << pick(bearing::kContactLoops)
    << "\"\n";
  if (coin(0.2)) t << "max_displacement = " << num(draw("solver.max_displacement")) << "\n";
  if (coin(0.3)) {
    t << "[acoustics]\nmicrophones = [";
    for (int i = integer(1, 3); i > 0; --i)
      t << "[\"" << num(u(0.1, 1)) << " m\", \"" << num(u(0, 360)) << " deg\"]"
        << (i > 1 ? ", " : "");
    t << "]\nring_source = \"" << pick(bearing::kRingSources) << "\"\nball_source = \""
      << pick(bearing::kBallSources) << "\"\nsummation = \"" << pick(bearing::kSummations)
      << "\"\n";
  }
  t << "[output]\nball_loads = " << (coin(0.3) ? "true" : "false")
    << "\nball_motion = " << (coin(0.3) ? "true" : "false")
    << "\nball_approach = " << (coin(0.3) ? "true" : "false") << "\nwindow = \""
    << pick(bearing::kWindows) << "\"\npeaks = " << integer(1, 20) << "\nformat = \""
    << pick(bearing::kOutputFormats) << "\"\n";
  if (kind.ball_dofs) t << "ball_dynamics = " << (coin(0.5) ? "true" : "false") << "\n";
  const double band = u(0, 1);
  if (band < 0.2)
    t << "envelope_band = \"auto\"\n";
  else if (band < 0.4) {
    const double lo = u(500, 3000);
    t << "envelope_band = [" << num(lo) << ", " << num(u(lo + 1000, rate / 2)) << "]\n";
  }
  t << housing(kind);
  t << slip(!still);
  return t.str();
}

// The scan finds what it looks for, in text and in .npy data, and nothing in words like "info".
TEST(Guarantees, TheNonFiniteScanFindsNanAndInf) {
  EXPECT_NE(non_finite_in("a.csv", "t,x\n0,1\n1,nan\n"), "");
  EXPECT_NE(non_finite_in("a.csv", "t,x\n0,-inf\n"), "");
  EXPECT_NE(non_finite_in("s.json", "{\"rms\": Infinity}"), "");
  EXPECT_NE(non_finite_in("s.json", "{\"rms\": NaN}"), "");
  EXPECT_EQ(non_finite_in("s.json", "{\"info\": \"inner\", \"nano\": 1e-9, \"l\": \"BPFI\"}"), "");
  std::string npy = std::string("\x93NUMPY\x01\x00\x76\x00", 10) +
                    "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 1), }";
  npy += std::string(127 - npy.size(), ' ') + "\n";
  const double values[2] = {1.5, std::nan("")};
  npy.append(reinterpret_cast<const char*>(values), 16);
  EXPECT_NE(non_finite_in("r.npy", npy), "");
  npy.replace(npy.size() - 8, 8, std::string(reinterpret_cast<const char*>(values), 8));
  EXPECT_EQ(non_finite_in("r.npy", npy), "");
}

TEST(Guarantees, FuzzRangesLieWithinTheSchemasRanges) {
  for (const Range& r : kRanges)
    if (r.limit) {
      EXPECT_TRUE(r.limit->contains(r.lo) || (r.log && r.lo > r.limit->lo)) << r.key;
      EXPECT_TRUE(r.limit->contains(r.hi)) << r.key;
    }
}

// 200 random valid cases (seed 2026): each run exits 0 with finite files, or 3 (a solver failure
// the physics explains) with a clear message and no result file. A draw the reader rejects (exit
// 2: a cross-key rule, e.g. balls that overlap, a step too long for a defect) is redrawn and
// counted; exit 1, a signal, or a NaN/Inf in any file fails. Two runs at a time.
TEST(Guarantees, RandomValidCasesGiveFiniteOutputs) {
  CaseDraw draws(2026);
  const fs::path root = fresh_dir("g_fuzz");
  fs::create_directories(root);
  int draws_made = 0, accepted = 0, solved = 0, solver_failures = 0, redraws = 0;
  std::map<std::string, int> rejected;  // the key of each exit-2 message
  const auto start = std::chrono::steady_clock::now();
  while (accepted < 200 && draws_made < 2000) {
    struct Slot {
      int id;
      fs::path file, dir, log;
      pid_t pid;
    };
    std::vector<Slot> slots;
    for (int k = 0; k < 2 && accepted + static_cast<int>(slots.size()) < 200; ++k) {
      Slot s;
      s.id = draws_made++;
      s.file = root / ("case" + std::to_string(s.id) + ".toml");
      s.dir = root / ("out" + std::to_string(s.id));
      s.log = root / ("log" + std::to_string(s.id) + ".txt");
      std::ofstream(s.file) << draws.next();
      s.pid = spawn_sim("run " + s.file.string() + " --out " + s.dir.string() + " --quiet",
                        s.log.string());
      slots.push_back(s);
    }
    for (const Slot& s : slots) {
      const int status = wait_sim(s.pid);
      const std::string log = read(s.log);
      SCOPED_TRACE("draw " + std::to_string(s.id) + " (" + s.file.string() + "): " + log);
      ASSERT_TRUE(status == 0 || status == 2 || status == 3) << "exit status " << status;
      if (status == 2) {
        ++redraws;
        const auto colon = log.find(": error: ");
        std::string what = colon == std::string::npos ? log : log.substr(colon + 9);
        if (what.rfind(s.file.string() + ": ", 0) == 0)
          what = what.substr(s.file.string().size() + 2);
        ++rejected[what.substr(0, what.find_first_of(" =:"))];
        EXPECT_TRUE(results_of(s.dir).empty());
        continue;
      }
      ++accepted;
      if (status == 3) {
        ++solver_failures;
        EXPECT_NE(log.find("solver error: "), std::string::npos);
        EXPECT_GT(log.size(), 60u) << "too short to say why";
        EXPECT_TRUE(results_of(s.dir).empty()) << "a failed run wrote files";
        std::cout << "  draw " << s.id << " exit 3: " << log;
        continue;
      }
      ++solved;
      const auto files = results_of(s.dir);
      EXPECT_GE(files.size(), 4u);
      for (const auto& [name, bytes] : files) EXPECT_EQ(non_finite_in(name, bytes), "");
      fs::remove_all(s.dir);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "  " << accepted << " cases (" << solved << " ran, " << solver_failures
            << " solver failures) from " << draws_made << " draws, " << redraws
            << " redrawn after an input error, in " << seconds << " s; rejected by key:";
  for (const auto& [key, n] : rejected) std::cout << " " << key << " " << n;
  std::cout << "\n";
  EXPECT_EQ(accepted, 200);
  EXPECT_LT(solver_failures, 20);
}

}  // namespace
