#pragma once
// `bearing-sim run`: a case through model and integrator into a response (time series), and the
// post-processing of that response into statistics, spectra and named peaks.

#include <memory>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/kinematics.h"
#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// Time series of a run, sampled at the case's output rate from t = 0.
struct Response {
  std::vector<std::string> channels;  ///< "x","y","vx","vy","ax","ay" (+ "z","vz","az"; "Q1"…)
  std::vector<std::string> units;     ///< SI unit of each channel
  std::vector<double> time;           ///< [s]
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
  IntegrationStats stats;
  ContactConstants contact;
  BearingFrequencies frequencies;  ///< with the loaded contact angle for a preloaded 3-DOF case
};

/// The model inputs a case describes (excitations resolved, contact constants computed).
ModelInputs model_inputs(const Case& c);

/// The model of `c.model.kind` ("2dof" or "3dof").
std::unique_ptr<BearingModel> make_model(const Case& c);

/// Runs the case. Throws InputError (bad settings) or SolverError (blow-up, no convergence).
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
};

/// Statistics of every channel and spectra and peaks of the ring's channels (not the ball
/// loads), over the post-transient window, with the case's window and peak count.
RunSummary summarize(const Case& c, const SimulationResult& result);

}  // namespace bearing
