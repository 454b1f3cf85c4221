#pragma once
// What the user says about a measured record where the file does not (`bearing-sim analyse`'s
// --channel, --rate, --unit, --scale, --dataset). The reader checks every field against the file:
// an option the file contradicts is an input error, not a silent choice.

#include <optional>
#include <string>

namespace bearing {

struct RecordOptions {
  /// The variable (.mat), column (.csv, .npy, a 2-D .h5 dataset) or channel (.wav) to read;
  /// empty: the file's only one. Unnamed channels (a .npy's or .wav's, a CSV without header) are
  /// named by their index from 0: "0", "1", ...
  std::string channel;
  /// The sampling rate [Hz], finite and > 0, for files that do not state one (.mat, .npy, a CSV
  /// without time column); where the file states one (a WAV header, a CSV time column, an HDF5
  /// rate attribute) it must agree with it, and is then the value used.
  std::optional<double> rate;
  /// The unit of the stored values times `scale`: "g", "m/s^2", "m/s" or "m" (kRecordUnits);
  /// empty: the file's (a CSV header "DE [g]", an HDF5 unit attribute), which it must agree with
  /// when both are given. Integer PCM WAV values are read as fractions of full scale (±1), so
  /// there `unit` is the unit of full scale, and `scale` the full scale in it (e.g. 50 for ±50 g).
  std::string unit;
  /// Stored value × scale = value in `unit` (a sensor sensitivity, a recorder's full scale);
  /// finite and nonzero; 1 by default. A negative scale flips the sensor's sign.
  double scale = 1.0;
  /// .h5 only: the path of the dataset to read ("/run3/accel"); empty: the file's only numeric
  /// dataset of rank 1 or 2.
  std::string dataset;
};

}  // namespace bearing
