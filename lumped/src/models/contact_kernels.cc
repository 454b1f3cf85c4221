// The contact kernels of contact_kernels.h: Highway's per-target code (this file is compiled once
// per instruction set through foreach_target.h) and the scalar reference.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "contact_kernels.h"

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

ContactKernels KernelsImpl() {
  return {&RotateBallsImpl, &RadialContactsImpl};
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
  for (int j = 0; j < Z; ++j) {
    cos_theta[j] = base_cos[j] * cos_phi - base_sin[j] * sin_phi;
    sin_theta[j] = base_sin[j] * cos_phi + base_cos[j] * sin_phi;
  }
}

void radial_contacts_scalar(const double* cos_theta, const double* sin_theta,
                            const double* excitation, const double* stiffness, int Z, double x,
                            double y, double gap, double* fx, double* fy) {
  for (int j = 0; j < Z; ++j) {
    const double c = cos_theta[j], s = sin_theta[j];
    const double delta = x * c + y * s - gap + excitation[j];
    if (delta <= 0) continue;
    const double q = stiffness[j] * delta * std::sqrt(delta);
    *fx -= q * c;
    *fy -= q * s;
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

ContactKernels contact_kernels(ContactLoop loop) {
#ifndef BEARING_WITHOUT_HIGHWAY
  if (loop == ContactLoop::simd) return HWY_DYNAMIC_DISPATCH(KernelsImpl)();
#endif
  (void)loop;
  return {&rotate_balls_scalar, &radial_contacts_scalar};
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
