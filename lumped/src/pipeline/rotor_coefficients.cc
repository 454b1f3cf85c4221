// The bearing's coefficients for a rotor model: ball-pass means (rotor_coefficients.h).

#include "bearing/rotor_coefficients.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "bearing/stiffness.h"

namespace bearing {

Matrix5 ball_pass_mean(const std::vector<Matrix5>& samples) {
  if (samples.empty()) throw std::logic_error("ball_pass_mean of no samples");
  const double n = static_cast<double>(samples.size());
  Matrix5 mean = Matrix5::Zero();
  for (const Matrix5& M : samples) mean += M / n;
  return mean;
}

RotorCoefficients rotor_coefficients(const BallPassStiffness& pass) {
  RotorCoefficients r;
  r.samples = static_cast<int>(pass.samples.size());
  r.stiffness = ball_pass_mean(pass.samples);
  if (!pass.damping_samples.empty()) r.damping = ball_pass_mean(pass.damping_samples);
  r.warnings = rotor_stiffness_warnings(r.stiffness);
  return r;
}

namespace {

std::string num(double v) {
  if (v == 0) v = 0;  // no "-0"
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// A block of K of one unit: its DOFs first … first + size − 1.
struct Block {
  const char* name;
  int first, size;
  const char* unit;
  const char* remedy;
};

constexpr Block kBlocks[] = {
    {"translations (x, y, z)", 0, 3, "N/m",
     "a preload (operation.axial_load) loads every ball and supports every translation"},
    {"tilts (gx, gy)", 3, 2, "N*m/rad",
     "a preload (operation.axial_load) or a moment (operation.moment) loads balls around the "
     "ring and supports both tilts"}};

// "z", or "0.71 x - 0.71 y": the unit eigenvector v over the block's DOFs, its sign fixed so
// that its largest component is positive, components below 0.01 left out.
std::string direction(const Eigen::VectorXd& v, int first) {
  Eigen::Index big = 0;
  v.cwiseAbs().maxCoeff(&big);
  const double sign = v(big) < 0 ? -1.0 : 1.0;
  if (std::fabs(v(big)) > 0.999) return kStiffnessDofs[first + big];
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double c = sign * v(i);
    if (std::fabs(c) < 0.01) continue;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f ", std::fabs(c));
    out += (out.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) + std::string(buf) +
           kStiffnessDofs[first + i];
  }
  return out;
}

// The sentence for one block, "" when it is not near singular.
std::string block_warning(const Matrix5& K, const Block& b) {
  const Eigen::MatrixXd B = K.block(b.first, b.first, b.size, b.size);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (B + B.transpose()));
  const double lo = eig.eigenvalues()(0), hi = eig.eigenvalues()(b.size - 1);
  const std::string unit = std::string(" ") + b.unit;
  if (!(hi > 0))
    return std::string("K averaged over one ball pass has no stiffness in the ") + b.name +
           ": the ring is unsupported in them at every cage angle; " + b.remedy;
  if (!(lo < kNearSingularRatio * hi)) return "";
  const std::string along = direction(eig.eigenvectors().col(0), b.first);
  return std::string("K averaged over one ball pass is near singular in the ") + b.name +
         ": its smallest eigenvalue, " + num(lo) + unit + " along " + along + ", is " +
         num(lo / hi) + " of its largest, " + num(hi) + unit + " (near singular: below " +
         num(kNearSingularRatio) + "); the ring is unsupported along " + along +
         " at every cage angle (each one's K is positive semi-definite, so their mean is "
         "singular only where all are); " +
         b.remedy;
}

}  // namespace

std::vector<std::string> rotor_stiffness_warnings(const Matrix5& K) {
  if (K.isZero(0.0))
    return {
        "K averaged over one ball pass is 0: no ball is loaded at any cage angle, the load sits "
        "in the clearance (the inner ring is free within it), so this bearing gives a rotor "
        "model no support in any direction; give operation.load, operation.axial_load or "
        "operation.moment"};
  std::vector<std::string> out;
  for (const Block& b : kBlocks)
    if (std::string w = block_warning(K, b); !w.empty()) out.push_back(std::move(w));
  return out;
}

}  // namespace bearing
