#pragma once
// `bearing-sim sweep`: many variants of one case, run in parallel, one summary row each.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"

namespace bearing {

/// One varied key: `KEY=FROM:TO:N`, N values spaced linearly from FROM to TO inclusive.
struct SweepAxis {
  std::string key;  ///< case-file key, e.g. "operation.speed", "waviness.inner.0.amplitude"
  std::vector<double> values;  ///< SI values
  Dimension dimension = Dimension::dimensionless;
  bool integer = false;  ///< the key takes whole numbers (values must come out whole)
};

/// Parses `KEY=FROM:TO:N`; FROM and TO may carry units ("1000rpm:3000rpm:5"), N in 1…100000.
/// Throws InputError naming `--vary`, the text and what is allowed.
SweepAxis parse_vary(std::string_view text);

/// One case of the sweep: the values of every axis and the overrides that set them.
struct SweepPoint {
  std::vector<double> values;
  std::vector<Override> overrides;
};

/// The Cartesian product of the axes, the first axis varying slowest.
std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes);

struct SweepRow {
  std::vector<double> values;  ///< the point's values (SI)
  bool ok = false;
  std::string error;                          ///< why the case failed (empty if ok)
  std::vector<ChannelSummary> channels;       ///< the run's summary (empty if it failed)
  std::vector<MicrophoneLevels> microphones;  ///< sound levels ([acoustics] only)
};

/// Runs every point with `threads` workers (0: all cores). `load` builds the case of a point
/// (base file + the point's overrides). A failed case is reported in its row and does not stop
/// the others. `progress(done, total)` is called from the workers, serialised.
std::vector<SweepRow> run_sweep(const std::function<Case(const std::vector<Override>&)>& load,
                                const std::vector<SweepPoint>& points, int threads,
                                const std::function<void(std::size_t, std::size_t)>& progress = {});

/// sweep.csv: the varied keys (SI), `status` (ok/failed), `error`, then for each ring channel of
/// the first successful row `<ch>.rms,<ch>.ptp,<ch>.kurtosis,<ch>.crest,<ch>.peak_frequency,
/// <ch>.peak_label`, and with an [acoustics] table per microphone i = 1… `mic<i>.spl_total,
/// mic<i>.spl_ring,mic<i>.spl_balls` [dB re 20 µPa]. Failed rows, and levels that do not exist
/// (source "none", silence), leave their fields empty.
std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows);

}  // namespace bearing
