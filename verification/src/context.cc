#include "context.h"

#include <cmath>
#include <filesystem>

#include "bearing/constants.h"
#include "bearing/presets.h"
#include "fem_runner.h"

namespace bearing::verify {

namespace {

thread_local unsigned* t_knobs = nullptr;

void read(unsigned knobs) {
  if (t_knobs != nullptr) *t_knobs |= knobs;
}

}  // namespace

KnobRecorder::KnobRecorder() : previous_(t_knobs) {
  t_knobs = &knobs_;
}
KnobRecorder::~KnobRecorder() {
  t_knobs = previous_;
}

Context::Context(Level level, Perturbation perturbation, FemRunner* fem, std::string source_dir)
    : level_(level), perturbation_(perturbation), fem_(fem), source_dir_(std::move(source_dir)) {}

Bearing Context::bearing(const std::string& designation) const {
  return bearing(preset(designation));
}

RecordAnalysis Context::analyse_record(const std::vector<double>& samples, double rate,
                                       const Bearing& b, SpeedSetting speed,
                                       RecordAnalysisSettings settings) const {
  read(kAnalysis);
  speed.speed *= perturbation_.analysis_speed;
  settings.prewhiten = settings.prewhiten && !perturbation_.drop_prewhitening;
  settings.lines.false_alarm *= perturbation_.false_alarm;
  settings.coherence.false_alarm *= perturbation_.false_alarm;
  return bearing::analyse_record(samples, rate, "record", "m/s^2", b, speed, settings);
}

Bearing Context::bearing(Bearing b) const {
  read(kPitch);
  b.pitch_diameter *= perturbation_.pitch_diameter;
  return b;
}

namespace {

void perturb(RaceContact& r, const Perturbation& p) {
  r.K *= p.contact_constant;
  r.exponent += p.contact_exponent;
  r.shape.b_star *= p.ellipse_minor;
}

void perturb(ContactConstants& k, const Perturbation& p) {
  perturb(k.inner, p);
  perturb(k.outer, p);
  k.K *= p.contact_constant;
  k.exponent += p.contact_exponent;
}

void turn_over(Waviness& w) {
  for (auto& h : w.harmonics) h.phase += pi;
}

}  // namespace

RaceContact Context::race_contact(const Bearing& b, Race race, HertzMethod method) const {
  read(kContact);
  RaceContact r = bearing::race_contact(b, race, *make_hertz_solution(method));
  perturb(r, perturbation_);
  return r;
}

ContactConstants Context::contact(const Bearing& b, HertzMethod method) const {
  read(kContact);
  ContactConstants k = contact_constants(b, *make_hertz_solution(method));
  perturb(k, perturbation_);
  return k;
}

BearingFrequencies Context::frequencies(const Bearing& b, double inner_speed) const {
  return bearing_frequencies(b, inner_speed);
}

StaticLoadResult Context::static_load(int balls, const ContactConstants& k, double gap,
                                      const Eigen::Vector2d& load, double phase) const {
  StaticLoadOptions options;
  options.phase = phase;
  options.exponent = k.exponent;
  return solve_static_load(balls, k.K, gap, load, options);
}

Case Context::example(const std::string& file, const std::vector<Override>& overrides) const {
  return read_case_file((std::filesystem::path(source_dir_) / "examples" / file).string(),
                        overrides);
}

Case Context::default_case(const std::vector<Override>& overrides) const {
  return bearing::default_case(overrides);
}

ModelInputs Context::inputs(const Case& c) const {
  Case geometry = c;
  geometry.bearing = bearing(c.bearing);
  ModelInputs in = model_inputs(geometry);
  perturb_model(in);
  return in;
}

ModelInputs Context::perturbed(ModelInputs in) const {
  read(kPitch);
  if (perturbation_.pitch_diameter != 1.0) {
    in.bearing = bearing(in.bearing);
    if (in.contact.method != ContactLaw::calibrated)
      in.contact = contact_constants(in.bearing, *make_hertz_solution(in.hertz_method));
  }
  perturb_model(in);
  return in;
}

// Records only the knobs that can change these inputs (no waviness: the sign cannot matter).
void Context::perturb_model(ModelInputs& in) const {
  read(kContact | kMass | kCageSlip | (in.damping != 0 || in.axial_damping != 0 ? kDamping : 0u) |
       (in.waviness_stiffness ? kTvds : 0u) |
       (in.inner_waviness.empty() && in.outer_waviness.empty() ? 0u : kWaviness) |
       (in.defects.empty() ? 0u : kDefect));
  perturb(in.contact, perturbation_);
  in.mass *= perturbation_.mass;
  in.axial_mass *= perturbation_.mass;
  in.damping *= perturbation_.damping;
  if (perturbation_.drop_tvds) in.waviness_stiffness = false;
  if (perturbation_.waviness_sign) {
    turn_over(in.inner_waviness);
    turn_over(in.outer_waviness);
  }
  in.cage_slip += perturbation_.cage_slip;
  for (LocalDefect& d : in.defects) d.width *= perturbation_.defect_width;
}

SimulationResult Context::simulate(ModelKind kind, const ModelInputs& in,
                                   const SolverSettings& solver,
                                   const OutputRequest& output) const {
  return bearing::simulate(kind, in, solver, output);
}

RunSettings Context::settings(const Case& c) const {
  RunSettings s = run_settings(c);
  s.model = inputs(c);
  s.acoustics = acoustics(s.acoustics);
  return s;
}

Air Context::air(double density, double sound_speed) const {
  read(kSoundSpeed);
  return Air{density, sound_speed * perturbation_.sound_speed};
}

Microphone Context::microphone(double radius, double angle) const {
  read(kMicrophone);
  return Microphone{radius * perturbation_.microphone_distance, angle};
}

AcousticsOptions Context::acoustics(AcousticsOptions a) const {
  read(kSoundSpeed | kMicrophone);
  a.sound_speed *= perturbation_.sound_speed;
  for (auto& m : a.microphones) m.radius *= perturbation_.microphone_distance;
  return a;
}

nlohmann::json Context::fem(const std::vector<std::string>& args,
                            const std::string& json_name) const {
  if (fem_ == nullptr) throw Skipped("no FE runner in this context");
  return fem_->run(args, json_name);
}

int Context::fe_degree(int degree) const {
  read(kFeDegree);
  return std::max(1, degree + perturbation_.fe_degree);
}

double Context::structure_young(double young) const {
  read(kStructure);
  return young * perturbation_.structure_young;
}

nlohmann::json Context::modal(nlohmann::json m) const {
  read(kStructure);
  const double s = perturbation_.modal_shapes;
  const auto scale = [](nlohmann::json& a, double f) {
    for (auto& v : a) v = v.get<double>() * f;
  };
  for (const char* k : {"x", "y", "z", "tilt_x", "tilt_y", "tilt_z"}) scale(m["seat"][k], s);
  for (auto& sensor : m["sensors"])
    for (const char* k : {"x", "y", "z"}) scale(sensor[k], s);
  for (const char* k : {"x", "y", "z"}) scale(m["effective_mass"][k], s * s);
  return m;
}

std::string Context::fem_input(const std::string& stem, const std::string& extension,
                               const std::string& text) const {
  if (fem_ == nullptr) throw Skipped("no FE runner in this context");
  return fem_->input_file(stem, extension, text);
}

int Context::fe_cells(int cells) const {
  read(kFeCells);
  return std::max(1, static_cast<int>(std::lround(cells * perturbation_.fe_cells)));
}

}  // namespace bearing::verify
