#pragma once
// The benchmark method (issue 41): the yardstick bearing-sim analyse must beat on measured records,
// written deliberately simply and apart from the toolkit's analysis — cepstral pre-whitening and
// the squared envelope spectrum over the full band (Randall & Antoni, MSSP 25, 2011; Smith &
// Randall, MSSP 64–65, 2015, "benchmark method"), and an automatic call in place of the expert's
// eye.
//
// 1. Cepstral pre-whitening: the real cepstrum set to zero but at quefrency 0, i.e. every
//    frequency bin's magnitude set to one, X_k / |X_k|, keeping its phase (the mean removed).
// 2. The squared envelope over the full band: |a(t)|², a the analytic signal of the whitened
//    record; its spectrum, the SES, |E_k| / N.
// 3. The call. For each family — outer race at BPFO, inner race at BPFI, ball at 2·BSF — and each
//    of its first three harmonics h f_F, the SES's largest bin within ±2 % of h f_F (the slip
//    window: 1–2 % slip, Randall & Antoni) against the median of the bins within ±f_F/2 of it.
//    Under the null — a whitened Gaussian record — an SES bin's power |E_k|² is exponential, so
//    its mean is the median / ln 2, and the largest of W bins exceeds t times that mean with
//    probability p = 1 − (1 − e^(−t))^W. A harmonic "stands out" when its window's largest bin
//    exceeds the t of p; a family is detected when at least two of its three harmonics stand out,
//    which under the null happens with probability 3p² − 2p³ = α, the stated false-alarm rate per
//    family (default 1e-3). The verdict is the detected family with the most harmonics standing
//    out (then the larger summed excess in dB); none if none is detected.
//
// Its known weakness, kept: a whole-record FFT leaks a strong line over hundreds of bins whose
// phases stay coherent after whitening, so discrete lines several dB above the whole broadband
// noise (a strong shaft harmonic, the supply) can stand out in the SES at their differences.
//
// That is the whole method: no band selection, no speed search, no sidebands, no second
// opinion. It is a reference, not a product: `bearing-verify`'s measured family compares the
// toolkit's verdicts with it record by record.

#include <array>
#include <string>
#include <vector>

namespace bearing::verify {

/// The benchmark's evidence for one family.
struct BenchmarkFamily {
  std::string family;              ///< "outer", "inner" or "ball"
  double rate = 0;                 ///< f_F [Hz]: BPFO, BPFI or 2·BSF
  std::array<double, 3> excess{};  ///< each harmonic's largest bin over the floor's mean [dB]
  std::array<double, 3> found{};   ///< where each harmonic's largest bin is [Hz]
  double threshold = 0;            ///< t of p for that window, the largest of the three [dB]
  int standing_out = 0;            ///< harmonics over their threshold (0–3)
  bool detected = false;           ///< at least two of three
};

/// The benchmark's verdict on one record.
struct BenchmarkVerdict {
  std::string family;  ///< "outer", "inner", "ball" or "none"
  std::vector<BenchmarkFamily> families;
  double false_alarm = 0;   ///< α per family
  std::size_t samples = 0;  ///< used (the record cut to a fast FFT length)
};

/// The defect rates as multiples of the shaft frequency (BPFO/f_r, BPFI/f_r, 2·BSF/f_r).
struct DefectMultiples {
  double bpfo = 0, bpfi = 0, ball = 0;
};

/// The benchmark method on a record x [any unit] sampled at `rate` [Hz], the shaft at `shaft` [Hz];
/// α the false-alarm rate per family, in (0, 0.5). Throws InputError on a record too short to hold
/// three harmonics of every family (fewer than 64 samples, or 3.2 · the largest rate above the
/// Nyquist frequency) or on non-finite values.
BenchmarkVerdict benchmark_method(const std::vector<double>& x, double rate, double shaft,
                                  const DefectMultiples& multiples, double false_alarm = 1e-3);

/// The squared envelope spectrum of step 2 (|E_k| / N, k = 0 … N/2; bin spacing rate / N), for
/// tests and figures.
std::vector<double> benchmark_ses(const std::vector<double>& x);

/// t such that the largest of `window` exponential bins exceeds t times their mean with
/// probability p: t = −ln(1 − (1 − p)^(1/W)).
double exceedance_threshold(double p, int window);

/// p such that at least two of three independent harmonics exceed with probability α: the root in
/// (0, 1) of 3p² − 2p³ = α.
double per_harmonic_probability(double false_alarm);

}  // namespace bearing::verify
