#pragma once
// Local defects (spalls): a slot of width w, along the rolling direction, and depth h in a
// raceway or on a ball, and the extra clearance (the "drop") a rolling contact gains over it
// (docs/model.md §5; case table [[defects]]).
//
// Model: the other body's curvature bounds the drop (the ball path over a spall of Sawalhi &
// Randall, "Simulating gear and bearing interactions in the presence of faults, Part I", Mech.
// Syst. Signal Process. 22 (2008) 1924–1951). In the rolling plane each body is a circle: the
// slotted surface of radius r_s (a race, or the ball), and the pivoting body of radius r_p that
// rolls over the slot (the ball, or a race). An edge at angle φ from the contact point, measured
// at the slotted surface's centre, is at half-chord a = r_s sin φ; the pivoting body resting on it
// lies lower than on the intact surface by
//   s(φ) = σ_p [r_p − √(r_p² − a²)] + σ_s r_s (1 − cos φ),
// each body's sag over the chord, σ = +1 for a convex surface (the ball, the inner race) and −1 for
// a concave one (the outer race). Race defect: r_s = ρ the race, r_p = R = D/2 the ball; ball
// defect: r_s = R, r_p = ρ the race it touches. Entering, the contact pivots on the entry edge
// (φ = u/r_s for the contact point an arc u past it); leaving, on the exit edge (φ = (w − u)/r_s);
// in the middle on both; never below the floor:
//   drop(u) = min( s(u/r_s), s((w − u)/r_s), h ),   max drop H = min( s(w/2r_s), h ),
// and h when a ≥ r_p (the ball reaches the floor). Limits: w → 0 gives no drop (s ≈ (w²/8)(1/R ±
// 1/ρ) → 0); a slot wider than the ball and shallower than its sag gives the full depth h. The race
// term matters: for the 6205's outer race (R = 3.97 mm, ρ = 23.5 mm) it takes 17 % off the ball's
// sag; a flat-race model (ρ → ∞) overstates the outer race's drop by R/ρ.
//
// Profiles: "rectangular" is the slot with sharp edges above (the contact's path follows the
// pivot geometry); "smooth" is a worn spall with rounded edges, drop(u) = H sin(πu/w), the same
// maximum drop H entered and left along a half sine.
//
// Where the contact is on the defect (u) as time goes on: outer race, fixed in the housing at
// angle φ_d, under ball j at θ_j: u = ρ_o·wrap(θ_j − φ_d) + w/2; inner race, turning with the
// shaft: u = ρ_i·wrap(θ_j − ω_i t − φ_d) + w/2; ball j, its defect at angle ψ from the ball's
// outer-race contact, ψ(t) = ψ₀ + ω_s t turning with the ball's rolling spin relative to the cage
// ω_s = (d_m/D)(1 + g) ω_c (g = D cos α/d_m; kinematics.h's BSF): u = R·wrap(ψ) + w/2 at the outer
// race and R·wrap(ψ − π) + w/2 at the inner race, one strike on each race per ball revolution.

#include <vector>

#include "bearing/bearing.h"
#include "bearing/choice.h"
#include "bearing/contact.h"

namespace bearing {

/// Where a spall is ([[defects]] location).
enum class DefectLocation { outer, inner, ball };
inline constexpr Named<DefectLocation> kDefectLocations[] = {{DefectLocation::outer, "outer"},
                                                             {DefectLocation::inner, "inner"},
                                                             {DefectLocation::ball, "ball"}};

/// The spall's edges ([[defects]] profile).
enum class DefectProfile { rectangular, smooth };
inline constexpr Named<DefectProfile> kDefectProfiles[] = {
    {DefectProfile::rectangular, "rectangular"}, {DefectProfile::smooth, "smooth"}};

/// One spall (one [[defects]] entry).
struct LocalDefect {
  DefectLocation location = DefectLocation::outer;
  /// outer: the defect centre's angle in the housing, from +x toward +y [rad]; inner: on the
  /// turning ring at t = 0; ball: the defect's angle on the ball from its outer-race contact at
  /// t = 0 [rad]
  double position = 0.0;
  int ball = 0;        ///< ball: which ball (0 … Z−1; ball 0 starts at model.cage_phase)
  double width = 0.0;  ///< w, along the rolling direction [m]
  double depth = 0.0;  ///< h [m]
  DefectProfile profile = DefectProfile::rectangular;
};

/// The rules of a bearing's defects; InputError names `defects[i].<field>`, the value and the
/// range: width in (0, D], depth in (0, D/4], position finite, ball in [0, Z − 1].
void check_defects(const std::vector<LocalDefect>& defects, const Bearing& bearing);

/// The radius of the surface the defect is in [m]: the inner or outer raceway (d_m ∓ D)/2, or the
/// ball D/2.
double defect_surface_radius(const LocalDefect& defect, const Bearing& bearing);

/// The drop one contact sees over one defect (see the top of this file): `contact` is the race
/// the contact is on (for a race defect: the defect's race).
class DefectPath {
 public:
  /// `bearing` and `defect` must satisfy check_defects (InputError otherwise).
  DefectPath(const Bearing& bearing, const LocalDefect& defect, Race contact);

  /// Extra clearance [m] with the contact point an arc u [m] past the entry edge, along the
  /// slotted surface; 0 outside (0, w). Continuous, 0 at both edges, symmetric about w/2.
  double drop(double u) const;
  /// d drop / du [-] (one-sided at the kinks: the right derivative).
  double slope(double u) const;
  /// The largest drop H, at u = w/2 [m].
  double max_drop() const { return max_drop_; }
  double width() const { return width_; }
  /// r_s, the slotted surface's radius [m] (u = r_s × the angle along it).
  double surface_radius() const { return surface_; }

 private:
  double pivot(double phi) const;        // s(φ), floored at 0 and capped at the depth
  double pivot_slope(double phi) const;  // ds/dφ where s is below the depth, else 0
  double surface_ = 0, surface_sign_ = 1, pivot_radius_ = 0, pivot_sign_ = 1;
  double width_ = 0, depth_ = 0, max_drop_ = 0;
  DefectProfile profile_ = DefectProfile::rectangular;
};

/// The ball's rolling spin relative to the cage, ω_s = (d_m/D)(1 + g) ω_c [rad/s] (2π × BSF
/// at the cage speed ω_c [rad/s], g = D cos(contact_angle)/d_m).
double ball_spin_speed(const Bearing& bearing, double cage_speed, double contact_angle);

/// Fixed steps per crossing of a defect that a run requires (solver.dt ≤ crossing time / this;
/// the adaptive methods' largest step): the entry and exit shape the impact, and at ten steps per
/// crossing the response's RMS is within 0.2 % of a step twelve times finer (the 0.533 mm outer
/// spall of the CWRU-like 6205: test DefectRuns.TheLargestAllowedStepResolvesTheImpacts).
inline constexpr double kStepsPerDefectCrossing = 10;

/// How long a contact takes to cross the defect [s]: w over the rolling speed of the contact
/// point along the slotted surface, outer ω_c ρ_o, inner |ω_i − ω_c| ρ_i, ball ω_s R; infinite
/// when it does not move. inner_speed ω_i and cage_speed ω_c [rad/s], contact_angle [rad].
double defect_transit_time(const LocalDefect& defect, const Bearing& bearing, double inner_speed,
                           double cage_speed, double contact_angle);

/// Extra clearance [m] of a ball over a rectangular race defect of width and depth [m] with the
/// contact an arc u [m] past its entry edge, on `race` of radius race_radius [m] (DefectPath for
/// one race defect, for callers with the plain numbers). Throws InputError naming the field
/// (`defects.width`, `defects.depth`, …) for a negative or non-finite size, or an outer race not
/// larger than the ball.
double defect_drop(double ball_diameter, Race race, double race_radius, double width, double depth,
                   double u);

/// The largest extra clearance over the slot, at u = w/2 [m].
double defect_max_drop(double ball_diameter, Race race, double race_radius, double width,
                       double depth);

}  // namespace bearing
