#pragma once
// One-sided amplitude spectrum of a sampled channel (docs/model.md §7), scaled so that a sinusoid
// of amplitude A shows as A, whatever the window.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/choice.h"
#include "bearing/signal/fft.h"

namespace bearing {

/// Window applied before the FFT. All three are periodic (DFT-even: w_j for j = 0 … N−1 with
/// z = 2πj/N), so each is a cosine sum whose DFT is non-zero on only a few bins.
///  - hann: 0.5 − 0.5 cos z. Default: narrow main lobe (±2 bins), good frequency resolution, but
///    up to −1.42 dB (−15 %) amplitude error for a tone halfway between bins.
///  - flattop: HFT90D of Heinzel, Rüdiger & Schilling, "Spectrum and spectral density estimation by
///    the Discrete Fourier transform (DFT), including a comprehensive list of window functions and
///    some new flat-top windows", Max-Planck-Institut für Gravitationsphysik, 2002, §D:
///    1 − 1.942604 cos z + 1.340318 cos 2z − 0.440811 cos 3z + 0.043097 cos 4z. Amplitude flat to
///    0.0039 dB (0.045 %) anywhere between bins, −90 dB sidelobes, main lobe ±5 bins wide.
///  - rectangular: w = 1. Exact only on bins; up to −3.9 dB (−36 %) between bins, and leaks.
enum class Window { hann, flattop, rectangular };
inline constexpr Named<Window> kWindows[] = {
    {Window::hann, "hann"}, {Window::flattop, "flattop"}, {Window::rectangular, "rectangular"}};

/// The window named "hann", "flattop" or "rectangular" (exact spelling). `key` is the case-file
/// key the name came from, used in the message. Throws InputError for any other name, listing the
/// allowed ones and suggesting the nearest.
Window parse_window(std::string_view name, const std::string& key);

/// The name parse_window accepts for `window`.
std::string_view window_name(Window window);

/// One-sided amplitude spectrum: bin k at frequency k·fs/N, k = 0 … ⌊N/2⌋.
struct Spectrum {
  std::vector<double> frequency;  ///< bin frequencies 0 … fs/2 (or just below it for odd N) [Hz]
  std::vector<double> amplitude;  ///< one-sided amplitude [unit of x]
  double resolution = 0;          ///< bin spacing fs / N [Hz]
};

/// One-sided amplitude spectrum of x [unit of x] sampled at `sample_rate` [Hz].
///
/// The mean is removed (so the DC bin shows only what the window leaks there), the signal is
/// windowed, transformed at its own length N (no zero padding, so the bins are k·fs/N for any
/// N ≥ 2) and scaled by 1 / (N · coherent gain) with coherent gain Σw/N, every bin but DC and
/// Nyquist doubled. So A sin(2π f t + φ) with f = k·fs/N on a bin shows amplitude A at bin k
/// exactly (to rounding) for every window, provided the
/// window's main lobe (half-width h = 0 rectangular, 1 hann, 4 flattop [bins]) does not reach the
/// tone's mirror image at −k or N − k: 2k > h and N − 2k > h. Between bins the largest bin is
/// within 0.0039 dB (~0.05 %) of A only for flattop; see Window for the others. A record holding
/// a non-whole number of periods has a sample mean of its own (at most A/(π·periods)); removing it
/// leaves that constant, spread by the window over bins 0 … h.
///
/// The DFT is RealFft (fft.h): O(N log N) for any N, about 1 ms for N = 24000 and 5 ms for the
/// prime 24001. The FFT tables are local to the call (thread-safe); for
/// several channels of one length, SpectrumPlan builds them (and the window) once.
/// Throws InputError if N < 2, a sample is NaN or infinite, or sample_rate is not positive and
/// finite.
Spectrum amplitude_spectrum(const std::vector<double>& x, double sample_rate,
                            Window window = Window::hann);

/// amplitude_spectrum() for many signals of one length N, sample rate and window: the window and
/// the FFT tables are built once, by the constructor (about half the cost of one spectrum at
/// N = 20000). Same result as amplitude_spectrum(), same errors (N and the rate checked here, the
/// samples and their count by operator()). operator() uses the plan's scratch space: one plan per
/// thread.
class SpectrumPlan {
 public:
  SpectrumPlan(std::size_t n, double sample_rate, Window window);
  ~SpectrumPlan();
  SpectrumPlan(SpectrumPlan&&) noexcept;
  SpectrumPlan& operator=(SpectrumPlan&&) noexcept;

  /// The spectrum of x (x.size() must be N).
  Spectrum operator()(const std::vector<double>& x);

 private:
  std::size_t n_;
  double sample_rate_;
  std::vector<double> window_;
  double window_sum_ = 0;  // N × coherent gain
  std::unique_ptr<RealFft> dft_;
};

}  // namespace bearing
