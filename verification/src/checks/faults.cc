// Local defects (issue 17): a spall's drop against a construction of the ball's position over it,
// and the envelope lines of spalls on the outer race, the inner race and a ball against the
// textbook kinematics of the true preset geometry. The bearing is the CWRU-like 6205 of
// examples/cwru_6205_outer.toml (1797 rpm, 500 N down, a 0.533 mm wide, 0.28 mm deep spall).
//
// Where the lines are. An outer-race spall is struck by every ball once per ball pass: the
// impacts, and so the envelope of the ringing they start, repeat at BPFO. An inner-race spall is
// struck at BPFI (its strength modulated at f_r as it turns through the load zone: sidebands
// BPFI ± f_r); a ball spall strikes both races once per ball revolution relative to the cage,
// 2·BSF (modulated at the cage speed). The checks take the envelope spectrum over a record of
// whole periods of the expected line, so the line sits on a bin.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../families.h"
#include "bearing/constants.h"
#include "bearing/envelope_analysis.h"
#include "bearing/local_defect.h"
#include "bearing/models/two_dof.h"
#include "bearing/presets.h"
#include "dynamics_closed_forms.h"
#include "dynamics_runs.h"

namespace bearing::verify {

namespace {

using namespace dynamics;
namespace cf = closed_form;

constexpr double kShaft = 1797.0 / 60.0;  // [Hz]
constexpr double kWidth = 0.533e-3, kDepth = 0.28e-3;

// The CWRU-like case with one spall: outer at the bottom (where ball 0 starts), inner at 0° on
// the ring, or on ball 0 a quarter turn from its outer contact (ψ₀ = 90°).
ModelInputs spalled(const Context& ctx, DefectLocation where) {
  ModelInputs in = case_inputs(
      ctx, {"bearing.preset=6205", "operation.speed=1797 rpm", "operation.load=[0, -500]"});
  LocalDefect d;
  d.location = where;
  d.width = kWidth;
  d.depth = kDepth;
  d.position = where == DefectLocation::outer  ? kBottom
               : where == DefectLocation::ball ? 0.5 * pi
                                               : 0.0;
  in.defects = {d};
  return in;
}

// The expected line [Hz] of the true 6205: BPFO, BPFI or 2·BSF = 2 (d_m/D)(1 + g) f_c.
double expected_line(DefectLocation where) {
  const Bearing b = preset("6205");
  const cf::Kinematics k = cf::kinematics(b, kShaft);
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  switch (where) {
    case DefectLocation::outer:
      return k.bpfo;
    case DefectLocation::inner:
      return k.bpfi;
    case DefectLocation::ball:
      break;
  }
  return 2 * b.pitch_diameter / b.ball_diameter * (1 + g) * k.cage;
}

// The names of the expected line and its second and third harmonics.
std::vector<std::string> line_names(DefectLocation where) {
  if (where == DefectLocation::ball) return {"2xBSF", "4xBSF", "6xBSF"};
  const std::string f = where == DefectLocation::outer ? "BPFO" : "BPFI";
  return {f, "2x" + f, "3x" + f};
}

Outcome spall_line(const Context& ctx, DefectLocation where) {
  const double expected = expected_line(where);
  RunSpec s;
  s.duration = 2.1;
  s.transient = 0.1;
  s.rate = 48000.0;
  const ModelInputs in = spalled(ctx, where);
  const Response r = run(ctx, in, s);
  const std::vector<double> steady = r.steady("ay");
  const double periods = std::floor(double(steady.size()) * expected / r.rate);
  const auto n = static_cast<std::size_t>(std::lround(periods * r.rate / expected));
  const std::vector<double> x(steady.begin(), steady.begin() + long(std::min(n, steady.size())));
  // The labels only: the toolkit's frequencies of the (perturbed) model inputs.
  const BearingFrequencies f = bearing_frequencies(in.bearing, in.inner_speed);
  const EnvelopeSummary e = analyse_envelope("ay", "m/s^2", x, r.rate, f,
                                             {EnvelopeBandSource::automatic, {}}, Window::hann, 40);
  Outcome o;
  double best = 0;
  for (const Peak& p : e.peaks)
    if (std::fabs(p.frequency / expected - 1) < 0.03 && p.amplitude > best)
      best = p.amplitude, o.value = p.frequency;
  o.reference = expected;
  o.detail = "envelope of ay in " + band_text(e.band) + " (kurtogram), spectral kurtosis " +
             fmt(e.spectral_kurtosis, 3) + "; " + std::to_string(x.size()) + " samples, bin " +
             fmt(e.spectrum.resolution, 6) + " Hz";
  const std::string where_name = name_of(kDefectLocations, where);
  Series sp{"envelope spectrum", {}, {}, "line"};
  for (std::size_t k = 1;
       k < e.spectrum.frequency.size() && e.spectrum.frequency[k] <= 4.5 * expected; ++k)
    sp.x.push_back(e.spectrum.frequency[k]), sp.y.push_back(e.spectrum.amplitude[k]);
  o.figures = {Figure{"dynamics-spall-" + where_name,
                      "6205, 1797 rpm, 500 N: 0.533 mm spall, " + where_name,
                      "frequency [Hz]",
                      "envelope of ay [m/s^2]",
                      false,
                      false,
                      {sp},
                      {{expected, line_names(where)[0]},
                       {2 * expected, line_names(where)[1]},
                       {3 * expected, line_names(where)[2]}},
                      Panel::spectrum}};
  return o;
}

// The ball's centre over a slot of width w in the outer race (radius ρ): on the bisector, where it
// touches both edge points, by bisection on its distance from the race centre; the drop is how
// much farther out that is than on the intact race (ρ − R).
double constructed_outer_drop(double D, double rho, double w) {
  const double R = 0.5 * D, phi = w / (2 * rho), ex = rho * std::cos(phi), ey = rho * std::sin(phi);
  double lo = rho - 2 * R, hi = ex;  // |c − edge| − R: > 0 at lo, < 0 at hi
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::hypot(mid - ex, ey) - R > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) - (rho - R);
}

Outcome spall_drop(const Context& ctx) {
  const ModelInputs in = ctx.perturbed(spalled(ctx, DefectLocation::outer));
  ModelInputs intact = in;
  intact.defects.clear();
  // Ball 0 sits over the defect's centre at t = 0: its approach falls by the drop.
  const double q[2] = {0.0, 0.0};
  std::vector<double> a(9), b(9);
  make_two_dof_model(in)->ball_approaches(0.0, q, a.data());
  make_two_dof_model(intact)->ball_approaches(0.0, q, b.data());
  const Bearing truth = preset("6205");
  Outcome o;
  o.value = b[0] - a[0];
  o.reference =
      constructed_outer_drop(truth.ball_diameter, 0.5 * truth.outer_raceway_diameter(), kWidth);
  o.detail = "the other balls' approaches change by " + fmt(std::fabs(a[4] - b[4]), 3) + " m";
  return o;
}

}  // namespace

std::vector<Check> fault_checks() {
  const char* line_why =
      "the record holds whole periods of the expected line, so it sits on a bin (0.5 Hz) and the "
      "parabolic vertex of the Hann log-spectrum is unbiased; the nearest other lines (the f_r "
      "or FTF sidebands, >= 24 bins away) shift it through the Hann sidelobes by < 1e-3 bin; "
      "bound 0.02 Hz, a twentieth of the 0.27 Hz a 1 % error of d_m makes";
  const auto line = [&](DefectLocation where, const char* name, const char* what) {
    const std::string on = where == DefectLocation::ball ? "ball 0" : std::string(name) + " race";
    return Check{std::string("dynamics.spall-envelope-line.") + name + ".6205",
                 "dynamics",
                 ReferenceKind::closed_form,
                 std::string("value: frequency of the strongest envelope line near ") + what +
                     " of ay, 2-DOF 6205 at 1797 rpm under 500 N with a 0.533 mm spall on the " +
                     on + " (RK4 5 us, 2 s at 48 kHz, band by the kurtogram); reference: " + what +
                     " of the preset geometry (textbook kinematics written here)",
                 std::string(what) + " line",
                 "Hz",
                 absolute(0.02, line_why),
                 Level::quick,
                 0.6,
                 {"pitch-diameter-x1.01"},
                 [where](const Context& ctx) { return spall_line(ctx, where); }};
  };
  return {
      {"dynamics.spall-drop.outer.6205",
       "dynamics",
       ReferenceKind::closed_form,
       "value: the fall of ball 0's approach when it sits over the centre of a 0.533 mm outer-race "
       "spall (2-DOF model, ring centred); reference: the ball's centre constructed here, touching "
       "both edges of the slot in the true 6205's outer raceway (bisection)",
       "drop",
       "m",
       relative(1e-9,
                "the construction is exact to the bisection's 1e-16 m; the model's drop is the "
                "closed form of the same geometry, rounding only (7.4 um)"),
       Level::quick,
       0.01,
       {"spall-width-x0.8", "pitch-diameter-x1.01"},
       spall_drop},
      line(DefectLocation::outer, "outer", "BPFO"),
      line(DefectLocation::inner, "inner", "BPFI"),
      line(DefectLocation::ball, "ball", "2xBSF"),
  };
}

}  // namespace bearing::verify
