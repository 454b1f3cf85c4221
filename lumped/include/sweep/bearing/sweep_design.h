#pragma once
// The designs of `bearing-sim sweep`: which cases a sweep runs. A design is a list of cases,
// each computed from its index alone (point(i)), so a sweep never holds all its points and any
// block of it (a --part, a --resume) sees the same values as the whole.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/case_file.h"

namespace bearing {

/// One varied key: `KEY=FROM:TO:N`, N values spaced linearly from FROM to TO inclusive.
struct SweepAxis {
  std::string key;  ///< case-file key, e.g. "operation.speed", "waviness.inner.0.amplitude"
  std::vector<double> values;  ///< SI values
  Dimension dimension = Dimension::dimensionless;
  bool integer = false;  ///< the key takes whole numbers (values must come out whole)
};

/// A key a design sets, with what its values are (the columns of sweep.csv before `status`).
struct SweepKey {
  std::string key;
  Dimension dimension = Dimension::dimensionless;
  bool integer = false;
};

/// The override text that sets `key` to the SI value `v` (whole numbers plain; angles and speeds
/// with their SI unit, since the case reader needs one).
std::string sweep_value_text(double v, const SweepKey& key);

/// One case of the sweep: the value of every key and the overrides that set them.
struct SweepPoint {
  std::vector<double> values;
  std::vector<Override> overrides;
};

/// Which cases a sweep runs: size() cases, case i (0 ≤ i < size()) from point(i) alone.
class SweepDesign {
 public:
  virtual ~SweepDesign() = default;
  virtual std::size_t size() const = 0;
  /// The keys each point sets, in column order.
  virtual const std::vector<SweepKey>& keys() const = 0;
  virtual SweepPoint point(std::size_t index) const = 0;
  /// The design as JSON text (kind and everything needed to rebuild it; see design_from_json).
  virtual std::string json() const = 0;
};

/// `--vary`: the Cartesian product of the axes, the first axis varying slowest.
std::unique_ptr<SweepDesign> grid_design(std::vector<SweepAxis> axes);

/// One `--sample KEY=DIST(...)`: a key drawn from uniform(a, b), normal(mean, sd) or
/// loguniform(a, b) (0 < a ≤ b), parameters in SI.
struct SweepSample {
  SweepKey key;
  std::string distribution;  ///< "uniform" | "normal" | "loguniform"
  double p1 = 0, p2 = 0;     ///< (a, b) or (mean, sd), SI
};

/// Parses `KEY=DIST(P1, P2)`; the parameters may carry units ("uniform(1000rpm, 3000rpm)").
/// Throws InputError naming `--sample`, the text and what is allowed.
SweepSample parse_sample(std::string_view text);

/// `--sample … --samples N --seed S`: N cases, case i's value of each key drawn by a
/// counter-based generator from (seed, i, key) alone — the same on any --jobs, --part or
/// --resume. A whole-number key takes round(value) (uniform: each whole number in [a, b] equally
/// likely).
std::unique_ptr<SweepDesign> random_design(std::vector<SweepSample> samples, std::size_t cases,
                                           std::uint64_t seed);

/// `--cases FILE.csv`: a header of keys, then one row per case (numbers in SI or with units).
/// Throws InputError naming the file, the line and the key.
std::unique_ptr<SweepDesign> list_design_from_csv(const std::string& path);

/// Rebuilds a design from its json() text. Throws InputError if the text is not one.
std::unique_ptr<SweepDesign> design_from_json(const std::string& json_text);

/// The uniform number in (0, 1) number `stream` (0, 1, …) of case `index` for `key` under `seed`:
/// SplitMix64 of the four together, so it depends on nothing else.
double sweep_uniform(std::uint64_t seed, std::size_t index, std::string_view key,
                     std::uint64_t stream);

}  // namespace bearing
