#pragma once
// An independent numerical solution of the squeeze-film Reynolds equation under a rigid
// ellipsoidal gap (issue 43): the reference the EHL film's damping (ehl_film.h) is checked
// against, by the `film` family (checks/film.cc) and the unit tests (tests/lumped/test_ehl_film.cc).
// It uses nothing of the library.
//
// The gap h = h₀ + x²/(2R_x) + y²/(2R_y) closes at −dh₀/dt = v; Reynolds' equation
// ∇·(h³∇p) = 12 η dh₀/dt. With x = √(2 R_x h₀) X, y = √(2 R_y h₀) Y, h = h₀ H, H = 1 + X² + Y²,
// λ = R_x/R_y and p = 24 R_x η v / h₀² P, it reads
//     ∂_X(H³ ∂_X P) + λ ∂_Y(H³ ∂_Y P) = −1,
// and the force F = ∫p dx dy = 48 η R_x √(R_x R_y) / h₀ · v · ∫P dX dY, so the damping is
// c = 48 η R_x √(R_x R_y) / h₀ · I, I = ∫P dX dY (the plane: I = π / (4 (1 + λ)), the closed form).
//
// Discretisation: the quadrant [0, L]² (P even in X and Y), P = 0 on X = L and Y = L, a node-
// centred finite-volume scheme on the stretched grid X_i = A sinh(β i/N), A sinh β = L (cells of
// ~A β/N near the contact, growing geometrically outwards), fluxes H³ ΔP/ΔX at the faces (the
// mapped mid-points), I = Σ P_ij × cell area. Second order in 1/N for the smooth mapping.
// Domain: on the disc r ≤ L the exact solution with P(L) = 0 is P_∞ − P_∞(L) (P_∞ depends on
// H alone), whose integral falls short of the plane's by 1/(1+L²) + L²/(1+L²)² < 2/L² relative;
// the square [−L, L]² lies between the discs of radius L and √2 L, so (maximum principle) its
// shortfall is below 2/L² too.

#include <cmath>
#include <vector>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace bearing::squeeze_reference {

/// I = ∫P dX dY of the scaled problem above, for λ = R_x/R_y, on [−L, L]² with N cells a side
/// of the quadrant.
inline double scaled_integral(double lambda, int n, double half_width = 1000.0,
                              double core = 0.5) {
  const double beta = std::asinh(half_width / core);
  std::vector<double> x(n + 1), face(n + 1);
  for (int i = 0; i <= n; ++i) x[i] = core * std::sinh(beta * i / n);
  for (int i = 0; i < n; ++i) face[i] = core * std::sinh(beta * (i + 0.5) / n);  // i + 1/2
  // The control volume of node i: [face[i−1], face[i]] (i = 0: [0, face[0]]).
  auto width = [&](int i) { return face[i] - (i == 0 ? 0.0 : face[i - 1]); };
  auto h3 = [](double a, double b) {
    const double h = 1.0 + a * a + b * b;
    return h * h * h;
  };
  const int m = n * n;  // unknowns: nodes 0..n−1 in each direction (node n: P = 0)
  auto id = [n](int i, int j) { return i * n + j; };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(5 * static_cast<std::size_t>(m));
  Eigen::VectorXd rhs(m), area(m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int r = id(i, j);
      area[r] = width(i) * width(j);
      rhs[r] = area[r];
      double diag = 0;
      // X faces: i+1/2 (always), i−1/2 (i > 0; at i = 0 the symmetry plane carries no flux).
      for (int s : {+1, -1}) {
        const int k = i + s;
        if (k < 0) continue;
        const double w = h3(s > 0 ? face[i] : face[i - 1], x[j]) * width(j) / std::fabs(x[k] - x[i]);
        diag += w;
        if (k < n) t.emplace_back(r, id(k, j), -w);
      }
      for (int s : {+1, -1}) {
        const int k = j + s;
        if (k < 0) continue;
        const double w =
            lambda * h3(x[i], s > 0 ? face[j] : face[j - 1]) * width(i) / std::fabs(x[k] - x[j]);
        diag += w;
        if (k < n) t.emplace_back(r, id(i, k), -w);
      }
      t.emplace_back(r, r, diag);
    }
  Eigen::SparseMatrix<double> a(m, m);
  a.setFromTriplets(t.begin(), t.end());
  // Symmetric scaling D^-1/2 A D^-1/2: the coefficients span H³ ~ L⁶ across the grid.
  Eigen::VectorXd d = a.diagonal().cwiseSqrt().cwiseInverse();
  Eigen::SparseMatrix<double> s = d.asDiagonal() * a * d.asDiagonal();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(s);
  const Eigen::VectorXd z = solver.solve(d.cwiseProduct(rhs));
  const Eigen::VectorXd p = d.cwiseProduct(z);
  return 4.0 * p.dot(area);  // four quadrants
}

/// The squeeze damping c [N s/m] of the gap with radii rx, ry [m], central gap h0 [m] and
/// viscosity eta [Pa s], from the numerical I.
inline double damping(double rx, double ry, double h0, double eta, int n,
                      double half_width = 1000.0) {
  return 48.0 * eta * rx * std::sqrt(rx * ry) / h0 * scaled_integral(rx / ry, n, half_width);
}

/// The relative shortfall of I on [−L, L]² below the plane's, bounded above (header comment).
inline double domain_bound(double half_width) { return 2.0 / (half_width * half_width); }

}  // namespace bearing::squeeze_reference
