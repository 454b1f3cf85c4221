#pragma once
// The geometry of a local defect (a spall: a slot of width w, along the race, and depth h in a
// raceway) as the ball that rolls over it sees it: the extra radial clearance it gains, as a
// function of where the ball is along the slot. Issue 17's first building block; no model uses it
// yet.
//
// Model: the ball's curvature bounds the drop (the ball path over a spall of Sawalhi & Randall,
// "Simulating gear and bearing interactions in the presence of faults, Part I", Mech. Syst.
// Signal Process. 22 (2008) 1924–1951). In the rolling plane the ball is a circle of radius
// R = D/2 and the raceway a circle of radius ρ (inner: convex, the ball outside it; outer:
// concave, the ball inside). A slot edge seen at angle φ from the ball's contact point, measured
// at the race's centre, is at half-chord a = ρ sin φ; the ball pivoting on it lies lower than on
// the intact race by
//   s(φ) = [R − √(R² − a²)] ± ρ (1 − cos φ)        (+ inner, − outer),
// the ball's sag over the chord plus (convex) or minus (concave) the race's own sag over it.
// Entering, it pivots on the entry edge (φ = u/ρ for the ball's contact an arc u past it);
// leaving, on the exit edge (φ = (w − u)/ρ); in the middle on both; never below the floor:
//   drop(u) = min( s(u/ρ), s((w − u)/ρ), h ),   max drop = min( s(w/2ρ), h ),
// and h when a ≥ R (the ball reaches the floor). Limits: w → 0 gives no drop (s ≈ (w²/8)(1/R ±
// 1/ρ) → 0); a slot wider than the ball and shallower than its sag gives the full depth h. The
// race term matters: for the 6205's outer race (R = 3.97 mm, ρ = 23.5 mm) it takes 17 % off the
// ball's sag; a flat-race model (ρ → ∞) overstates the outer race's drop by R/ρ.

#include "bearing/contact.h"

namespace bearing {

/// Extra clearance [m] when the ball's contact point is an arc u [m] past the slot's entry edge
/// on `race` of radius race_radius [m] (groove bottom: inner d_i/2, outer d_o/2): min(s(u/ρ),
/// s((w − u)/ρ), h) for 0 < u < w, else 0. Continuous in u, 0 at both edges, symmetric about
/// w/2. Throws InputError naming the field (`defects.width`, `defects.depth`, …) for a negative
/// or non-finite size, or an outer race not larger than the ball.
double defect_drop(double ball_diameter, Race race, double race_radius, double width, double depth,
                   double u);

/// The largest extra clearance over the slot, at u = w/2 [m].
double defect_max_drop(double ball_diameter, Race race, double race_radius, double width,
                       double depth);

}  // namespace bearing
