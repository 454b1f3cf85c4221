#pragma once
// What the acoustics of a run is asked for (the case file's [acoustics] table, docs/model.md §8):
// microphones, which source model stands for the inner ring and for each ball, how their
// pressures add up, and the air.

#include <vector>

#include "bearing/acoustics/pressure.h"
#include "bearing/choice.h"

namespace bearing {

/// A microphone in the bearing plane, in the fixed frame with its origin at the bearing centre.
struct Microphone {
  double radius = 0.0;  ///< distance from the bearing centre [m]
  double angle = 0.0;   ///< from +x towards +y (up) [rad]
};

/// The inner ring as a sound source.
enum class RingSource {
  cylinder_dipole,  ///< an infinite cylinder translating with the ring, exact in ka
  paper,            ///< seed 000's eq. 19: the low-ka cylinder as derived there
  none,
};
inline constexpr Named<RingSource> kRingSources[] = {
    {RingSource::cylinder_dipole, "cylinder-dipole"},
    {RingSource::paper, "paper"},
    {RingSource::none, "none"}};

/// Each ball as a sound source, driven by its centre's radial velocity.
enum class BallSource {
  oscillating_sphere,  ///< a translating rigid ball, exact in ka (the FE reference supports it)
  pulsating_sphere,    ///< seed 000's choice, exact in ka
  paper,               ///< seed 000's eq. 23
  none,
};
inline constexpr Named<BallSource> kBallSources[] = {
    {BallSource::oscillating_sphere, "oscillating-sphere"},
    {BallSource::pulsating_sphere, "pulsating-sphere"},
    {BallSource::paper, "paper"},
    {BallSource::none, "none"}};

/// The make_source name of a source model ("cylinder-dipole-paper" for the ring's "paper",
/// "pulsating-sphere-paper" for the balls'; "none" for none).
inline const char* source_model_name(RingSource source) {
  return source == RingSource::paper ? "cylinder-dipole-paper" : name_of(kRingSources, source);
}
inline const char* source_model_name(BallSource source) {
  return source == BallSource::paper ? "pulsating-sphere-paper" : name_of(kBallSources, source);
}

/// Sound radiated by the inner ring and the balls; on when the case has an [acoustics] table.
struct AcousticsOptions {
  bool enabled = false;
  RingSource ring_source = RingSource::cylinder_dipole;
  /// The default is the oscillating sphere because the FE field of a translating ball matches it,
  /// while it lies 7–30 dB below the pulsating sphere (fem/README.md).
  BallSource ball_source = BallSource::oscillating_sphere;
  Summation summation = Summation::coherent;  ///< coherent: sum of pressures; energetic: seed 000
  std::vector<Microphone> microphones;        ///< at least one when enabled
  double ring_radius = 0.0;                   ///< radiating radius of the inner ring [m]
  double density = 1.204;                     ///< air density ρ₀ [kg/m^3] (20 °C, 1 atm)
  double sound_speed = 343.2;                 ///< speed of sound c₀ [m/s] (20 °C)
};

}  // namespace bearing
