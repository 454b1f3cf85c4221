#pragma once
// One case's row of a sweep: what sweep.csv (sweep_columns.h), the Python rows, the row codec
// (MPI, --save's spool) and sweep.h5 get from its run.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bearing/analysis.h"
#include "bearing/sweep_tables.h"

namespace bearing {

/// One envelope of a run as its sweep row keeps it: summary.json's `envelope.<ch>` without the
/// envelope spectrum and the kurtogram map (a row stays small).
struct SweepEnvelope {
  std::string channel;                    ///< the ring acceleration: "ax", "ay", "az"
  FrequencyBand band;                     ///< the band demodulated [Hz]
  double spectral_kurtosis = 0;           ///< of the band, over the noise floor [-]
  std::optional<double> energy_fraction;  ///< band_energy_fraction(): kurtogram bands only [-]
  std::optional<Peak> peak;  ///< the largest envelope line (Hz, channel unit m/s^2, label)
};

struct SweepRow {
  std::vector<double> values;  ///< the point's values (SI)
  bool ok = false;
  std::string error;                          ///< why the case failed (empty if ok)
  std::vector<ChannelSummary> channels;       ///< the run's summary (empty if it failed)
  std::vector<MicrophoneLevels> microphones;  ///< sound levels ([acoustics] only)
  std::vector<SweepEnvelope> envelopes;       ///< output.envelope_band only, per acceleration
  std::optional<Diagnosis> diagnosis;         ///< with the envelopes: the run's diagnosis
  /// The tables `--save` asked for (sweep_tables.h), built where the case ran; null when nothing
  /// is saved or the case failed.
  std::shared_ptr<const SweepCaseTables> tables;
};

}  // namespace bearing
