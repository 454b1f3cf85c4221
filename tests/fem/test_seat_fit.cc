// The seat's rigid fit (fem/modes/seat_fit.h, no deal.II) on a cylindrical seat sampled by the
// midpoint rule: a rigid motion is recovered exactly with no residual, a field orthogonal to the
// rigid motions is not fitted at all, and a mix leaves the residual its orthogonal part has,
// computed here point by point, not through the moments.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "bearing/errors.h"
#include "modes/seat_fit.h"

namespace bearing::fem {
namespace {

struct Sample {
  double w;
  Vec3 x;
};

// A cylinder of radius 0.026 m about the axis (0.01, -0.02, z), z in [0.003, 0.018].
std::vector<Sample> cylinder() {
  std::vector<Sample> s;
  const int nt = 48, nz = 6;
  const double r = 0.026, z0 = 0.003, len = 0.015;
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < nz; ++k) {
      const double t = 2 * M_PI * (i + 0.5) / nt, z = z0 + len * (k + 0.5) / nz;
      s.push_back(
          {2 * M_PI * r / nt * len / nz, {0.01 + r * std::cos(t), -0.02 + r * std::sin(t), z}});
    }
  return s;
}

Vec3 rigid(const Vec3& t, const Vec3& th, const Vec3& c, const Vec3& x) {
  const Vec3 r{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  return {t[0] + th[1] * r[2] - th[2] * r[1], t[1] + th[2] * r[0] - th[0] * r[2],
          t[2] + th[0] * r[1] - th[1] * r[0]};
}

RigidFit fit_of(const std::vector<Sample>& s, const std::function<Vec3(const Vec3&)>& u) {
  SurfaceMoments m;
  FieldMoments f;
  for (const Sample& p : s) {
    m.add(p.w, p.x);
    f.add(p.w, p.x, u(p.x));
  }
  // Summed in two halves and joined through the packed form, as across MPI processes.
  const std::vector<double> a = packed(m), b = packed(f);
  return fit_rigid_motion(surface_moments_from(a.data()), field_moments_from(b.data()));
}

TEST(SeatFit, ARigidMotionIsRecoveredExactly) {
  const auto s = cylinder();
  SurfaceMoments m;
  for (const Sample& p : s) m.add(p.w, p.x);
  const Vec3 c = m.centre();
  EXPECT_NEAR(c[0], 0.01, 1e-15);
  EXPECT_NEAR(c[1], -0.02, 1e-15);
  EXPECT_NEAR(c[2], 0.0105, 1e-15);
  const Vec3 t{1e-6, -2e-6, 3e-7}, th{4e-5, -1e-5, 2e-5};
  const RigidFit f = fit_of(s, [&](const Vec3& x) { return rigid(t, th, c, x); });
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(f.translation[i], t[i], 1e-17);
    EXPECT_NEAR(f.rotation[i], th[i], 1e-15);
  }
  EXPECT_LT(f.residual, 1e-6);  // sqrt of a cancellation at round-off
}

TEST(SeatFit, TheResidualIsTheShareOfTheFieldNoRigidMotionHas) {
  const auto s = cylinder();
  const Vec3 c{0.01, -0.02, 0.0105};
  // An ovalisation u = e (x - c_x) e_x: zero mean, no moment about the centroid.
  const auto oval = [&](const Vec3& x) { return Vec3{1e-3 * (x[0] - c[0]), 0, 0}; };
  const RigidFit o = fit_of(s, oval);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(o.translation[i], 0, 1e-18);
    EXPECT_NEAR(o.rotation[i], 0, 1e-15);
  }
  EXPECT_NEAR(o.residual, 1.0, 1e-9);
  // Rigid plus ovalisation: the fit keeps the rigid part; the residual, point by point.
  const Vec3 t{2e-6, 0, -1e-6}, th{0, 3e-5, 0};
  const auto mix = [&](const Vec3& x) {
    const Vec3 a = rigid(t, th, c, x), b = oval(x);
    return Vec3{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  };
  const RigidFit f = fit_of(s, mix);
  double misfit = 0, total = 0;
  for (const Sample& p : s) {
    const Vec3 u = mix(p.x), v = rigid(f.translation, f.rotation, c, p.x);
    for (int i = 0; i < 3; ++i)
      misfit += p.w * (u[i] - v[i]) * (u[i] - v[i]), total += p.w * u[i] * u[i];
  }
  EXPECT_NEAR(f.residual, std::sqrt(misfit / total), 1e-9);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f.translation[i], t[i], 1e-17);
  EXPECT_NEAR(f.rotation[1], th[1], 1e-15);
}

TEST(SeatFit, ASeatOnALineCannotFixARotation) {
  SurfaceMoments line;
  for (int i = 0; i < 10; ++i) line.add(0.1, {0, 0, 0.01 * i});
  EXPECT_THROW(check_seat_geometry(line, "seat"), InputError);
  EXPECT_THROW(check_seat_geometry(SurfaceMoments{}, "seat"), InputError);
  SurfaceMoments ring;
  for (const Sample& p : cylinder()) ring.add(p.w, p.x);
  EXPECT_NO_THROW(check_seat_geometry(ring, "seat"));
}

}  // namespace
}  // namespace bearing::fem
