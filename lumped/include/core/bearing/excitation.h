#pragma once
// Excitations shared by every model (docs/model.md §5): raceway waviness, ball-size errors.
// Sign convention (docs/model.md §1): a deviation is radial, positive toward the ball (more
// material, more approach), on either race; a smaller ball reduces the approach by ΔD_j = D − D_j.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/bearing.h"

namespace bearing {

struct WavinessHarmonic {
  int order = 0;           ///< N_s, waves per revolution (≥ 1)
  double amplitude = 0.0;  ///< A_s [m] (≥ 0)
  double phase = 0.0;      ///< ψ_s [rad]
};

/// Waviness of one race: Π(φ) = Σ_s A_s sin(N_s φ + ψ_s), φ the race-fixed angle of the contact.
struct Waviness {
  std::vector<WavinessHarmonic> harmonics;

  bool empty() const { return harmonics.empty(); }
  /// Π(φ) [m].
  double profile(double phi) const;
  /// dΠ/dφ [m/rad].
  double slope(double phi) const;
  /// d²Π/dφ² [m/rad²].
  double second_derivative(double phi) const;
  /// Highest order present (0 if none).
  int max_order() const;
};

/// Reads a waviness table: CSV rows `order,amplitude[,phase]`, amplitude in micrometres and phase
/// in degrees unless the header names other units (`amplitude_m`, `amplitude_um`, `phase_rad`,
/// `phase_deg`); '#' starts a comment. Throws InputError naming `key`, the file, the line and
/// the value for anything malformed (order < 1, negative or non-finite amplitude, wrong columns).
std::vector<WavinessHarmonic> read_waviness_table(const std::string& path, const std::string& key);

/// The table's text parsed as read_waviness_table does; `path` only names it in messages (the
/// file is read by read_waviness_table, fuzzed and tested without one).
std::vector<WavinessHarmonic> parse_waviness_table(std::string_view text, const std::string& path,
                                                   const std::string& key);

/// The rules for waviness harmonics on a race of `bearing` (the case key `key`,
/// "waviness.inner"): order in [1, 100000], amplitude in [0, D/100) (waviness is a few µm at
/// most), phase finite. Throws InputError naming key[i] and the field.
void check_waviness(const std::vector<WavinessHarmonic>& harmonics, const Bearing& bearing,
                    const std::string& key);

/// The rules for ball-size errors ΔD_j = D − D_j [m]: none, or one per ball, each finite with
/// |ΔD_j| < D/100. Throws InputError naming ball_errors.values[j] (shown as D_j − D).
void check_ball_size_errors(const std::vector<double>& errors, const Bearing& bearing);

/// Ball-size deviations ΔD_j = D − D_j [m] drawn uniformly in [−band/2, band/2] (so the diameters
/// spread over `band`) from a 64-bit seed; the same seed gives the same values on every machine
/// (own generator, not std:: distributions, whose output is implementation-defined).
std::vector<double> ball_size_errors_from_band(int balls, double band, std::uint64_t seed);

}  // namespace bearing
