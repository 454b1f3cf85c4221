#pragma once
// `bearing-sim sweep`: many variants of one case, run in parallel, one summary row each.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"
#include "bearing/sweep_columns.h"
#include "bearing/sweep_design.h"
#include "bearing/sweep_row.h"
#include "bearing/sweep_tables.h"

namespace bearing {

/// Parses `KEY=FROM:TO:N`; FROM and TO may carry units ("1000rpm:3000rpm:5"; a plain number is
/// SI, except for angles and speeds: "0:200:3" N of operation.axial_load), N in 1…100000.
/// Throws InputError naming `--vary`, the text and what is allowed.
SweepAxis parse_vary(std::string_view text);

/// The number of cases: the product of the axes' sizes (0 without axes). Throws InputError if
/// it does not fit a std::size_t.
std::size_t sweep_size(const std::vector<SweepAxis>& axes);

/// Case `index` (0 ≤ index < sweep_size(axes)) of the Cartesian product of the axes, the first
/// axis varying slowest; computed from the index alone, so a sweep never holds all its points.
SweepPoint sweep_point(const std::vector<SweepAxis>& axes, std::size_t index);

/// Every case of the Cartesian product at once (sweep_point for each index).
std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes);

/// Builds the case of a point: the base file + the point's overrides.
using SweepLoader = std::function<Case(const std::vector<Override>&)>;
/// Called with (cases done, cases in all), serialised.
using SweepProgress = std::function<void(std::size_t, std::size_t)>;

/// Runs cases 0 … `cases` − 1 (`point(i)` gives case i) with `threads` workers (0: all cores) and
/// hands each row to `sink(i, row)` in case order, serialised, as soon as the rows before it are
/// done. A worker starts case i only while i < (rows handed over) + 4 × workers, so at most that
/// many finished rows wait for an earlier one: memory does not grow with the number of cases. A
/// failed case is reported in its row and does not stop the others; an exception from `sink`
/// stops the sweep (no new cases start) and is rethrown once the running ones are done. With
/// `save` each successful row also holds those tables of its run (SweepRow::tables), built on the
/// worker's thread: memory stays bounded by the same window.
void run_sweep(const SweepLoader& load, std::size_t cases,
               const std::function<SweepPoint(std::size_t)>& point, int threads,
               const std::function<void(std::size_t, SweepRow&&)>& sink,
               const SweepProgress& progress = {}, const std::vector<SweepSave>& save = {});

/// A function with run_sweep's signature (the threads of one process, or MPI ranks).
using SweepRunner = std::function<void(const SweepLoader&, std::size_t,
                                       const std::function<SweepPoint(std::size_t)>&, int,
                                       const std::function<void(std::size_t, SweepRow&&)>&,
                                       const SweepProgress&, const std::vector<SweepSave>&)>;

/// Every point's row at once, in the order of `points` (the streaming run_sweep above, collected).
std::vector<SweepRow> run_sweep(const SweepLoader& load, const std::vector<SweepPoint>& points,
                                int threads, const SweepProgress& progress = {});

/// sweep.csv: the varied keys (SI), `status` (ok/failed), `error`, then the columns of the first
/// successful row (sweep_columns.h): per ring channel `<ch>.rms,<ch>.ptp,<ch>.kurtosis,<ch>.crest,
/// <ch>.peak_frequency,<ch>.peak_label`, with an [acoustics] table per microphone i = 1…
/// `mic<i>.spl_total,mic<i>.spl_ring,mic<i>.spl_balls` [dB re 20 µPa], with output.envelope_band
/// per ring acceleration `env_<ch>.…` and `diagnosis.…`. Failed rows, and levels that do not exist
/// (source "none", silence), leave their fields empty.
std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows);

/// sweep_csv's text, written as the rows come (in case order) to `out`. The columns follow the
/// first successful row, so failed rows before it are held (their values and message) until it
/// comes, or until finish() if none does; every other row is formatted and passed on at once.
class SweepCsvWriter {
 public:
  SweepCsvWriter(const std::vector<SweepAxis>& axes, std::function<void(std::string_view)> out);
  SweepCsvWriter(std::vector<std::string> keys, std::function<void(std::string_view)> out);
  /// Continues a file that already holds `header` (its first line, without the newline): the
  /// columns are taken from it and no header is written. Call before the first add().
  void continue_after(std::string_view header);
  void add(const SweepRow& row);
  /// Writes what is still held (a sweep where no case succeeded). Call once, after the last row.
  void finish();

 private:
  void start(const SweepRow* first_ok);
  void write_row(const SweepRow& row);
  std::vector<std::string> keys_;
  std::function<void(std::string_view)> out_;
  bool started_ = false;
  SweepColumns columns_;        ///< those of the first successful row
  std::vector<SweepRow> held_;  ///< failed rows before the first successful one
  std::string line_;
};

/// A further output of write_sweep beside sweep.csv (e.g. sweep.h5 of `--save`): `add(i, row)`
/// gets every row in case order with the tables `save` names (SweepRow::tables, built where the
/// case ran, on any runner); `commit()` runs once after the last row and before sweep.csv is
/// renamed into place. An exception from either stops the sweep, and sweep.csv is not written.
struct SweepRowHook {
  std::vector<SweepSave> save;
  std::function<void(std::size_t, const SweepRow&)> add;
  std::function<void()> commit;
};

/// Counts of a sweep written by write_sweep.
struct SweepCounts {
  std::size_t cases = 0;
  std::size_t failed = 0;
};

/// The base case of a sweep as it was read: the case file's text (or the built-in default's),
/// its name in messages, the folder its tables are found in, and the --set overrides. Every case
/// of the sweep is parse_case(text, source, overrides + point, base_dir), at the start and on
/// --resume alike.
struct SweepBase {
  std::string source;
  std::string text;
  std::string base_dir;
  std::vector<Override> overrides;
};

/// Reads CASE (empty: the built-in default case) as read_case_file would; checks that the base
/// case with `overrides` resolves. Throws InputError.
SweepBase sweep_base(const std::string& case_path, std::vector<Override> overrides);

/// The base case with a point's overrides after the base's.
Case load_sweep_case(const SweepBase& base, const std::vector<Override>& point);

/// `--part K/N`: the K-th (1 … N) of N contiguous blocks of the design's cases.
struct SweepPart {
  std::size_t index = 1;
  std::size_t count = 1;
};

/// Parses "K/N" (1 ≤ K ≤ N ≤ 10^6). Throws InputError naming --part and the text.
SweepPart parse_part(std::string_view text);

/// The cases [first, end) of `part` of a design of `cases` cases: first = ⌊cases·(K−1)/N⌋.
std::pair<std::size_t, std::size_t> part_range(std::size_t cases, SweepPart part);

/// Everything a sweep folder needs to be run, resumed or merged: recorded at the start in
/// DIR/sweep.design.json.
struct SweepPlan {
  std::shared_ptr<const SweepDesign> design;
  SweepBase base;
  SweepPart part;
  std::string program;  ///< e.g. "bearing-sim 0.1.0"; parts of one design must agree
};

/// The plan as the JSON text of sweep.design.json (format, program, design, cases, base with
/// its resolved TOML, part with its first and end case).
std::string sweep_record(const SweepPlan& plan);

/// Reads DIR/sweep.design.json back. Throws InputError naming the file.
SweepPlan read_sweep_record(const std::string& dir);

/// Runs the plan's cases (all, or its part) into DIR (created if missing): writes
/// DIR/sweep.design.json, streams the rows to DIR/.sweep.csv.partial (flushed row by row) and
/// renames it to DIR/sweep.csv when every row is in. A whole sweep then removes the record (only
/// sweep.csv is left); a part keeps it for `merge`. With `resume`, the complete rows already in
/// the temporary file are kept (a truncated last line is dropped) and only the others run (all of
/// them without a temporary file; resume_sweep() first checks whether the sweep has finished).
/// On an error the temporary file and the record stay, for --resume. `runner` defaults to
/// run_sweep (an MPI runner with its signature may take its place). Throws InputError.
/// With `hook.add` (a further output, e.g. `--save`'s sweep.h5) every row also goes to the hook
/// with its tables, on any runner, before its line is written: on `resume` every kept row has been
/// given to the hook.
SweepCounts write_sweep(const std::string& dir, const SweepPlan& plan, int threads,
                        const SweepProgress& progress = {}, const SweepRunner& runner = {},
                        bool resume = false, const SweepRowHook& hook = {});

/// The counts of the sweep in DIR if its sweep.csv is complete: sweep.csv is there, no
/// `.sweep.csv.partial` (a sweep into DIR that stopped, or is running), and if the design record is
/// there (a part keeps it; a whole sweep removes it at the end) sweep.csv has as many rows as its
/// part has cases (otherwise the record is of a sweep killed before its first row). Nullopt if not.
/// Reads every row (the failed ones are counted). Throws InputError for an unreadable record.
std::optional<SweepCounts> finished_sweep(const std::string& dir);

/// `bearing-sim sweep --resume DIR`: the plan read back from DIR, then write_sweep(resume). A
/// finished sweep (finished_sweep()) is left as it is: its counts are returned, nothing runs.
SweepCounts resume_sweep(const std::string& dir, int threads, const SweepProgress& progress = {},
                         const SweepRunner& runner = {}, const SweepRowHook& hook = {});

/// `bearing-sim merge OUT DIR…`: checks that the folders hold complete parts of one design (the
/// same record but for the part; every part once, none missing) and writes OUT/sweep.csv, the
/// same bytes as one run of the whole design. Returns the counts. Throws InputError naming the
/// folder and what differs.
SweepCounts merge_sweeps(const std::string& out, const std::vector<std::string>& dirs);

}  // namespace bearing
