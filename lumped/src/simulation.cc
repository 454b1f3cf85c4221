#include "bearing/simulation.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "bearing/errors.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"

namespace bearing {

const std::vector<double>& Response::channel(const std::string& name) const {
  for (std::size_t i = 0; i < channels.size(); ++i)
    if (channels[i] == name) return values[i];
  throw std::out_of_range("response has no channel \"" + name + "\"");
}

std::vector<double> Response::steady(const std::string& name) const {
  const auto& v = channel(name);
  return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first_steady), v.end() - 1);
}

ModelInputs model_inputs(const Case& c) {
  ModelInputs in;
  in.bearing = c.bearing;
  in.hertz_method = hertz_shape_method(c.model);
  in.contact = contact_constants(c);
  in.inner_speed = c.operation.speed;
  in.load = c.operation.load;
  in.axial_load = c.operation.axial_load;
  in.unbalance = c.operation.unbalance;
  in.gravity = c.operation.gravity;
  in.mass = c.rotor.mass;
  in.damping = c.rotor.damping;
  in.axial_mass = c.rotor.axial_mass;
  in.axial_damping = c.rotor.axial_damping;
  in.inner_waviness.harmonics = c.excitation.inner_waviness;
  in.outer_waviness.harmonics = c.excitation.outer_waviness;
  in.ball_size_errors = c.excitation.ball_size_errors;
  in.waviness_stiffness = c.model.waviness_stiffness;
  return in;
}

std::unique_ptr<BearingModel> make_model(const Case& c) {
  const ModelInputs in = model_inputs(c);
  if (c.model.kind == "2dof") return make_two_dof_model(in);
  if (c.model.kind == "3dof") return make_three_dof_model(in);
  throw InputError("model.kind = \"" + c.model.kind + "\": allowed: 2dof, 3dof");
}

namespace {

// Bearing frequencies as the model runs them: a preloaded 3-DOF bearing turns at its loaded
// contact angle.
BearingFrequencies run_frequencies(const Case& c) {
  Bearing b = c.bearing;
  if (c.model.kind == "3dof") b.contact_angle = solve_axial_preload(model_inputs(c)).contact_angle;
  return bearing_frequencies(b, c.operation.speed);
}

}  // namespace

SimulationResult simulate(const Case& c, const Progress& progress) {
  SimulationResult r;
  const auto model = make_model(c);
  r.contact = contact_constants(c);
  r.frequencies = run_frequencies(c);

  const int n = model->dofs();
  const std::vector<double> q0 = model->initial_displacement();
  const std::vector<double> v0(static_cast<std::size_t>(n), 0.0);

  // One tolerance for the user: the absolute tolerance on displacements is solver.tolerance times
  // the displacement scale of the problem (the static deflection, the per-ball gap, at least
  // 1 µm), so tightening the tolerance is never capped by a fixed absolute floor.
  double scale = std::max(1e-6, c.bearing.ball_gap());
  for (double q : q0) scale = std::max(scale, std::fabs(q));
  IntegratorSettings settings;
  settings.method = c.solver.method;
  settings.dt = c.solver.dt;
  settings.rtol = c.solver.tolerance;
  settings.atol = c.solver.tolerance * scale;
  settings.max_displacement = c.solver.max_displacement;
  const auto integrator = make_integrator(settings);

  const int Z = model->balls();
  const auto names = model->dof_names();
  Response& out = r.response;
  for (const auto& q : names) out.channels.push_back(q), out.units.push_back("m");
  for (const auto& q : names) out.channels.push_back("v" + q), out.units.push_back("m/s");
  for (const auto& q : names) out.channels.push_back("a" + q), out.units.push_back("m/s^2");
  if (c.output.ball_loads)
    for (int j = 0; j < Z; ++j)
      out.channels.push_back("Q" + std::to_string(j + 1)), out.units.push_back("N");

  // Output times k / rate; the sample count comes from the duration, rounded to whole samples.
  const auto samples =
      static_cast<std::size_t>(std::floor(c.solver.duration * c.solver.output_rate + 1e-9)) + 1;
  out.time.resize(samples);
  for (std::size_t k = 0; k < samples; ++k)
    out.time[k] = static_cast<double>(k) / c.solver.output_rate;
  out.first_steady =
      static_cast<std::size_t>(std::ceil(c.solver.transient * c.solver.output_rate - 1e-9));
  out.values.assign(out.channels.size(), std::vector<double>(samples));

  std::vector<double> loads(static_cast<std::size_t>(Z));
  std::size_t k = 0;
  const Observer observe = [&](double t, const double* q, const double* v, const double* a) {
    for (int i = 0; i < n; ++i) {
      out.values[static_cast<std::size_t>(i)][k] = q[i];
      out.values[static_cast<std::size_t>(n + i)][k] = v[i];
      out.values[static_cast<std::size_t>(2 * n + i)][k] = a[i];
    }
    if (c.output.ball_loads) {
      model->ball_loads(t, q, loads.data());
      for (int j = 0; j < Z; ++j)
        out.values[static_cast<std::size_t>(3 * n + j)][k] = loads[static_cast<std::size_t>(j)];
    }
    ++k;
  };
  r.stats = integrator->integrate(*model, 0.0, q0, v0, out.time, observe, progress);
  if (k != samples)
    throw SolverError("the integrator delivered " + std::to_string(k) + " of " +
                      std::to_string(samples) + " output samples");
  return r;
}

RunSummary summarize(const Case& c, const SimulationResult& result) {
  const Response& resp = result.response;
  RunSummary s;
  const Window window = parse_window(c.output.window, "output.window");
  const double rate = c.solver.output_rate;
  const auto& f = result.frequencies;
  const auto names = bearing_frequency_names(f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf);
  std::unique_ptr<SpectrumPlan> plan;  // one window and FFT table for all channels
  for (std::size_t i = 0; i < resp.channels.size(); ++i) {
    ChannelSummary ch;
    ch.name = resp.channels[i];
    ch.unit = resp.units[i];
    const std::vector<double> x = resp.steady(ch.name);
    ch.statistics = channel_statistics(x);
    if (ch.name.front() != 'Q') {
      if (!plan) plan = std::make_unique<SpectrumPlan>(x.size(), rate, window);
      Spectrum spectrum = (*plan)(x);
      ch.peaks = find_peaks(spectrum, names, c.output.peaks);
      s.spectrum_channels.push_back(ch.name);
      s.spectra.push_back(std::move(spectrum));
    }
    s.channels.push_back(std::move(ch));
  }
  return s;
}

}  // namespace bearing
