// Harris's dimensionless approach δ*(F(ρ)) as printed in seed 001 (001_345ec0eb4b896522.txt,
// Table 1, "Dimensional contact parameters by Harris (1991)"), interpolated. The table gives δ*
// only, so κ, K(e), E(e), a*, b* come from the exact solution.
//
// Interpolation: δ* falls to 0 like (1 − F)^{1/3} (times a logarithm) as F → 1, where the
// table is sparse, so δ* is interpolated in x = (1 − F)^{1/3} with Steffen's monotone cubic
// (GSL), which passes through every table point exactly and cannot overshoot between them.
// Against the exact solution this is within 2e-4 relative for 0.87 ≤ F ≤ 0.9995 (the bearing
// range), 1.3e-3 below F = 0.87 (where the first entries carry only three or four digits) and
// 6e-3 at F = 0.9999; plain linear interpolation in F is off by 0.4 % at F = 0.99 and by 24 % at
// F = 0.9999. The 1.3e-3 near F = 0.83595 comes from that table entry itself (see below).
//
// Known defects of the printed table, kept as printed except the first:
//  - the row F = 0.995112 reads "3176" in the seed: the OCR dropped "0."; the value is 0.3176
//    (the exact solution gives 0.31756).
//  - F = 0.4795: table 0.9429, exact 0.94320 (differs by 3e-4, three units of the last digit).
//  - F = 0.83595: table 0.7602, exact 0.75921 (differs by 1e-3, ten units of the last digit).
// Every other entry agrees with the exact solution to its printed rounding (tests/lumped/
// test_contact.cc checks this).

#include <cmath>
#include <memory>
#include <string_view>

#include <gsl/gsl_interp.h>

#include "bearing/hertz.h"
#include "hertz_internal.h"

namespace bearing {

namespace {

struct HarrisRow {
  double f_rho;
  double delta_star;
};

// Seed 001 Table 1, in order of increasing F(ρ).
constexpr HarrisRow kHarrisTable[] = {
    {0.0, 1.0},           {0.1075, 0.997},     {0.3204, 0.9761},    {0.4795, 0.9429},
    {0.5916, 0.9077},     {0.6716, 0.8733},    {0.7332, 0.8394},    {0.7948, 0.7961},
    {0.83595, 0.7602},    {0.87366, 0.7169},   {0.90999, 0.6636},   {0.93657, 0.6112},
    {0.95738, 0.5551},    {0.97290, 0.4960},   {0.983797, 0.4352},  {0.990902, 0.3745},
    {0.995112, 0.3176},  // printed "3176" (OCR dropped "0.")
    {0.997300, 0.2705},   {0.9981847, 0.2427}, {0.9989156, 0.2106}, {0.9994785, 0.17167},
    {0.9998527, 0.11995}, {1.0, 0.0},
};
constexpr std::size_t kRows = sizeof(kHarrisTable) / sizeof(kHarrisTable[0]);

// Interpolation abscissa; decreasing in F, so the table is stored reversed.
double abscissa(double f_rho) {
  return std::cbrt(1.0 - f_rho);
}

class HarrisTableHertz final : public HertzSolution {
 public:
  HarrisTableHertz() : exact_(make_exact_hertz()), interp_(nullptr, &gsl_interp_free) {
    for (std::size_t i = 0; i < kRows; ++i) {
      const HarrisRow& row = kHarrisTable[kRows - 1 - i];
      x_[i] = abscissa(row.f_rho);
      y_[i] = row.delta_star;
    }
    interp_.reset(gsl_interp_alloc(gsl_interp_steffen, kRows));
    gsl_interp_init(interp_.get(), x_, y_, kRows);
  }

  HertzShape shape(double f_rho) const override {
    detail::require_curvature_difference(f_rho, name());
    HertzShape s = exact_->shape(f_rho);
    s.delta_star = delta_star(f_rho);
    return s;
  }
  HertzMethod method() const override { return HertzMethod::harris_table; }

 private:
  double delta_star(double f_rho) const {
    // Table points are returned exactly, not through the (exact anyway) spline evaluation.
    for (const HarrisRow& row : kHarrisTable) {
      if (row.f_rho == f_rho) return row.delta_star;
    }
    // x ∈ (0, 1] for F ∈ [0, 1): inside the table range, so GSL's range check cannot fire.
    return gsl_interp_eval(interp_.get(), x_, y_, abscissa(f_rho), nullptr);
  }

  std::unique_ptr<HertzSolution> exact_;
  double x_[kRows];
  double y_[kRows];
  std::unique_ptr<gsl_interp, decltype(&gsl_interp_free)> interp_;
};

}  // namespace

std::unique_ptr<HertzSolution> make_harris_table_hertz() {
  return std::make_unique<HarrisTableHertz>();
}

}  // namespace bearing
