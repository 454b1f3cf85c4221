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

/// The number of cases: the product of the axes' sizes (0 without axes). Throws InputError if
/// it does not fit a std::size_t.
std::size_t sweep_size(const std::vector<SweepAxis>& axes);

/// Case `index` (0 ≤ index < sweep_size(axes)) of the Cartesian product of the axes, the first
/// axis varying slowest; computed from the index alone, so a sweep never holds all its points.
SweepPoint sweep_point(const std::vector<SweepAxis>& axes, std::size_t index);

/// Every case of the Cartesian product at once (sweep_point for each index).
std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes);

struct SweepRow {
  std::vector<double> values;  ///< the point's values (SI)
  bool ok = false;
  std::string error;                          ///< why the case failed (empty if ok)
  std::vector<ChannelSummary> channels;       ///< the run's summary (empty if it failed)
  std::vector<MicrophoneLevels> microphones;  ///< sound levels ([acoustics] only)
};

/// Builds the case of a point: the base file + the point's overrides.
using SweepLoader = std::function<Case(const std::vector<Override>&)>;
/// Called with (cases done, cases in all), serialised.
using SweepProgress = std::function<void(std::size_t, std::size_t)>;

/// Runs cases 0 … `cases` − 1 (`point(i)` gives case i) with `threads` workers (0: all cores) and
/// hands each row to `sink(i, row)` in case order, serialised, as soon as the rows before it are
/// done. A worker starts case i only while i < (rows handed over) + 4 × workers, so at most that
/// many finished rows wait for an earlier one: memory does not grow with the number of cases. A
/// failed case is reported in its row and does not stop the others; an exception from `sink`
/// stops the sweep (no new cases start) and is rethrown once the running ones are done.
void run_sweep(const SweepLoader& load, std::size_t cases,
               const std::function<SweepPoint(std::size_t)>& point, int threads,
               const std::function<void(std::size_t, SweepRow&&)>& sink,
               const SweepProgress& progress = {});

/// Every point's row at once, in the order of `points` (the streaming run_sweep above, collected).
std::vector<SweepRow> run_sweep(const SweepLoader& load, const std::vector<SweepPoint>& points,
                                int threads, const SweepProgress& progress = {});

/// sweep.csv: the varied keys (SI), `status` (ok/failed), `error`, then for each ring channel of
/// the first successful row `<ch>.rms,<ch>.ptp,<ch>.kurtosis,<ch>.crest,<ch>.peak_frequency,
/// <ch>.peak_label`, and with an [acoustics] table per microphone i = 1… `mic<i>.spl_total,
/// mic<i>.spl_ring,mic<i>.spl_balls` [dB re 20 µPa]. Failed rows, and levels that do not exist
/// (source "none", silence), leave their fields empty.
std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows);

/// sweep_csv's text, written as the rows come (in case order) to `out`. The columns follow the
/// first successful row, so failed rows before it are held (their values and message) until it
/// comes, or until finish() if none does; every other row is formatted and passed on at once.
class SweepCsvWriter {
 public:
  SweepCsvWriter(const std::vector<SweepAxis>& axes, std::function<void(std::string_view)> out);
  void add(const SweepRow& row);
  /// Writes what is still held (a sweep where no case succeeded). Call once, after the last row.
  void finish();

 private:
  void start(const SweepRow* first_ok);
  void write_row(const SweepRow& row);
  std::vector<std::string> keys_;
  std::function<void(std::string_view)> out_;
  bool started_ = false;
  std::vector<std::string> channels_;  ///< ring channels of the first successful row
  std::size_t microphones_ = 0;
  std::vector<SweepRow> held_;  ///< failed rows before the first successful one
  std::string line_;
};

/// Counts of a sweep written by write_sweep.
struct SweepCounts {
  std::size_t cases = 0;
  std::size_t failed = 0;
};

/// A function with the streaming run_sweep's signature (run_sweep, or run_sweep_mpi).
using SweepRunner = std::function<void(
    const SweepLoader&, std::size_t, const std::function<SweepPoint(std::size_t)>&, int,
    const std::function<void(std::size_t, SweepRow&&)>&, const SweepProgress&)>;

/// `bearing-sim sweep`: runs every case of the axes' product (with `runner`; empty: run_sweep) and
/// streams the rows to `dir`/sweep.csv (created if missing) under a temporary name, renamed into
/// place only when every row is written; on any failure the temporary file is removed and nothing
/// else is touched. Throws InputError if the folder or the file cannot be written.
SweepCounts write_sweep(const std::string& dir, const std::vector<SweepAxis>& axes,
                        const SweepLoader& load, int threads, const SweepProgress& progress = {},
                        const SweepRunner& runner = {});

}  // namespace bearing
