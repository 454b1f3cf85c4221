#pragma once
// `bearing-sim run`: a case through model and integrator into a response (time series), and the
// post-processing of that response into statistics, spectra and named peaks.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/kinematics.h"
#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/quasi_static.h"
#include "bearing/noise.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// Time series of a run, sampled at the case's output rate from t = 0.
struct Response {
  /// "x","y","vx","vy","ax","ay" (+ "z","vz","az"), then per ball "Q1"… (output.ball_loads),
  /// "d1"… (output.ball_approach), "r1"…, "vr1"… (output.ball_motion)
  std::vector<std::string> channels;
  std::vector<std::string> units;           ///< SI unit of each channel
  std::vector<double> time;                 ///< [s]
  std::vector<std::vector<double>> values;  ///< values[channel][sample], SI
  std::size_t first_steady = 0;             ///< first sample at or after solver.transient

  /// The samples of one channel; throws std::out_of_range for an unknown name.
  const std::vector<double>& channel(const std::string& name) const;
  /// The analysis window of one channel: the half-open interval [transient, duration), exactly
  /// (duration − transient)·rate samples, so spectral bins fall on multiples of
  /// 1/(duration − transient) (the last sample, at t = duration, is written but not analysed).
  std::vector<double> steady(const std::string& name) const;
};

struct SimulationResult {
  Response response;
  IntegrationStats stats;                        ///< dynamic models; quasistatic: steps only
  std::optional<QuasiStaticStats> quasi_static;  ///< quasistatic only
  ContactConstants contact;
  BearingFrequencies frequencies;  ///< with the loaded contact angle for a preloaded 3-DOF case
};

/// The model inputs a case describes (excitations resolved, contact constants computed).
ModelInputs model_inputs(const Case& c);

/// The dynamic model of `c.model.kind` ("2dof" or "3dof"; InputError for "quasistatic", which
/// make_quasi_static_model(model_inputs(c)) builds).
std::unique_ptr<BearingModel> make_model(const Case& c);

/// Whether a response channel belongs to one ball (Q1…, d1…, r1…, vr1…): statistics only, no spectrum
/// or peaks (the ring's channels get those).
bool is_ball_channel(const std::string& name);

/// Runs the case: a dynamic model (2dof, 3dof) through the case's integrator, or the quasi-static
/// equilibrium followed through the output times (solver.method, dt and tolerance unused). Throws
/// InputError (bad settings) or SolverError (blow-up, no convergence).
SimulationResult simulate(const Case& c, const Progress& progress = {});

struct ChannelSummary {
  std::string name;
  std::string unit;
  ChannelStatistics statistics;  ///< over the post-transient window
  std::vector<Peak> peaks;       ///< largest first (ring channels only)
};

struct RunSummary {
  std::vector<ChannelSummary> channels;        ///< in response order
  std::vector<std::string> spectrum_channels;  ///< channels with a spectrum (the ring's)
  std::vector<Spectrum> spectra;               ///< one per spectrum channel
  std::optional<BearingNoise> noise;           ///< sound at the microphones ([acoustics] only)
};

/// Statistics of every channel and spectra and peaks of the ring's channels (not the ball
/// loads), over the post-transient window, with the case's window and peak count; and, with an
/// [acoustics] table, the sound at the microphones (bearing_noise).
RunSummary summarize(const Case& c, const SimulationResult& result);

}  // namespace bearing
