// The structure family's closed forms (structure_reference.h has the mathematics).

#include "structure_reference.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace bearing::verify::structure_reference {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The 4 × 4 boundary determinant of the Timoshenko cantilever at ω, scaled by 1/cosh(p₁L) so it
// stays of order one.
double cantilever_determinant(const Section& s, double L, double k, double w) {
  const double A = s.area(), I = s.inertia(), E = s.young, rho = s.density;
  const double kGA = k * s.shear_modulus() * A;
  const double q = rho * A * w * w / kGA;
  const double a2 = E * I, a1 = E * I * q + rho * I * w * w, a0 = q * (rho * I * w * w - kGA);
  const double disc = std::sqrt(a1 * a1 - 4 * a2 * a0);
  const double mu1 = (-a1 + disc) / (2 * a2), mu2 = (-a1 - disc) / (2 * a2);
  const double p1 = std::sqrt(mu1), p2 = std::sqrt(-mu2);
  // ψ of each w-solution: cosh → c1 sinh, sinh → c1 cosh, cos → c2 sin, sin → −c2 cos.
  const double c1 = (mu1 + q) / p1, c2 = (q - p2 * p2) / p2;
  const double ch = std::cosh(p1 * L), sh = std::sinh(p1 * L);
  const double co = std::cos(p2 * L), si = std::sin(p2 * L);
  Eigen::Matrix4d m;
  m << 1, 0, 1, 0,                                                      // w(0) = 0
      0, c1, 0, -c2,                                                    // ψ(0) = 0
      c1 * p1 * ch, c1 * p1 * sh, c2 * p2 * co, c2 * p2 * si,           // ψ'(L) = 0
      (p1 - c1) * sh, (p1 - c1) * ch, -(p2 + c2) * si, (p2 + c2) * co;  // w'(L) − ψ(L) = 0
  return m.determinant() / ch;
}

}  // namespace

double cowper_rectangle(double poisson) {
  return 10 * (1 + poisson) / (12 + 11 * poisson);
}

double thin_ring_frequency(const Section& s, double radius, int n) {
  const double r4 = std::pow(radius, 4);
  return std::sqrt(s.young * s.inertia() / (s.density * s.area() * r4)) * n * (n * n - 1) /
         std::sqrt(n * n + 1.0) / (2 * kPi);
}

double timoshenko_ring_frequency(const Section& s, double radius, int n, double k) {
  const double A = s.area(), I = s.inertia(), R = radius, E = s.young;
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero(), M = Eigen::Matrix3d::Zero();
  K(0, 0) = E * A / (R * R);
  K(0, 1) = K(1, 0) = E * A * n / (R * R);
  K(1, 1) = E * A * n * n / (R * R);
  K(2, 2) = E * I * n * n / (R * R);
  const Eigen::Vector3d g(n / R, 1 / R, 1.0);
  K += k * s.shear_modulus() * A * g * g.transpose();
  M.diagonal() << s.density * A, s.density * A, s.density * I;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> solver(K, M, Eigen::EigenvaluesOnly);
  return std::sqrt(solver.eigenvalues()(0)) / (2 * kPi);
}

std::vector<double> timoshenko_cantilever(const Section& s, double length, double k, int count) {
  // Scan in β = (ρAω²/(EI))^{1/4} L, whose roots lie about π apart (Euler–Bernoulli: 1.875,
  // 4.694, 7.855, …), in steps of 0.01: at most one root per step.
  const double cutoff = std::sqrt(k * s.shear_modulus() * s.area() / (s.density * s.inertia()));
  const double scale = std::sqrt(s.young * s.inertia() / (s.density * s.area())) /
                       (length * length);  // ω = scale β²
  std::vector<double> roots;
  double beta = 0.5, f0 = cantilever_determinant(s, length, k, scale * beta * beta);
  while (static_cast<int>(roots.size()) < count) {
    const double next = beta + 0.01, w1 = scale * next * next;
    if (w1 > 0.5 * cutoff)
      throw std::runtime_error("timoshenko_cantilever: a mode near the shear cut-off");
    const double f1 = cantilever_determinant(s, length, k, w1);
    if ((f0 < 0) != (f1 < 0)) {
      double lo = scale * beta * beta, hi = w1, flo = f0;
      while (hi - lo > 1e-13 * hi) {
        const double mid = 0.5 * (lo + hi), fm = cantilever_determinant(s, length, k, mid);
        if ((fm < 0) == (flo < 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      roots.push_back(0.5 * (lo + hi) / (2 * kPi));
    }
    beta = next, f0 = f1;
  }
  return roots;
}

std::vector<double> euler_bernoulli_cantilever(const Section& s, double length, int count) {
  const double scale =
      std::sqrt(s.young * s.inertia() / (s.density * s.area())) / (length * length) / (2 * kPi);
  std::vector<double> f;
  for (int n = 1; n <= count; ++n) {
    // cos β cosh β = −1, bracketed in ((n − ½)π − 0.5, (n − ½)π + 0.5).
    double lo = (n - 0.5) * kPi - 0.5, hi = (n - 0.5) * kPi + 0.5;
    const auto g = [](double b) { return std::cos(b) * std::cosh(b) + 1; };
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((g(mid) < 0) == (g(lo) < 0) ? lo : hi) = mid;
    }
    const double beta = 0.5 * (lo + hi);
    f.push_back(scale * beta * beta);
  }
  return f;
}

}  // namespace bearing::verify::structure_reference
