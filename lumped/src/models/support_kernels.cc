// The support's arithmetic of every force evaluation on a housing (housed_model.h): Highway's
// per-target code (this file is compiled once per instruction set through foreach_target.h, as
// contact_kernels.cc is) and the scalar reference. With 20 structure modes it is four sums of 20
// products and twenty forces per evaluation, about what the 2-DOF force itself costs when done
// one double at a time.
//
// Same bits on every target and in the scalar reference: each sum is accumulated in kSupportLanes =
// 8 partial sums (lane k mod 8, whatever the hardware's vector width: a narrower target walks the
// 8 lanes in several vectors) and the partial sums are joined pairwise in one fixed order; every
// force is the same sequence of IEEE operations; no fused multiply-add (the file is built with
// -ffp-contract=off).

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "housed_model.h"

#ifndef BEARING_WITHOUT_HIGHWAY
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "models/support_kernels.cc"  // this file, from lumped/src
#include <hwy/foreach_target.h>                         // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace bearing::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using Tag = hn::CappedTag<double, kSupportLanes>;

void SeatSumsImpl(const double* HWY_RESTRICT sx, const double* HWY_RESTRICT sy,
                  const double* HWY_RESTRICT p, const double* HWY_RESTRICT pv, int dofs,
                  double* HWY_RESTRICT out) {
  const Tag d;
  // The 8 partial sums of each sum in kV vectors of kL lanes, held in registers.
  constexpr std::size_t kL = HWY_MIN(kSupportLanes, HWY_LANES(double));
  constexpr std::size_t kV = kSupportLanes / kL;
  using V = decltype(hn::Zero(d));
  V xp[kV], yp[kV], xv[kV], yv[kV];
  for (std::size_t v = 0; v < kV; ++v) xp[v] = yp[v] = xv[v] = yv[v] = hn::Zero(d);
  const std::size_t n = static_cast<std::size_t>(dofs);
  std::size_t k = 0;
  for (; k + kSupportLanes <= n; k += kSupportLanes)
    for (std::size_t v = 0; v < kV; ++v) {
      const std::size_t i = k + v * kL;
      const auto a = hn::LoadU(d, sx + i), b = hn::LoadU(d, sy + i);
      const auto vp = hn::LoadU(d, p + i), vv = hn::LoadU(d, pv + i);
      xp[v] = hn::Add(xp[v], hn::Mul(a, vp));
      yp[v] = hn::Add(yp[v], hn::Mul(b, vp));
      xv[v] = hn::Add(xv[v], hn::Mul(a, vv));
      yv[v] = hn::Add(yv[v], hn::Mul(b, vv));
    }
  HWY_ALIGN double sxp[kSupportLanes], syp[kSupportLanes], sxv[kSupportLanes], syv[kSupportLanes];
  for (std::size_t v = 0; v < kV; ++v) {
    hn::Store(xp[v], d, sxp + v * kL);
    hn::Store(yp[v], d, syp + v * kL);
    hn::Store(xv[v], d, sxv + v * kL);
    hn::Store(yv[v], d, syv + v * kL);
  }
  // The last, partial block lane by lane (never a load past the state's end).
  for (std::size_t l = 0; k + l < n; ++l) {
    sxp[l] += sx[k + l] * p[k + l];
    syp[l] += sy[k + l] * p[k + l];
    sxv[l] += sx[k + l] * pv[k + l];
    syv[l] += sy[k + l] * pv[k + l];
  }
  const auto join = [](const double* s) {
    return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
  };
  out[0] = join(sxp);
  out[1] = join(syp);
  out[2] = join(sxv);
  out[3] = join(syv);
}

void SupportForcesImpl(const double* HWY_RESTRICT sx, const double* HWY_RESTRICT sy,
                       const double* HWY_RESTRICT k, const double* HWY_RESTRICT c, double bx,
                       double by, const double* HWY_RESTRICT p, const double* HWY_RESTRICT pv,
                       int dofs, double* HWY_RESTRICT f) {
  const Tag d;
  const std::size_t L = hn::Lanes(d), n = static_cast<std::size_t>(dofs);
  const auto mbx = hn::Set(d, -bx), mby = hn::Set(d, -by);
  std::size_t i = 0;
  for (; i + L <= n; i += L) {
    const auto reaction =
        hn::Add(hn::Mul(hn::LoadU(d, sx + i), mbx), hn::Mul(hn::LoadU(d, sy + i), mby));
    const auto spring = hn::Mul(hn::LoadU(d, k + i), hn::LoadU(d, p + i));
    const auto damper = hn::Mul(hn::LoadU(d, c + i), hn::LoadU(d, pv + i));
    hn::StoreU(hn::Sub(hn::Sub(reaction, spring), damper), d, f + i);
  }
  for (; i < n; ++i) f[i] = (sx[i] * -bx + sy[i] * -by) - k[i] * p[i] - c[i] * pv[i];
}

SupportKernels SupportKernelsImpl() {
  return {&SeatSumsImpl, &SupportForcesImpl};
}

}  // namespace bearing::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
#endif  // BEARING_WITHOUT_HIGHWAY

#if defined(BEARING_WITHOUT_HIGHWAY) || HWY_ONCE
namespace bearing::detail {
namespace {

void seat_sums_scalar(const double* sx, const double* sy, const double* p, const double* pv,
                      int dofs, double* out) {
  double xp[kSupportLanes] = {}, yp[kSupportLanes] = {}, xv[kSupportLanes] = {},
         yv[kSupportLanes] = {};
  for (int k = 0; k < dofs; ++k) {
    const std::size_t l = static_cast<std::size_t>(k) % kSupportLanes;
    xp[l] += sx[k] * p[k];
    yp[l] += sy[k] * p[k];
    xv[l] += sx[k] * pv[k];
    yv[l] += sy[k] * pv[k];
  }
  const auto join = [](const double* s) {
    return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
  };
  out[0] = join(xp);
  out[1] = join(yp);
  out[2] = join(xv);
  out[3] = join(yv);
}

void support_forces_scalar(const double* sx, const double* sy, const double* k, const double* c,
                           double bx, double by, const double* p, const double* pv, int dofs,
                           double* f) {
  for (int i = 0; i < dofs; ++i) f[i] = (sx[i] * -bx + sy[i] * -by) - k[i] * p[i] - c[i] * pv[i];
}

#ifndef BEARING_WITHOUT_HIGHWAY
HWY_EXPORT(SupportKernelsImpl);
#endif

}  // namespace

SupportKernels support_kernels(ContactLoop loop) {
#ifndef BEARING_WITHOUT_HIGHWAY
  if (loop == ContactLoop::simd) return HWY_DYNAMIC_DISPATCH(SupportKernelsImpl)();
#endif
  (void)loop;
  return {&seat_sums_scalar, &support_forces_scalar};
}

std::vector<std::pair<std::string, SupportKernels>> support_kernels_per_target() {
  std::vector<std::pair<std::string, SupportKernels>> out;
#ifndef BEARING_WITHOUT_HIGHWAY
  for (const auto target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    out.emplace_back(hwy::TargetName(target), HWY_DYNAMIC_DISPATCH(SupportKernelsImpl)());
  }
  hwy::SetSupportedTargetsForTest(0);  // back to what the CPU supports
#endif
  return out;
}

}  // namespace bearing::detail
#endif  // HWY_ONCE
