#pragma once
// Cepstral pre-whitening: a record's spectrum flattened to one magnitude with every phase kept,
// which removes what is stationary and discrete (shaft harmonics, gear mesh, the rig's own lines,
// the resonances' shape) and leaves the impacts of a local fault as impulses. It is the editing of
// the real cepstrum to zero everywhere but at quefrency 0 (R. B. Randall and N. Sawalhi, "A new
// method for separating discrete components from a signal", Sound and Vibration 45(5), 2011; J.
// Antoni and R. B. Randall); on the Case Western Reserve University bearing data it is the first
// step of the benchmark method (W. A. Smith and R. B. Randall, "Rolling element bearing
// diagnostics using the Case Western Reserve University data: a benchmark study", Mech. Syst.
// Signal Process. 64–65, 2015, 100–131).

#include <vector>

namespace bearing {

/// The pre-whitened record y of x (N samples, any unit):
///
///   X = DFT(x),   Y_k = a · X_k / |X_k|  (k ≥ 1),   Y_0 = 0,   y = IDFT(Y),
///
/// x → FFT → unit magnitude, phase kept → IFFT, with the DFT of fft.h at the record's own length
/// (no window, no padding: the phase of every bin is the record's). DC is dropped (y has zero
/// mean). Energy: a = √(E / M), E = Σ_{k=1}^{N−1} |X_k|² (over all N bins but DC) and M the
/// number of those bins that are kept, so Σ y² = Σ (x − x̄)²: y has x's unit and x's RMS (a
/// white record stays about the same; the envelope amplitudes after pre-whitening are those of a
/// record of equal RMS with a flat spectrum). A bin with |X_k| ≤ 1e-13 max|X| holds rounding only
/// and has no phase to keep: Y_k = 0 there. So |DFT(y)_k| = a exactly (to rounding) for every
/// other bin, and an impulse A δ_{n,n0} (flat already) gives A (δ_{n,n0} − 1/N): itself, mean
/// removed. A constant record gives zeros.
/// Throws InputError if N < 2 or a sample is NaN or infinite. O(N log N): two real FFTs.
std::vector<double> cepstral_prewhiten(const std::vector<double>& x);

}  // namespace bearing
