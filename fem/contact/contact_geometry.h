#pragma once
// The geometry of a contact reference (private to fem/contact): the body's coarse mesh with its
// manifolds and boundary ids, and the gap to the rigid indenter. The contact solver
// (hertz_contact.cc) is the same for every geometry; a new geometry is a new implementation of
// this interface.
//
// Frame: the first contact point is the origin, z points from the elastic body into the rigid
// one (the body lies in z ≤ 0 near the contact), x is the rolling direction (minor semi-axis b),
// y the transverse one (major semi-axis a). Only the quarter x ≥ 0, y ≥ 0 is meshed.

#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>

#include <memory>
#include <string>

#include "hertz_contact.h"

namespace bearing::fem {

/// Boundary ids every geometry sets on its coarse mesh.
namespace boundary {
constexpr dealii::types::boundary_id symmetry_x = 0;  ///< x = 0: u_x = 0
constexpr dealii::types::boundary_id free_x = 1;      ///< traction free
constexpr dealii::types::boundary_id symmetry_y = 2;  ///< y = 0: u_y = 0
constexpr dealii::types::boundary_id free_y = 3;      ///< traction free
constexpr dealii::types::boundary_id clamped = 4;     ///< u = 0
constexpr dealii::types::boundary_id contact = 5;     ///< candidate contact surface
}  // namespace boundary

/// Size of the meshed domain, for the result and the messages.
struct DomainSize {
  double x = 0, y = 0, z = 0;  ///< extents [m]
};

class ContactGeometry {
 public:
  virtual ~ContactGeometry() = default;

  /// Creates the coarse mesh in `tria`, with boundary ids (namespace boundary) and manifolds.
  virtual DomainSize make_coarse_grid(
      dealii::parallel::distributed::Triangulation<3>& tria) const = 0;

  /// Number of refinement levels the coarse mesh needs to reach cells of size h_x near the
  /// contact (the refinement stops there anyway; this bounds the sweeps).
  virtual unsigned int levels_to(double finest_hx) const = 0;

  /// Whether every cell is an axis-parallel box whose size depends on its level only (then one
  /// element matrix per level serves all cells).
  virtual bool cells_are_level_boxes() const = 0;

  /// G(p, δ): the gap along z between the undeformed surface point p and the rigid surface after
  /// the approach δ (negative: geometric overlap) [m].
  virtual double gap(const dealii::Point<3>& p, double approach) const = 0;

  /// Depth of p below the contact surface (≤ 0 above it) [m], for the refinement toward the
  /// contact patch.
  virtual double depth(const dealii::Point<3>& p) const { return -p[2]; }

  /// One line for messages and contact.json.
  virtual std::string describe() const = 0;
};

/// The Hertz-reduced block and rigid paraboloid (hertz_contact.cc).
std::unique_ptr<ContactGeometry> make_hertz_block(const HertzContactParameters& p);

/// The ring segment with its true groove and the rigid sphere (raceway_segment.cc).
std::unique_ptr<ContactGeometry> make_raceway_segment(const HertzContactParameters& p);

}  // namespace bearing::fem
