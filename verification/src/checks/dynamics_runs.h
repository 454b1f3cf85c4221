#pragma once
// How the dynamics checks set up and run the toolkit's models: the case's model inputs as
// bearing::model_inputs maps them, changed by the check (waviness, speed, phase), then perturbed
// by the Context (the mutation under test) and simulated through it.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../context.h"
#include "bearing/case_file.h"
#include "bearing/simulation.h"

namespace bearing::verify::dynamics {

/// Ball 0 at the bottom (θ₀ = −π/2): the ball set is symmetric about the y axis for any Z.
inline constexpr double kBottom = -1.57079632679489661923;

/// The default case (6308, 2000 rpm, 20 N down, 0.6 kg, 200 N s/m) with `key=value` overrides,
/// mapped to model inputs without any perturbation: the physics the references describe.
inline ModelInputs case_inputs(const Context& ctx, const std::vector<std::string>& sets) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  ModelInputs in = model_inputs(ctx.default_case(o));
  in.cage_phase = kBottom;
  return in;
}

inline void add_waviness(ModelInputs& in, bool inner, int order, double amplitude, double phase) {
  (inner ? in.inner_waviness : in.outer_waviness).harmonics.push_back({order, amplitude, phase});
}

struct RunSpec {
  ModelKind kind = ModelKind::two_dof;
  IntegratorMethod method = IntegratorMethod::rk4;
  double dt = 5e-6;
  double duration = 0.1;
  double transient = 0.0;
  double rate = 20000.0;
  double tolerance = 1e-6;
};

inline SolverSettings solver_settings(const RunSpec& s) {
  SolverSettings solver;
  solver.method = s.method;
  solver.dt = s.dt;
  solver.duration = s.duration;
  solver.transient = s.transient;
  solver.output_rate = s.rate;
  solver.tolerance = s.tolerance;
  return solver;
}

/// The model under test: `in` perturbed by the Context's mutation, simulated through it.
inline Response run(const Context& ctx, const ModelInputs& in, const RunSpec& s) {
  return ctx.simulate(s.kind, ctx.perturbed(in), solver_settings(s), OutputRequest{}).response;
}

/// A reference model run (cross-model checks): the unperturbed inputs straight through the
/// pipeline, never through the Context, so it stays the correct model under every mutation.
inline Response run_reference(const ModelInputs& in, const RunSpec& s) {
  return bearing::simulate(s.kind, in, solver_settings(s), OutputRequest{}).response;
}

/// A sampled extremum, refined by the parabola through it and its two neighbours.
struct Extremum {
  double t = 0, value = 0;
};
inline std::vector<Extremum> extrema(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<Extremum> out;
  for (std::size_t i = 1; i + 1 < y.size(); ++i) {
    const bool max = y[i] > y[i - 1] && y[i] >= y[i + 1];
    const bool min = y[i] < y[i - 1] && y[i] <= y[i + 1];
    if (!max && !min) continue;
    const double a = y[i - 1], b = y[i], c = y[i + 1];
    const double den = a - 2 * b + c;
    const double d = den != 0 ? 0.5 * (a - c) / den : 0.0;
    const double h = t[i + 1] - t[i];
    out.push_back({t[i] + d * h, b - 0.25 * (a - c) * d});
  }
  return out;
}

inline std::string fmt(double v, int digits = 6) {
  char s[64];
  std::snprintf(s, sizeof s, "%.*g", digits, v);
  return s;
}

}  // namespace bearing::verify::dynamics
