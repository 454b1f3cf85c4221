// The seat's rigid motion by least squares (seat_fit.h has the mathematics).

#include "modes/seat_fit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bearing/errors.h"

namespace bearing::fem {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

using Matrix = std::array<Vec3, 3>;

// J = ∫ (|r|² I − r rᵀ) dA about the centroid, from the moments about the origin:
// S = ∫ r rᵀ dA = ∫ x xᵀ dA − A c cᵀ, J = tr(S) I − S.
Matrix polar_tensor(const SurfaceMoments& s) {
  const Vec3 c = s.centre();
  Matrix S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) S[i][j] = s.second[i][j] - s.area * c[i] * c[j];
  const double trace = S[0][0] + S[1][1] + S[2][2];
  Matrix J;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = (i == j ? trace : 0.0) - S[i][j];
  return J;
}

double determinant(const Matrix& m) {
  return dot(m[0], cross(m[1], m[2]));
}

}  // namespace

void SurfaceMoments::add(double weight, const Vec3& x) {
  area += weight;
  for (int i = 0; i < 3; ++i) {
    first[i] += weight * x[i];
    for (int j = 0; j < 3; ++j) second[i][j] += weight * x[i] * x[j];
  }
}

Vec3 SurfaceMoments::centre() const {
  return {first[0] / area, first[1] / area, first[2] / area};
}

void FieldMoments::add(double weight, const Vec3& x, const Vec3& u) {
  const Vec3 m = cross(x, u);
  for (int i = 0; i < 3; ++i) {
    mean[i] += weight * u[i];
    moment[i] += weight * m[i];
  }
  square += weight * dot(u, u);
}

void check_seat_geometry(const SurfaceMoments& s, const std::string& name) {
  if (!(s.area > 0)) throw InputError("the seat surface \"" + name + "\" has no area in the mesh");
  const Matrix J = polar_tensor(s);
  const double scale = (J[0][0] + J[1][1] + J[2][2]) / 3;
  if (!(determinant(J) > 1e-9 * scale * scale * scale))
    throw InputError("the seat surface \"" + name +
                     "\" cannot determine a rotation: its faces lie (nearly) on a line");
}

RigidFit fit_rigid_motion(const SurfaceMoments& s, const FieldMoments& f) {
  RigidFit fit;
  const Vec3 c = s.centre();
  for (int i = 0; i < 3; ++i) fit.translation[i] = f.mean[i] / s.area;
  // ∫ (x − c) × u dA = ∫ x × u dA − c × ∫ u dA.
  const Vec3 cu = cross(c, f.mean);
  const Vec3 b{f.moment[0] - cu[0], f.moment[1] - cu[1], f.moment[2] - cu[2]};
  // θ = J⁻¹ b by Cramer's rule (J symmetric positive definite, 3 × 3).
  const Matrix J = polar_tensor(s);
  const double d = determinant(J);
  for (int k = 0; k < 3; ++k) {
    Matrix Jk = J;
    for (int i = 0; i < 3; ++i) Jk[i][k] = b[i];
    fit.rotation[k] = determinant(Jk) / d;
  }
  const double misfit =
      f.square - s.area * dot(fit.translation, fit.translation) - dot(fit.rotation, b);
  fit.residual = f.square > 0 ? std::sqrt(std::max(0.0, misfit) / f.square) : 0.0;
  return fit;
}

std::vector<double> packed(const SurfaceMoments& s) {
  std::vector<double> p{s.area, s.first[0], s.first[1], s.first[2]};
  for (const Vec3& row : s.second) p.insert(p.end(), row.begin(), row.end());
  return p;
}

std::vector<double> packed(const FieldMoments& f) {
  return {f.mean[0], f.mean[1], f.mean[2], f.moment[0], f.moment[1], f.moment[2], f.square};
}

SurfaceMoments surface_moments_from(const double* p) {
  SurfaceMoments s;
  s.area = p[0];
  for (int i = 0; i < 3; ++i) {
    s.first[i] = p[1 + i];
    for (int j = 0; j < 3; ++j) s.second[i][j] = p[4 + 3 * i + j];
  }
  return s;
}

FieldMoments field_moments_from(const double* p) {
  FieldMoments f;
  for (int i = 0; i < 3; ++i) f.mean[i] = p[i], f.moment[i] = p[3 + i];
  f.square = p[6];
  return f;
}

}  // namespace bearing::fem
