// The contact kernels of contact_kernels.h: Highway's per-target code (this file is compiled once
// per instruction set through foreach_target.h) and the scalar reference.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "contact_kernels.h"
#include "inline_contacts.h"
#include "phasor.h"

// Once, before the per-target code (foreach_target.h includes this file once per target).
#ifndef BEARING_CONTACT_KERNELS_SHARED
#define BEARING_CONTACT_KERNELS_SHARED
namespace bearing::detail {
// The planar balls one at a time (below), for targets with fewer than kPlanarLanes lanes too.
void planar_balls_scalar(const PlanarBalls& in, double x, double y, double* ring, double* radial,
                         double* torque);
// The ring force from its kPlanarLanes lane sums, in one fixed order for every target.
inline double planar_ring_sum(double start, const double* lanes) {
  static_assert(kPlanarLanes == 4, "the order below adds four lanes");
  return start + ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3]));
}
}  // namespace bearing::detail
#endif

#ifndef BEARING_WITHOUT_HIGHWAY
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "models/contact_kernels.cc"  // this file, from lumped/src
#include <hwy/foreach_target.h>                         // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace bearing::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// At most 8 lanes: one byte of mask bits, and the padding of kKernelPad.
using Tag = hn::CappedTag<double, kKernelPad>;

void RotateBallsImpl(const double* HWY_RESTRICT base_cos, const double* HWY_RESTRICT base_sin,
                     double cos_phi, double sin_phi, int Z, double* HWY_RESTRICT cos_theta,
                     double* HWY_RESTRICT sin_theta) {
  const Tag d;
  const auto cp = hn::Set(d, cos_phi), sp = hn::Set(d, sin_phi);
  const auto n = static_cast<std::size_t>(Z);
  for (std::size_t j = 0; j < n; j += hn::Lanes(d)) {
    const auto bc = hn::LoadU(d, base_cos + j), bs = hn::LoadU(d, base_sin + j);
    hn::StoreU(hn::Sub(hn::Mul(bc, cp), hn::Mul(bs, sp)), d, cos_theta + j);
    hn::StoreU(hn::Add(hn::Mul(bs, cp), hn::Mul(bc, sp)), d, sin_theta + j);
  }
}

void RadialContactsImpl(const double* HWY_RESTRICT cos_theta, const double* HWY_RESTRICT sin_theta,
                        const double* HWY_RESTRICT excitation, const double* HWY_RESTRICT stiffness,
                        int Z, double x, double y, double gap, double* fx, double* fy) {
  const Tag d;
  const auto vx = hn::Set(d, x), vy = hn::Set(d, y), vgap = hn::Set(d, gap);
  const auto zero = hn::Zero(d);
  HWY_ALIGN double qc[kKernelPad];
  HWY_ALIGN double qs[kKernelPad];
  double sx = *fx, sy = *fy;
  const auto n = static_cast<std::size_t>(Z);
  for (std::size_t j = 0; j < n; j += hn::Lanes(d)) {
    const auto c = hn::LoadU(d, cos_theta + j), s = hn::LoadU(d, sin_theta + j);
    const auto delta = hn::Add(hn::Sub(hn::Add(hn::Mul(vx, c), hn::Mul(vy, s)), vgap),
                               hn::LoadU(d, excitation + j));
    const auto loaded = hn::And(delta > zero, hn::FirstN(d, n - j));
    if (hn::AllFalse(d, loaded)) continue;  // most balls are unloaded under a radial load
    const auto dp = hn::IfThenElseZero(loaded, delta);
    const auto q = hn::Mul(hn::Mul(hn::LoadU(d, stiffness + j), dp), hn::Sqrt(dp));
    hn::Store(hn::Mul(q, c), d, qc);
    hn::Store(hn::Mul(q, s), d, qs);
    uint8_t bits[8] = {};
    hn::StoreMaskBits(d, loaded, bits);
    // The loaded balls in ball order, as the scalar loop adds them.
    for (unsigned b = bits[0]; b != 0; b &= b - 1) {
      const int k = __builtin_ctz(b);
      sx -= qc[k];
      sy -= qs[k];
    }
  }
  *fx = sx;
  *fy = sy;
}

// The planar balls in vectors of 4 (AVX2's width, also on AVX-512 machines: 7 to 9 balls are
// common). The last vector ends at the last ball and overlaps the one before, so no load or store
// passes the arrays' end (the ball DOFs sit in the integrator's state vectors); its lanes already
// done are stored again with the same values and add zero to the ring sums. The ring force is
// summed lane-wise and the four lanes added last (planar_ring_sum): a dependency chain of two
// vector additions and three scalar ones instead of one addition per ball (issue 42). Needs
// Z >= 4 (contact_kernels() gives the scalar loop for fewer balls); a target with narrower
// vectors runs the scalar loop, which adds in the same order, so every target gives its bits.
using PlanarTag = hn::CappedTag<double, kPlanarLanes>;

// ring = (fx, fy) + planar_ring_sum of the lanes of (sx, sy): x and y side by side in the two
// lanes of 128-bit vectors, stored as one pair. Targets of fewer than kPlanarLanes lanes never
// call it (their kernel is the scalar loop), so they do not compile it.
template <class D, class V>
void StoreRingSums(D d, V sx, V sy, double fx, double fy, double* HWY_RESTRICT ring) {
#if HWY_TARGET != HWY_SCALAR  // one lane: no halves
  if constexpr (hn::MaxLanes(D()) == kPlanarLanes) {
    // (x0 + x1, y0 + y1, x2 + x3, y2 + y3): interleaving works within 128-bit blocks.
    const auto pairs = hn::Add(hn::InterleaveLower(d, sx, sy), hn::InterleaveUpper(d, sx, sy));
    const hn::Half<D> h;
    const auto sums = hn::Add(hn::LowerHalf(h, pairs), hn::UpperHalf(h, pairs));
    HWY_ALIGN const double start[2] = {fx, fy};
    hn::StoreU(hn::Add(hn::Load(h, start), sums), h, ring);
    return;
  }
#endif
  (void)d, (void)sx, (void)sy, (void)fx, (void)fy, (void)ring;
}

void PlanarBallsImpl(const PlanarBalls& in, double ring_x, double ring_y, double* HWY_RESTRICT ring,
                     double* HWY_RESTRICT radial, double* HWY_RESTRICT torque) {
  const PlanarTag d;
  if (hn::Lanes(d) < kPlanarLanes)
    return planar_balls_scalar(in, ring_x, ring_y, ring, radial, torque);
  const std::size_t N = kPlanarLanes, n = static_cast<std::size_t>(in.balls);
  const auto x = hn::Set(d, ring_x), y = hn::Set(d, ring_y), gap = hn::Set(d, in.gap);
  const auto vx = hn::Set(d, in.vx), vy = hn::Set(d, in.vy), zero = hn::Zero(d);
  const auto fc = hn::Set(d, in.centrifugal), cb = hn::Set(d, in.ball_damping);
  const auto lever = hn::Set(d, in.lever), ai = hn::Set(d, in.drive_inner);
  const auto ao = hn::Set(d, in.drive_outer), gain = hn::Set(d, in.traction_gain);
  const auto cap = hn::Set(d, in.traction_cap), minus_cap = hn::Neg(cap);
  auto sx = zero, sy = zero;  // the ring force, lane-wise
  for (std::size_t done = 0; done < n;) {
    const std::size_t j = std::min(done, n - N);          // the last vector ends at ball Z − 1
    const auto fresh = hn::Not(hn::FirstN(d, done - j));  // lanes not yet summed
    const auto c = hn::LoadU(d, in.cos_theta + j), s = hn::LoadU(d, in.sin_theta + j);
    const auto pos = hn::LoadU(d, in.position + j);
    // The ring's position enters last (it is known last): δ_i = (x c + y s) − (s_j + γ − e_i).
    const auto delta_o = hn::Max(hn::Add(pos, hn::LoadU(d, in.outer_excitation + j)), zero);
    const auto shift_i = hn::Add(pos, hn::Sub(gap, hn::LoadU(d, in.inner_excitation + j)));
    const auto delta_i = hn::Max(hn::Sub(hn::Add(hn::Mul(x, c), hn::Mul(y, s)), shift_i), zero);
    const auto load_o =
        hn::Mul(hn::Mul(hn::LoadU(d, in.outer_stiffness + j), delta_o), hn::Sqrt(delta_o));
    const auto load_i =
        hn::Mul(hn::Mul(hn::LoadU(d, in.inner_stiffness + j), delta_i), hn::Sqrt(delta_i));
    const auto rest = hn::Sub(fc, hn::Mul(cb, hn::LoadU(d, in.speed + j)));
    hn::StoreU(hn::Add(hn::Sub(load_i, load_o), rest), d, radial + j);
    // The ring force per unit Q_i, (−c + μ_i s, −s − μ_i c), ready before Q_i is.
    auto ux = hn::Neg(c), uy = hn::Neg(s);
    if (in.friction) {
      const auto spin = hn::Mul(lever, hn::LoadU(d, in.spin + j));
      const auto dvi = hn::Add(hn::Sub(ai, spin), hn::Sub(hn::Mul(vy, c), hn::Mul(vx, s)));
      const auto dvo = hn::Sub(ao, spin);
      const auto mu_i = hn::Min(hn::Max(hn::Mul(gain, dvi), minus_cap), cap);
      const auto mu_o = hn::Min(hn::Max(hn::Mul(gain, dvo), minus_cap), cap);
      hn::StoreU(
          hn::Add(hn::Mul(hn::Mul(lever, mu_i), load_i), hn::Mul(hn::Mul(lever, mu_o), load_o)), d,
          torque + j);
      ux = hn::Sub(hn::Mul(mu_i, s), c);  // μ Q_i τ_j on the ring
      uy = hn::Neg(hn::Add(s, hn::Mul(mu_i, c)));
    } else {
      hn::StoreU(zero, d, torque + j);
    }
    sx = hn::Add(sx, hn::Mul(load_i, hn::IfThenElseZero(fresh, ux)));
    sy = hn::Add(sy, hn::Mul(load_i, hn::IfThenElseZero(fresh, uy)));
    done = j + N;
  }
  StoreRingSums(d, sx, sy, in.fx, in.fy, ring);
}

// phasor() (phasor.h) lane by lane: the same operations in the same order, the table entry
// gathered (Phasor is {cos, sin}: entry i is at 2i and 2i + 1 of the doubles).
void PhasorsImpl(const double* HWY_RESTRICT theta, int n, double* HWY_RESTRICT cos_theta,
                 double* HWY_RESTRICT sin_theta) {
  using C = PhasorConstants;
  const PhasorConstants& pc = phasor_constants();
  const Tag d;
  const hn::RebindToSigned<Tag> di;
  const auto step = hn::Set(d, C::kStep), shifter = hn::Set(d, C::kShifter);
  const auto hi = hn::Set(d, pc.step_hi), lo = hn::Set(d, pc.step_lo), one = hn::Set(d, 1.0);
  const auto c1 = hn::Set(d, -0.5), c2 = hn::Set(d, 1.0 / 24), c3 = hn::Set(d, -1.0 / 720),
             c4 = hn::Set(d, 1.0 / 40320);
  const auto s1 = hn::Set(d, -1.0 / 6), s2 = hn::Set(d, 1.0 / 120), s3 = hn::Set(d, -1.0 / 5040),
             s4 = hn::Set(d, 1.0 / 362880);
  const auto mask = hn::Set(di, C::kN - 1);
  const double* const table = &pc.table[0].c;
  const auto count = static_cast<std::size_t>(n);
  for (std::size_t j = 0; j < count; j += hn::Lanes(d)) {
    const auto th = hn::LoadU(d, theta + j);
    const auto k = hn::Sub(hn::Add(hn::Div(th, step), shifter), shifter);
    const auto r = hn::Sub(hn::Sub(th, hn::Mul(k, hi)), hn::Mul(k, lo));
    const auto r2 = hn::Mul(r, r);
    const auto cr = hn::Add(
        one,
        hn::Mul(r2,
                hn::Add(c1, hn::Mul(r2, hn::Add(c2, hn::Mul(r2, hn::Add(c3, hn::Mul(r2, c4))))))));
    const auto sr = hn::Mul(
        r,
        hn::Add(
            one,
            hn::Mul(
                r2,
                hn::Add(s1, hn::Mul(r2, hn::Add(s2, hn::Mul(r2, hn::Add(s3, hn::Mul(r2, s4)))))))));
    const auto index = hn::ShiftLeft<1>(hn::And(hn::ConvertTo(di, k), mask));
    const auto tc = hn::GatherIndex(d, table, index);
    const auto ts = hn::GatherIndex(d, table, hn::Add(index, hn::Set(di, 1)));
    hn::StoreU(hn::Sub(hn::Mul(tc, cr), hn::Mul(ts, sr)), d, cos_theta + j);
    hn::StoreU(hn::Add(hn::Mul(ts, cr), hn::Mul(tc, sr)), d, sin_theta + j);
  }
}

ContactKernels KernelsImpl() {
  return {&RotateBallsImpl, &RadialContactsImpl, &PlanarBallsImpl, &PhasorsImpl};
}
const char* TargetImpl() {
  return hwy::TargetName(HWY_TARGET);
}

}  // namespace bearing::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
#endif  // BEARING_WITHOUT_HIGHWAY

#if defined(BEARING_WITHOUT_HIGHWAY) || HWY_ONCE
namespace bearing {
namespace detail {
namespace {

void rotate_balls_scalar(const double* base_cos, const double* base_sin, double cos_phi,
                         double sin_phi, int Z, double* cos_theta, double* sin_theta) {
  rotate_balls_inline(base_cos, base_sin, cos_phi, sin_phi, Z, cos_theta, sin_theta);
}

void radial_contacts_scalar(const double* cos_theta, const double* sin_theta,
                            const double* excitation, const double* stiffness, int Z, double x,
                            double y, double gap, double* fx, double* fy) {
  radial_contacts_inline(cos_theta, sin_theta, excitation, stiffness, Z, x, y, gap, fx, fy);
}

void phasors_scalar(const double* theta, int n, double* cos_theta, double* sin_theta) {
  for (int i = 0; i < n; ++i) {
    const Phasor p = phasor(theta[i]);
    cos_theta[i] = p.c;
    sin_theta[i] = p.s;
  }
}

#ifndef BEARING_WITHOUT_HIGHWAY
HWY_EXPORT(KernelsImpl);
HWY_EXPORT(TargetImpl);
const char* dispatched_target() {
  return HWY_DYNAMIC_DISPATCH(TargetImpl)();
}
#else
const char* dispatched_target() {
  return "scalar (built without Highway)";
}
#endif

}  // namespace

// The SIMD kernel's arithmetic ball by ball: the balls in lanes of kPlanarLanes as the kernel
// takes them (the last group ending at the last ball, its lanes already done adding zero), each
// lane's ring sum in the same order, the lanes added by planar_ring_sum.
void planar_balls_scalar(const PlanarBalls& in, double x, double y, double* ring, double* radial,
                         double* torque) {
  constexpr int N = kPlanarLanes;
  const double cap = in.traction_cap;
  double sx[N] = {}, sy[N] = {};
  for (int done = 0; done < in.balls;) {
    const int first = in.balls >= N ? std::min(done, in.balls - N) : 0;
    for (int k = 0; k < N && first + k < in.balls; ++k) {
      const int j = first + k;
      const double c = in.cos_theta[j], s = in.sin_theta[j];
      const double delta_o = std::max(in.position[j] + in.outer_excitation[j], 0.0);
      const double shift_i = in.position[j] + (in.gap - in.inner_excitation[j]);
      const double delta_i = std::max((x * c + y * s) - shift_i, 0.0);
      const double load_o = in.outer_stiffness[j] * delta_o * std::sqrt(delta_o);
      const double load_i = in.inner_stiffness[j] * delta_i * std::sqrt(delta_i);
      radial[j] = (load_i - load_o) + (in.centrifugal - in.ball_damping * in.speed[j]);
      double ux = -c, uy = -s;
      if (in.friction) {
        const double spin = in.lever * in.spin[j];
        const double dvi = in.drive_inner - spin + (in.vy * c - in.vx * s);
        const double dvo = in.drive_outer - spin;
        const double mu_i = std::min(std::max(in.traction_gain * dvi, -cap), cap);
        const double mu_o = std::min(std::max(in.traction_gain * dvo, -cap), cap);
        torque[j] = in.lever * mu_i * load_i + in.lever * mu_o * load_o;
        ux = mu_i * s - c;  // μ Q_i τ_j on the ring
        uy = -(s + mu_i * c);
      } else {
        torque[j] = 0.0;
      }
      const bool fresh = j >= done;  // not yet in the ring sums
      sx[k] += load_i * (fresh ? ux : 0.0);
      sy[k] += load_i * (fresh ? uy : 0.0);
    }
    done = first + N;
  }
  ring[0] = planar_ring_sum(in.fx, sx);
  ring[1] = planar_ring_sum(in.fy, sy);
}

ContactKernels contact_kernels(ContactLoop loop, int balls) {
#ifndef BEARING_WITHOUT_HIGHWAY
  if (loop == ContactLoop::simd) {
    ContactKernels k = HWY_DYNAMIC_DISPATCH(KernelsImpl)();
    if (balls < kPlanarLanes) k.planar_balls = &planar_balls_scalar;
    return k;
  }
#endif
  (void)balls;
  (void)loop;
  return {&rotate_balls_scalar, &radial_contacts_scalar, &planar_balls_scalar, &phasors_scalar};
}

std::vector<NamedKernels> kernels_per_target() {
  std::vector<NamedKernels> out;
#ifndef BEARING_WITHOUT_HIGHWAY
  for (const auto target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    out.push_back({hwy::TargetName(target), HWY_DYNAMIC_DISPATCH(KernelsImpl)()});
  }
  hwy::SetSupportedTargetsForTest(0);  // back to what the CPU supports
#endif
  return out;
}

}  // namespace detail

std::string simd_target() {
  return detail::dispatched_target();
}

}  // namespace bearing
#endif  // HWY_ONCE
