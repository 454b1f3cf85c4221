// The ring segment with its true groove, pressed by a rigid sphere (hertz_contact.h,
// RacewaySegment; the coarse mesh comes from meshes/raceway_segment.geo).
//
// Geometry in the contact frame (origin at the groove bottom under the ball, z toward the ball,
// y axial, x rolling). The bearing axis is the line {x = 0, z = z_a}, z_a = −R_b for the inner
// ring and +R_b for the outer ring; ρ is the distance from it. In the cross-section φ = 0 the
// groove is the circle of radius r_g about (y, z) = (0, r_g); turned about the axis it is a torus
// whose tube centre lies at ρ_c = R_b + r_g (inner) or R_b − r_g (outer). The ring's other faces
// are planes through the axis (x = 0 and the segment's end), planes y = const and cylinders
// ρ = const.
//
// Manifolds, so that refinement puts new vertices on the true surfaces: every cell and face uses
// a CylindricalManifold about the bearing axis (new points interpolated in φ, ρ, y: exact on the
// planes and cylinders), and the groove faces a manifold that does the same and then moves the
// point onto the torus along the tube's radius in its (y, ρ) half-plane.
//
// Boundary ids from the coarse mesh's geometry (all vertices of a face on the surface):
// x = 0 symmetry_x; y = 0 symmetry_y; ρ = back_radius clamped; the torus (within the groove)
// contact; the rest (segment end, land, ring side) free.

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "contact_geometry.h"

namespace bearing::fem {

using namespace dealii;

namespace {

constexpr int dim = 3;

// Distance from the bearing axis and the axial coordinate of p.
struct AxisCoordinates {
  double rho, y;
};

class RingGeometry {
 public:
  explicit RingGeometry(const RacewaySegment& r)
      : axis_z(r.outer ? r.groove_bottom : -r.groove_bottom),
        tube_rho(r.outer ? r.groove_bottom - r.groove_radius : r.groove_bottom + r.groove_radius),
        tube_radius(r.groove_radius) {}
  AxisCoordinates axis_coordinates(const Point<dim>& p) const {
    return {std::hypot(p[0], p[2] - axis_z), p[1]};
  }
  // p moved onto the groove torus along the tube radius through it (same φ).
  Point<dim> onto_torus(const Point<dim>& p) const {
    const AxisCoordinates c = axis_coordinates(p);
    const double dr = c.rho - tube_rho, dy = c.y, d = std::hypot(dr, dy);
    if (d == 0) return p;
    const double rho = tube_rho + dr * tube_radius / d, y = dy * tube_radius / d;
    const double s = rho / c.rho;  // same direction from the axis
    return Point<dim>(p[0] * s, y, axis_z + (p[2] - axis_z) * s);
  }
  // Distance below the groove surface, continued into the whole ring (the material lies outside
  // the tube for both rings).
  double depth(const Point<dim>& p) const {
    const AxisCoordinates c = axis_coordinates(p);
    return std::hypot(c.rho - tube_rho, c.y) - tube_radius;
  }
  double torus_distance(const Point<dim>& p) const {
    const AxisCoordinates c = axis_coordinates(p);
    return std::abs(std::hypot(c.rho - tube_rho, c.y) - tube_radius);
  }
  Point<dim> axis_point() const { return Point<dim>(0, 0, axis_z); }

 private:
  double axis_z, tube_rho, tube_radius;
};

// Cylindrical interpolation, then onto the torus.
class GrooveManifold final : public CylindricalManifold<dim> {
 public:
  explicit GrooveManifold(const RingGeometry& ring)
      : CylindricalManifold<dim>(Tensor<1, dim>({0.0, 1.0, 0.0}), ring.axis_point()), ring(ring) {}
  std::unique_ptr<Manifold<dim>> clone() const override {
    return std::make_unique<GrooveManifold>(ring);
  }
  Point<dim> get_new_point(const ArrayView<const Point<dim>>& points,
                           const ArrayView<const double>& weights) const override {
    return ring.onto_torus(CylindricalManifold<dim>::get_new_point(points, weights));
  }

 private:
  RingGeometry ring;
};

class RacewaySegmentGeometry final : public ContactGeometry {
 public:
  explicit RacewaySegmentGeometry(const HertzContactParameters& p)
      : prm(p), r(p.raceway), ring(p.raceway) {
    if (!(r.ball_radius > 0 && r.groove_radius > r.ball_radius && r.groove_bottom > 0 &&
          r.back_radius > 0 && r.half_width > 0 && r.land_depth > 0))
      throw std::invalid_argument(
          "RacewaySegment: radii, half-width and land depth must be positive, and the groove "
          "radius larger than the ball's");
    if (r.coarse_mesh.empty()) throw std::invalid_argument("RacewaySegment: no coarse mesh given");
  }

  DomainSize make_coarse_grid(parallel::distributed::Triangulation<dim>& tria) const override {
    std::ifstream in(r.coarse_mesh);
    if (!in) throw std::runtime_error("cannot read the coarse mesh " + r.coarse_mesh);
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(tria);
    grid_in.read_msh(in);

    const double tol = 1e-7 * r.groove_radius;
    BoundingBox<dim> all;
    bool first = true;
    for (const auto& cell : tria.active_cell_iterators()) {
      cell->set_all_manifold_ids(0);
      const BoundingBox<dim> box = cell->bounding_box();
      if (first) all = box, first = false;
      all.merge_with(box);
    }
    for (const auto& cell : tria.active_cell_iterators())
      for (const auto& face : cell->face_iterators()) {
        if (!face->at_boundary()) continue;
        bool x0 = true, y0 = true, back = true, groove = true;
        for (unsigned int v = 0; v < face->n_vertices(); ++v) {
          const Point<dim> q = face->vertex(v);
          x0 &= std::abs(q[0]) < tol;
          y0 &= std::abs(q[1]) < tol;
          back &= std::abs(ring.axis_coordinates(q).rho - r.back_radius) < tol;
          groove &= ring.torus_distance(q) < tol && q[2] < r.land_depth + tol;
        }
        if (x0)
          face->set_boundary_id(boundary::symmetry_x);
        else if (y0)
          face->set_boundary_id(boundary::symmetry_y);
        else if (back)
          face->set_boundary_id(boundary::clamped);
        else if (groove) {
          face->set_boundary_id(boundary::contact);
          face->set_all_manifold_ids(1);
        } else
          face->set_boundary_id(boundary::free_x);
      }
    tria.set_manifold(0,
                      CylindricalManifold<dim>(Tensor<1, dim>({0.0, 1.0, 0.0}), ring.axis_point()));
    tria.set_manifold(1, GrooveManifold(ring));

    const auto [lo, hi] = all.get_boundary_points();
    coarse_hx = 0;
    for (const auto& cell : tria.active_cell_iterators()) {
      const BoundingBox<dim> box = cell->bounding_box();
      const auto [clo, chi] = box.get_boundary_points();
      coarse_hx = std::max(coarse_hx, chi[0] - clo[0]);
    }
    return DomainSize{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  }

  unsigned int levels_to(double finest_hx) const override {
    return static_cast<unsigned int>(std::max(0.0, std::ceil(std::log2(coarse_hx / finest_hx))));
  }
  bool cells_are_level_boxes() const override { return false; }
  double depth(const Point<dim>& p) const override { return ring.depth(p); }

  double gap(const Point<dim>& p, double approach) const override {
    const double x2 = p[0] * p[0], y2 = p[1] * p[1];
    if (r.paraboloid_gap) return x2 / (2 * prm.radius_x) + y2 / (2 * prm.radius_y) - approach;
    const double R = r.ball_radius;
    if (x2 + y2 >= R * R) return R;  // beyond the sphere's silhouette: never in contact
    return (R - approach - std::sqrt(R * R - x2 - y2)) - p[2];
  }

  std::string describe() const override {
    return std::string(r.outer ? "outer" : "inner") +
           " ring segment with its true groove (gmsh meshes/raceway_segment.geo), E = (1-nu^2) "
           "E* (equivalent modulus: ball compliance in the ring), clamped " +
           (r.outer ? "outside diameter" : "bore") + ", " +
           (r.paraboloid_gap ? "Hertz's paraboloid gap (finite-ring effect only)"
                             : "rigid sphere of the ball's radius, exact gap along z");
  }

 private:
  HertzContactParameters prm;
  RacewaySegment r;
  RingGeometry ring;
  mutable double coarse_hx = 0;
};

// The last `n` lines of the text file `path`, joined by " | " ("" if it cannot be read).
std::string last_lines(const std::string& path, std::size_t n) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  std::string out;
  for (std::size_t k = lines.size() > n ? lines.size() - n : 0; k < lines.size(); ++k)
    out += (out.empty() ? "" : " | ") + lines[k];
  return out;
}

}  // namespace

void mesh_raceway_segment(RacewaySegment& r, double groove_depth, double segment_angle,
                          const std::string& msh, const std::string& log, MPI_Comm comm) {
  if (!(groove_depth > 0 && segment_angle > 0 && segment_angle < pi / 2))
    throw std::invalid_argument(
        "mesh_raceway_segment: groove depth and segment angle out of range");
  // The land depth as raceway_segment.geo computes it (a groove wider than the ring ends at 95 %
  // of the half-width).
  double h = groove_depth;
  const double cos_s = std::max(-0.999, 1 - h / r.groove_radius);
  const double y_s = r.groove_radius * std::sqrt(1 - cos_s * cos_s);
  if (y_s > 0.95 * r.half_width) {
    const double y = 0.95 * r.half_width;
    h = r.groove_radius - std::sqrt(r.groove_radius * r.groove_radius - y * y);
  }
  r.land_depth = h;
  r.coarse_mesh = msh;
  int status = 0;
  if (Utilities::MPI::this_mpi_process(comm) == 0) {
    std::ostringstream cmd;
    // -format msh: the version the .geo sets, whatever `msh` ends with (a temporary name).
    cmd << std::setprecision(17) << '"' << BEARING_GMSH << "\" -3 -v 2 -format msh -setnumber race "
        << (r.outer ? 1 : 0) << " -setnumber groove_radius " << r.groove_radius
        << " -setnumber groove_bottom " << r.groove_bottom << " -setnumber groove_depth "
        << groove_depth << " -setnumber back_radius " << r.back_radius << " -setnumber half_width "
        << r.half_width << " -setnumber segment_angle " << segment_angle << " \""
        << BEARING_MESH_DIR << "/raceway_segment.geo\" -o \"" << msh << "\" > \"" << log
        << "\" 2>&1";
    status = std::system(cmd.str().c_str());
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  if (status != 0)
    // The log's end in the message: the caller may write the log under a temporary name that
    // goes with the failed run.
    throw std::runtime_error("gmsh failed on " + std::string(BEARING_MESH_DIR) +
                             "/raceway_segment.geo" +
                             (Utilities::MPI::this_mpi_process(comm) == 0
                                  ? ": " + last_lines(log, 5)
                                  : std::string(" (rank 0 shows gmsh's output)")));
}

std::unique_ptr<ContactGeometry> make_raceway_segment(const HertzContactParameters& p) {
  return std::make_unique<RacewaySegmentGeometry>(p);
}

}  // namespace bearing::fem
