// HelmholtzRadiation: the exterior Helmholtz problem of helmholtz_radiation.h, in the shape of
// deal.II's step-29 (real and imaginary parts as two components, because Debian's PETSc is real)
// with the perfectly matched layer of step-62 written for polar coordinates.
//
// ## Weak form
// Multiplying Δp + k²p = 0 by a test function q and integrating by parts over the fluid Ω, with
// the body's condition ∂p/∂n_Ω = −∂p/∂n_body = iωρ₀uΘ on its surface Γ_b (n_Ω points into the
// body):
//     ∫_Ω (∇p·∇q − k² p q) w dA = iωρ₀ ∫_Γb u Θ q w ds,
// with w = 1 (planar) or w = x (axisymmetric: the volume element 2πx dA, 2π cancelling).
//
// ## The layer
// Outside the physical zone (distance ρ from the origin > R₀) the radial coordinate is continued
// into the complex plane, ρ → ρ̃(ρ) = ρ − i Im(ρ̃), Im(ρ̃) ≥ 0 rising with ρ. An outgoing wave
// ∝ h(kρ̃) ~ e^{−ikρ̃} then decays by e^{−k Im ρ̃}, while inside ρ < R₀ nothing changes: the
// continued problem has the same solution there, for any profile (no reflection at the
// interface, only the discretisation's). With s_ρ = dρ̃/dρ and s_t = ρ̃/ρ, the Jacobian of the
// map x → x ρ̃/ρ is diag(s_ρ, s_t) (polar) or diag(s_ρ, s_t, s_t) (spherical), and the equation
// in the original coordinates is
//     ∇·(Λ ∇p) + k² β p = 0,   Λ = det J · J⁻¹J⁻ᵀ,   β = det J:
//     planar:        Λ = (s_t/s_ρ) ρ̂ρ̂ᵀ + (s_ρ/s_t)(I − ρ̂ρ̂ᵀ),    β = s_ρ s_t,
//     axisymmetric:  Λ = (s_t²/s_ρ) ρ̂ρ̂ᵀ + s_ρ (I − ρ̂ρ̂ᵀ),       β = s_ρ s_t²
// (in the meridian plane; the azimuthal row does not enter an axisymmetric field). The layer's
// outer circle carries p = 0.
//
// The profile. Step-62's σ/ω stretch decays by a frequency-independent factor, but at 100 Hz
// (kR₀ ~ 0.01) it maps the layer onto metres of complex distance within a fraction of a cell, and
// the near field ∝ 1/ρ̃ⁿ becomes a boundary layer no mesh resolves. Instead, per frequency:
//     Im ρ̃ = R₀ (e^{γξ} − 1 − γξ),   ξ = (ρ − R₀)/L ∈ [0, 1],
// with γ such that k R₀ (e^γ − 1 − γ) = σ₀, so that a wave decays by exactly e^{−σ₀} across the
// layer at every frequency, s_ρ − 1 = −i(R₀γ/L)(e^{γξ} − 1) starts from 0 (no jump at R₀), and
// |ρ̃| grows geometrically — a near field 1/ρ̃ⁿ falls like e^{−nγξ}, smooth on the layer's cells
// (γ ≈ 6 at 100 Hz for R₀ = 30 mm, below 1 at 20 kHz).
//
// ## Real form
// With p = p_r + i p_i and B = B_r + i B_i the complex-symmetric form above (B_r from Re Λ,
// Re β; B_i from Im Λ, Im β), the real system is
//     [ B_r  −B_i ] [p_r]   [ 0  ]
//     [ B_i   B_r ] [p_i] = [ F  ],   F_j = ωρ₀ ∫_Γb u Θ φ_j w ds,
// solved by UMFPACK: a 2-D problem of 10⁴–10⁵ unknowns, factorised once per frequency and reused
// for every motion (right-hand side).
//
// ## Microphones beyond the physical zone
// Outside a circle of radius R_c that holds every body the field is a sum of outgoing modes,
//     planar:        p(r, θ) = Σ_n c_n H_n⁽²⁾(kr)/H_n⁽²⁾(kR_c) e^{inθ},
//     axisymmetric:  p(r, θ) = Σ_n a_n h_n⁽²⁾(kr)/h_n⁽²⁾(kR_c) P_n(cos θ),
// whose coefficients are the FE field's on that circle: c_n by the trapezoidal rule in θ (spectral
// for a periodic function), a_n = (2n+1)/2 ∫ p P_n d(cos θ) by Gauss–Legendre. Since |H_n(x)| falls
// as x grows, continuing outward never amplifies the FE's error. So a microphone at 1 m costs no
// more than one at 1 cm; R_c lies between the bodies and R₀.

#include "radiation/helmholtz_radiation.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/numerics/roots.h"

namespace bearing::fem {
namespace {

using namespace dealii;
constexpr int dim = 2;
using cplx = std::complex<double>;

constexpr types::boundary_id kOuterBoundary = 100;  // the layer's outer circle: p = 0
constexpr types::boundary_id kAxis = 50;            // axisymmetric: x = 0, natural condition
// Body j's surface is boundary j + 1 and manifold kBodyManifold + j.
constexpr types::manifold_id kPolarManifold = 0, kCellManifold = 1, kBodyManifold = 10;

// Outgoing Hankel functions H_n⁽²⁾(x) (cylindrical) or h_n⁽²⁾(x) (spherical), n = 0 … up to
// n_max, by upward recurrence from the exact first two (stable for the Hankel function: above
// n ≈ x it is the dominant solution). Stops early where |h_n| would pass 1e250 (such modes are
// below rounding at any point outside the circle).
std::vector<cplx> outgoing_hankel(bool spherical, unsigned int n_max, double x) {
  std::vector<cplx> h;
  if (spherical) {
    const cplx e = std::exp(cplx(0, -x));
    h = {cplx(0, 1) * e / x, e * cplx(-x, 1) / (x * x)};
  } else {
    h = {cplx(gsl_sf_bessel_J0(x), -gsl_sf_bessel_Y0(x)),
         cplx(gsl_sf_bessel_J1(x), -gsl_sf_bessel_Y1(x))};
  }
  for (unsigned int n = 1; n < n_max; ++n) {
    const cplx next = (spherical ? 2.0 * n + 1 : 2.0 * n) / x * h[n] - h[n - 1];
    if (!(std::abs(next) < 1e250)) break;
    h.push_back(next);
  }
  return h;
}

// Legendre polynomials P_0 … P_n_max at μ.
std::vector<double> legendre(unsigned int n_max, double mu) {
  std::vector<double> p{1.0, mu};
  for (unsigned int n = 1; n < n_max; ++n)
    p.push_back(((2.0 * n + 1) * mu * p[n] - n * p[n - 1]) / (n + 1));
  p.resize(n_max + 1);
  return p;
}

// The layer's coefficients at a point: Λ (complex 2×2) and β.
struct LayerCoefficients {
  Tensor<2, dim> lambda_re, lambda_im;
  double beta_re = 1, beta_im = 0;
};

class PerfectlyMatchedLayer {
 public:
  PerfectlyMatchedLayer(RadiationGeometry geometry, double inner_radius, double thickness,
                        double attenuation, double wavenumber)
      : geometry_(geometry), r0_(inner_radius), l_(thickness) {
    gamma_ = growth(attenuation, wavenumber * r0_);
  }

  /// γ of a layer starting at kR₀: k R₀ (e^γ − 1 − γ) = σ₀, by bisection (the left side rises
  /// monotonically from 0).
  static double growth(double attenuation, double kr0) {
    const double target = attenuation / kr0;
    const auto below = [&](double g) { return std::expm1(g) - g < target; };
    // Only hi grows: the bisection starts from [0, hi].
    const double hi = numerics::grow_bracket(0, 1, below, std::numeric_limits<int>::max()).hi;
    numerics::BisectionOptions o;
    o.rel_width = 1e-15;
    const numerics::Bracket b = numerics::bisect(0, hi, below, o);
    return 0.5 * (b.lo + b.hi);
  }

  double gamma() const { return gamma_; }

  LayerCoefficients at(const Point<dim>& x) const {
    LayerCoefficients c;
    const double rho = x.norm();
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    if (rho <= r0_) {
      c.lambda_re = identity;
      return c;
    }
    const double xi = (rho - r0_) / l_;
    const cplx rho_t(rho, -r0_ * (std::expm1(gamma_ * xi) - gamma_ * xi));
    const cplx s_r(1.0, -r0_ * gamma_ / l_ * std::expm1(gamma_ * xi));
    const cplx s_t = rho_t / rho;
    cplx radial, tangential, beta;
    if (geometry_ == RadiationGeometry::planar) {
      radial = s_t / s_r, tangential = s_r / s_t, beta = s_r * s_t;
    } else {
      radial = s_t * s_t / s_r, tangential = s_r, beta = s_r * s_t * s_t;
    }
    const Tensor<1, dim> n = x / rho;
    const Tensor<2, dim> nn = outer_product(n, n);
    c.lambda_re = radial.real() * nn + tangential.real() * (identity - nn);
    c.lambda_im = radial.imag() * nn + tangential.imag() * (identity - nn);
    c.beta_re = beta.real(), c.beta_im = beta.imag();
    return c;
  }

 private:
  RadiationGeometry geometry_;
  double r0_, l_, gamma_ = 0;
};

class HelmholtzRadiation {
 public:
  explicit HelmholtzRadiation(const HelmholtzParameters& p);
  HelmholtzResult run(MPI_Comm comm);

 private:
  void check_parameters() const;
  void make_grid();
  void make_polar_grid();
  void mesh_section() const;
  void read_section_grid();
  void classify_boundaries();
  void setup_system();
  void assemble_system(double frequency);
  void solve();
  std::vector<std::vector<cplx>> microphone_pressures(double wavenumber) const;
  void setup_continuation();
  std::string output_results(std::size_t frequency_index) const;

  double weight(const Point<dim>& x) const {
    return prm.geometry == RadiationGeometry::axisymmetric ? x[0] : 1.0;
  }
  // Θ of a motion at a point of its body's surface.
  double pattern(const SurfaceMotion& m, const Point<dim>& x) const;

  HelmholtzParameters prm;
  double lambda_min = 0, r0 = 0, thickness = 0;
  unsigned int layers = 0;  // coarse cells across the layer

  Triangulation<dim> triangulation;
  // The degree-p mapping onto the manifolds, evaluated once per grid (the manifolds are slow).
  MappingQCache<dim> mapping;
  const FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
  AffineConstraints<double> constraints;
  SparsityPattern sparsity_pattern;
  SparseMatrix<double> system_matrix;
  std::vector<Vector<double>> system_rhs, solutions;
  // Each microphone's cell and reference-cell coordinates (found once).
  using CellPoint = std::pair<DoFHandler<dim>::active_cell_iterator, Point<dim>>;
  std::vector<CellPoint> microphone_cells;  // of the microphones not continued, in order
  std::vector<bool> continued;              // microphone i lies beyond R₀
  // The continuation circle: radius, modes, its points' cells, angles (planar) or Gauss nodes
  // cos θ_j and weights (axisymmetric).
  double r_c = 0;
  unsigned int n_modes = 0;
  std::vector<CellPoint> circle_cells;
  std::vector<double> circle_angle, circle_weight;
  // The pressure of each motion at the given points.
  std::vector<std::vector<cplx>> values_at(const std::vector<CellPoint>& points) const;
};

HelmholtzRadiation::HelmholtzRadiation(const HelmholtzParameters& p)
    : prm(p), mapping(std::max(1u, p.degree)), fe(FE_Q<dim>(std::max(1u, p.degree)), 2) {
  check_parameters();
  const double f_max = *std::max_element(prm.frequencies.begin(), prm.frequencies.end());
  lambda_min = prm.air.sound_speed / f_max;

  // The physical zone (radius R₀) holds every body with a margin.
  double extent = 0;
  for (const auto& b : prm.bodies) extent = std::max(extent, std::hypot(b.x, b.y) + b.radius);
  // Microphones within 3× the bodies' extent are evaluated in the mesh (which then reaches past
  // them); farther ones, and any beyond a given R₀, by the outgoing-mode continuation.
  double farthest_near = 0, farthest = 0;
  for (const auto& m : prm.microphones) {
    const double r = std::hypot(m[0], m[1]);
    farthest = std::max(farthest, r);
    if (r <= 3 * extent) farthest_near = std::max(farthest_near, r);
  }
  const double default_r0 = farthest > 3 * extent ? std::max(1.5 * extent, 1.1 * farthest_near)
                                                  : std::max(1.25 * extent, 1.1 * farthest_near);
  r0 = prm.physical_radius > 0 ? prm.physical_radius : default_r0;
  if (r0 <= 1.2 * extent)
    throw InputError("physical radius = " + std::to_string(r0) +
                     " m: must exceed 1.2 x the bodies' extent (" + std::to_string(extent) + " m)");
  r_c = extent + 0.8 * (r0 - extent);
  for (const auto& m : prm.microphones) continued.push_back(std::hypot(m[0], m[1]) > r_c);
  // The layer's thickness does not set its absorption (the profile does, per frequency), only the
  // oscillations a wave makes in it: half the shortest wavelength, or R₀/2 if less. Its cells:
  // the near field falls like e^{−nγξ} in it (n = 1 for a cylinder's dipole, 2 for a sphere's), so
  // about one e-fold per cell at the lowest frequency's γ, and no cell longer than the far-field
  // size.
  thickness = prm.pml_thickness > 0 ? prm.pml_thickness : std::min(0.5 * lambda_min, 0.5 * r0);
  const double f_min = *std::min_element(prm.frequencies.begin(), prm.frequencies.end());
  const double gamma_max =
      PerfectlyMatchedLayer::growth(prm.pml_attenuation, two_pi * f_min / prm.air.sound_speed * r0);
  const double order = prm.geometry == RadiationGeometry::planar ? 1 : 2;
  layers = prm.pml_layers > 0
               ? prm.pml_layers
               : static_cast<unsigned int>(std::ceil(std::max(
                     {4.0, order * gamma_max, thickness * prm.cells_per_wavelength / lambda_min})));
}

void HelmholtzRadiation::check_parameters() const {
  if (prm.bodies.empty()) throw InputError("radiation: no body given");
  if (prm.bodies.size() >= kAxis)  // boundary ids 1 … n of the bodies stay below the axis's
    throw InputError("radiation: " + std::to_string(prm.bodies.size()) + " bodies: at most " +
                     std::to_string(kAxis - 1));
  if (prm.motions.empty()) throw InputError("radiation: no surface motion given");
  if (prm.microphones.empty()) throw InputError("radiation: no microphone given");
  if (prm.frequencies.empty()) throw InputError("frequencies: none given");
  for (double f : prm.frequencies)
    if (!(f > 0 && std::isfinite(f)))
      throw InputError("frequencies: " + std::to_string(f) + " Hz: must be positive");
  if (!(prm.air.density > 0 && prm.air.sound_speed > 0))
    throw InputError("air: density and sound speed must be positive");
  if (prm.degree < 1 || prm.degree > 8)
    throw InputError("degree = " + std::to_string(prm.degree) + ": must be 1 to 8");
  if (!(prm.cells_per_wavelength > 0)) throw InputError("cells per wavelength must be positive");
  if (!(prm.cells_per_radius >= 4))
    throw InputError("cells per radius = " + std::to_string(prm.cells_per_radius) +
                     ": must be at least 4");
  if (!(prm.pml_attenuation > 0)) throw InputError("PML attenuation must be positive");
  for (const auto& b : prm.bodies) {
    if (!(b.radius > 0)) throw InputError("body radius must be positive");
    if (prm.geometry == RadiationGeometry::axisymmetric && b.x != 0)
      throw InputError("axisymmetric: a body must be centred on the axis (x = 0)");
  }
  if (prm.bodies.size() == 1 && (prm.bodies[0].x != 0 || prm.bodies[0].y != 0))
    throw InputError("a single body must be centred at the origin");
  if (prm.geometry == RadiationGeometry::axisymmetric && prm.bodies.size() > 1)
    throw InputError("axisymmetric: one body only");
  if (prm.bodies.size() > 1) {
    const RadiatingBody& ring = prm.bodies[0];
    if (ring.x != 0 || ring.y != 0)
      throw InputError("section: the first body (the ring) must be at the origin");
    const RadiatingBody& ball = prm.bodies[1];
    const double pitch = std::hypot(ball.x, ball.y);
    const double first_angle = std::atan2(ball.y, ball.x);
    for (std::size_t j = 1; j < prm.bodies.size(); ++j) {
      const auto& b = prm.bodies[j];
      const double expected = first_angle + two_pi * (j - 1) / (prm.bodies.size() - 1);
      if (std::abs(b.radius - ball.radius) > 1e-12 * ball.radius ||
          std::hypot(b.x - pitch * std::cos(expected), b.y - pitch * std::sin(expected)) >
              1e-9 * pitch)
        throw InputError("section: the balls must be equal and equally spaced on one pitch circle");
    }
    const double z = static_cast<double>(prm.bodies.size() - 1);
    if (!(ring.radius + ball.radius < pitch && ball.radius < pitch * std::sin(pi / z)))
      throw InputError("section: the ring and the balls must not touch (ring radius " +
                       std::to_string(ring.radius) + " m + ball radius " +
                       std::to_string(ball.radius) + " m must be below the pitch radius " +
                       std::to_string(pitch) + " m, and the balls apart)");
  }
  for (const auto& m : prm.motions)
    if (m.body >= prm.bodies.size()) throw InputError("motion " + m.name + ": no such body");
  for (const auto& m : prm.microphones) {
    if (prm.geometry == RadiationGeometry::axisymmetric && m[0] < 0)
      throw InputError("axisymmetric: a microphone must have x >= 0");
    for (const auto& b : prm.bodies)
      if (std::hypot(m[0] - b.x, m[1] - b.y) <= b.radius)
        throw InputError("microphone (" + std::to_string(m[0]) + ", " + std::to_string(m[1]) +
                         ") m lies inside a body");
  }
}

double HelmholtzRadiation::pattern(const SurfaceMotion& m, const Point<dim>& x) const {
  if (m.breathing) return 1.0;
  const RadiatingBody& b = prm.bodies[m.body];
  Tensor<1, dim> n;
  n[0] = x[0] - b.x, n[1] = x[1] - b.y;
  n /= n.norm();
  if (prm.geometry == RadiationGeometry::axisymmetric) return n[1];
  return n[0] * std::cos(m.direction) + n[1] * std::sin(m.direction);
}

// ## The grids
// One body at the origin: a polar grid, N cells around and radial cells growing geometrically
// (square cells: Δρ = ρ·2π/N) up to the far-field size λ_min/cells_per_wavelength, then the layer
// in equal cells. N is set by the body (cells_per_radius along a) and by the far-field size at
// the layer's outer circle. The whole grid carries the polar manifold, so with the degree-p
// mapping the circles are exact.
void HelmholtzRadiation::make_polar_grid() {
  const double a = prm.bodies[0].radius, r1 = r0 + thickness;
  const double h_far = lambda_min / prm.cells_per_wavelength;
  const bool axisym = prm.geometry == RadiationGeometry::axisymmetric;
  unsigned int n = static_cast<unsigned int>(
      std::ceil(std::max(two_pi * prm.cells_per_radius, two_pi * r1 / h_far)));
  n = 4 * ((n + 3) / 4);

  std::vector<double> radii{a};
  while (radii.back() < r0)
    radii.push_back(radii.back() + std::min(radii.back() * two_pi / n, h_far));
  if (radii.size() < 3) radii = {a, 0.5 * (a + r0), r0};  // at least two cells across
  const double stretch = (r0 - a) / (radii.back() - a);
  for (double& r : radii) r = a + (r - a) * stretch;
  radii.back() = r0;
  for (unsigned int i = 1; i <= layers; ++i) radii.push_back(r0 + thickness * i / layers);

  const unsigned int n_angles = axisym ? n / 2 + 1 : n;  // vertex columns
  const unsigned int n_sectors = axisym ? n / 2 : n;
  std::vector<Point<dim>> vertices;
  for (double r : radii)
    for (unsigned int j = 0; j < n_angles; ++j) {
      const double t = two_pi * j / n;
      vertices.push_back(axisym ? Point<dim>(r * std::sin(t), r * std::cos(t))
                                : Point<dim>(r * std::cos(t), r * std::sin(t)));
    }
  std::vector<CellData<dim>> cells;
  for (unsigned int i = 0; i + 1 < radii.size(); ++i)
    for (unsigned int j = 0; j < n_sectors; ++j) {
      const unsigned int jn = (j + 1) % n_angles;
      CellData<dim> c;
      c.vertices = {i * n_angles + j, (i + 1) * n_angles + j, i * n_angles + jn,
                    (i + 1) * n_angles + jn};
      cells.push_back(c);
    }
  GridTools::invert_all_negative_measure_cells(vertices, cells);
  triangulation.create_triangulation(vertices, cells, SubCellData());
  triangulation.set_all_manifold_ids(kPolarManifold);
  triangulation.set_manifold(kPolarManifold, PolarManifold<dim>(Point<dim>()));
}

// Several bodies (a bearing's 2-D section): gmsh meshes meshes/bearing_section.geo (quadrilaterals,
// sized by the bodies' curvature and the far-field wavelength); each body's surface then gets its
// own polar manifold, the outer circle the origin's, and the cells a transfinite interpolation of
// their boundaries, so refinement and the mapping follow the true circles.
void HelmholtzRadiation::mesh_section() const {
  const RadiatingBody& ring = prm.bodies[0];
  const RadiatingBody& ball = prm.bodies[1];
  const double pitch = std::hypot(ball.x, ball.y);
  const double first_angle = std::atan2(ball.y, ball.x);
  const std::string msh = prm.work_dir + "/bearing_section.msh";
  std::ostringstream cmd;
  // gmsh sizes before its all-quadrilateral subdivision, which halves them.
  cmd << std::setprecision(17) << '"' << BEARING_GMSH << "\" -2 -v 2"
      << " -setnumber ring_radius " << ring.radius << " -setnumber ball_radius " << ball.radius
      << " -setnumber pitch_radius " << pitch << " -setnumber first_angle " << first_angle
      << " -setnumber balls " << prm.bodies.size() - 1 << " -setnumber physical_radius " << r0
      << " -setnumber outer_radius " << r0 + thickness << " -setnumber h_layer "
      << 2 * thickness / layers << " -setnumber h_far " << 2 * lambda_min / prm.cells_per_wavelength
      << " -setnumber cells_per_turn " << std::ceil(pi * prm.cells_per_radius) << " \""
      << BEARING_MESH_DIR << "/bearing_section.geo\" -o \"" << msh << "\" > \"" << msh
      << ".log\" 2>&1";
  if (std::system(cmd.str().c_str()) != 0)
    throw std::runtime_error("gmsh failed on " + std::string(BEARING_MESH_DIR) +
                             "/bearing_section.geo (see " + msh + ".log)");
}

void HelmholtzRadiation::read_section_grid() {
  const std::string msh = prm.work_dir + "/bearing_section.msh";
  std::ifstream in(msh);
  if (!in) throw std::runtime_error("cannot read " + msh);
  GridIn<dim> grid_in;
  grid_in.attach_triangulation(triangulation);
  grid_in.read_msh(in);
}

void HelmholtzRadiation::classify_boundaries() {
  const double r1 = r0 + thickness;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto& face : cell->face_iterators()) {
      if (!face->at_boundary()) continue;
      auto on_circle = [&](double cx, double cy, double r) {
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          if (std::abs(std::hypot(face->vertex(v)[0] - cx, face->vertex(v)[1] - cy) - r) > 1e-6 * r)
            return false;
        return true;
      };
      if (on_circle(0, 0, r1)) {
        face->set_boundary_id(kOuterBoundary);
        continue;
      }
      bool found = false;
      for (std::size_t j = 0; j < prm.bodies.size() && !found; ++j)
        if (on_circle(prm.bodies[j].x, prm.bodies[j].y, prm.bodies[j].radius)) {
          face->set_boundary_id(static_cast<types::boundary_id>(j + 1));
          if (prm.bodies.size() > 1)
            face->set_manifold_id(static_cast<types::manifold_id>(kBodyManifold + j));
          found = true;
        }
      if (found) continue;
      if (prm.geometry == RadiationGeometry::axisymmetric &&
          std::abs(face->vertex(0)[0]) < 1e-9 * r1 && std::abs(face->vertex(1)[0]) < 1e-9 * r1) {
        face->set_boundary_id(kAxis);
        continue;
      }
      throw std::runtime_error(
          "radiation grid: a boundary face at (" + std::to_string(face->center()[0]) + ", " +
          std::to_string(face->center()[1]) + ") lies on no body, axis or outer circle");
    }
}

void HelmholtzRadiation::make_grid() {
  if (prm.bodies.size() == 1) {
    make_polar_grid();
    classify_boundaries();
  } else {
    read_section_grid();
    triangulation.set_all_manifold_ids(kCellManifold);
    classify_boundaries();
    for (const auto& cell : triangulation.active_cell_iterators())
      for (const auto& face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == kOuterBoundary)
          face->set_manifold_id(kPolarManifold);
    triangulation.set_manifold(kPolarManifold, PolarManifold<dim>(Point<dim>()));
    for (std::size_t j = 0; j < prm.bodies.size(); ++j)
      triangulation.set_manifold(static_cast<types::manifold_id>(kBodyManifold + j),
                                 PolarManifold<dim>(Point<dim>(prm.bodies[j].x, prm.bodies[j].y)));
    TransfiniteInterpolationManifold<dim> cells;
    cells.initialize(triangulation);
    triangulation.set_manifold(kCellManifold, cells);
  }
  triangulation.refine_global(prm.refinements);
  mapping.initialize(MappingQ<dim>(fe.degree), triangulation);
}

void HelmholtzRadiation::setup_system() {
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);
  DoFRenumbering::Cuthill_McKee(dof_handler);
  constraints.clear();
  VectorTools::interpolate_boundary_values(mapping, dof_handler, kOuterBoundary,
                                           Functions::ZeroFunction<dim>(2), constraints);
  constraints.close();
  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
  sparsity_pattern.copy_from(dsp);
  system_matrix.reinit(sparsity_pattern);
  system_rhs.assign(prm.motions.size(), Vector<double>(dof_handler.n_dofs()));
  solutions.assign(prm.motions.size(), Vector<double>(dof_handler.n_dofs()));

  microphone_cells.clear();
  for (std::size_t i = 0; i < prm.microphones.size(); ++i) {
    const auto& m = prm.microphones[i];
    if (continued[i]) continue;
    try {
      microphone_cells.push_back(
          GridTools::find_active_cell_around_point(mapping, dof_handler, Point<dim>(m[0], m[1])));
    } catch (...) {
      throw InputError("microphone (" + std::to_string(m[0]) + ", " + std::to_string(m[1]) +
                       ") m is not in the fluid");
    }
  }
  setup_continuation();
}

// The continuation circle's points: modes up to kR_c + 40 at the highest frequency (the bodies'
// near fields on R_c decay like (extent/R_c)^n ≈ 0.8^n), sampled by 2N + 16 equally spaced
// angles (planar) or N + 16 Gauss–Legendre nodes in cos θ (axisymmetric).
void HelmholtzRadiation::setup_continuation() {
  circle_cells.clear(), circle_angle.clear(), circle_weight.clear();
  if (std::none_of(continued.begin(), continued.end(), [](bool c) { return c; })) return;
  const double k_max = two_pi / lambda_min;
  n_modes = static_cast<unsigned int>(std::ceil(k_max * r_c)) + 40;
  std::vector<Point<dim>> points;
  if (prm.geometry == RadiationGeometry::planar) {
    const unsigned int m = 2 * n_modes + 16;
    for (unsigned int j = 0; j < m; ++j) {
      const double t = two_pi * j / m;
      circle_angle.push_back(t);
      points.emplace_back(r_c * std::cos(t), r_c * std::sin(t));
    }
  } else {
    const unsigned int m = n_modes + 16;
    gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(m);
    for (unsigned int j = 0; j < m; ++j) {
      double mu = 0, w = 0;
      gsl_integration_glfixed_point(-1, 1, j, &mu, &w, table);
      circle_angle.push_back(mu);  // cos θ_j
      circle_weight.push_back(w);
      points.emplace_back(r_c * std::sqrt(std::max(0.0, 1 - mu * mu)), r_c * mu);
    }
    gsl_integration_glfixed_table_free(table);
  }
  for (const auto& x : points)
    circle_cells.push_back(GridTools::find_active_cell_around_point(mapping, dof_handler, x));
}

void HelmholtzRadiation::assemble_system(double frequency) {
  const double omega = two_pi * frequency, k = omega / prm.air.sound_speed;
  const PerfectlyMatchedLayer layer(prm.geometry, r0, thickness, prm.pml_attenuation, k);
  system_matrix = 0;
  for (auto& b : system_rhs) b = 0;

  // The layer's coefficients vary on the scale L/γ: one more Gauss point than the degree needs.
  const QGauss<dim> quadrature(fe.degree + 2);
  const QGauss<dim - 1> face_quadrature(fe.degree + 1);
  FEValues<dim> fe_values(
      mapping, fe, quadrature,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  FEFaceValues<dim> fe_face_values(mapping, fe, face_quadrature,
                                   update_values | update_quadrature_points | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  std::vector<Vector<double>> cell_rhs(prm.motions.size(), Vector<double>(n));
  std::vector<types::global_dof_index> dofs(n);
  std::vector<unsigned int> component(n);
  for (unsigned int i = 0; i < n; ++i) component[i] = fe.system_to_component_index(i).first;
  std::vector<double> phi(n);
  std::vector<Tensor<1, dim>> grad(n), lambda_re_grad(n), lambda_im_grad(n);

  for (const auto& cell : dof_handler.active_cell_iterators()) {
    fe_values.reinit(cell);
    cell_matrix = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      const Point<dim>& x = fe_values.quadrature_point(q);
      const LayerCoefficients c = layer.at(x);
      const double dx = fe_values.JxW(q) * weight(x);
      for (unsigned int i = 0; i < n; ++i) {
        phi[i] = fe_values.shape_value(i, q);
        grad[i] = fe_values.shape_grad(i, q);
        lambda_re_grad[i] = c.lambda_re * grad[i];
        lambda_im_grad[i] = c.lambda_im * grad[i];
      }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j) {
          // B_r = ∫Re Λ ∇φ_j·∇φ_i − k² Re β φ_j φ_i, B_i likewise; blocks [B_r −B_i; B_i B_r].
          const double br = lambda_re_grad[j] * grad[i] - k * k * c.beta_re * phi[j] * phi[i];
          const double bi = lambda_im_grad[j] * grad[i] - k * k * c.beta_im * phi[j] * phi[i];
          if (component[i] == component[j])
            cell_matrix(i, j) += br * dx;
          else
            cell_matrix(i, j) += (component[i] == 0 ? -bi : bi) * dx;
        }
    }
    for (auto& b : cell_rhs) b = 0;
    bool has_rhs = false;
    for (const auto f : cell->face_indices()) {
      const auto face = cell->face(f);
      if (!face->at_boundary() || face->boundary_id() == 0 ||
          face->boundary_id() > prm.bodies.size())
        continue;
      const std::size_t body = face->boundary_id() - 1;
      fe_face_values.reinit(cell, f);
      for (std::size_t m = 0; m < prm.motions.size(); ++m) {
        if (prm.motions[m].body != body) continue;
        has_rhs = true;
        for (unsigned int q = 0; q < face_quadrature.size(); ++q) {
          const Point<dim>& x = fe_face_values.quadrature_point(q);
          // F = ωρ₀ ∫ u Θ φ w ds, in the imaginary part's rows, u = 1 m/s.
          const double g = omega * prm.air.density * pattern(prm.motions[m], x) * weight(x) *
                           fe_face_values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            if (component[i] == 1) cell_rhs[m](i) += g * fe_face_values.shape_value(i, q);
        }
      }
    }
    cell->get_dof_indices(dofs);
    constraints.distribute_local_to_global(cell_matrix, dofs, system_matrix);
    if (has_rhs)
      for (std::size_t m = 0; m < prm.motions.size(); ++m)
        constraints.distribute_local_to_global(cell_rhs[m], dofs, system_rhs[m]);
  }
}

void HelmholtzRadiation::solve() {
  SparseDirectUMFPACK direct;
  direct.initialize(system_matrix);
  for (std::size_t m = 0; m < prm.motions.size(); ++m) {
    direct.vmult(solutions[m], system_rhs[m]);
    constraints.distribute(solutions[m]);
  }
}

std::vector<std::vector<cplx>> HelmholtzRadiation::values_at(
    const std::vector<CellPoint>& points) const {
  std::vector<std::vector<cplx>> p(prm.motions.size(), std::vector<cplx>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& [cell, unit_point] = points[i];
    FEValues<dim> values(mapping, fe, Quadrature<dim>(std::vector<Point<dim>>{unit_point}),
                         update_values);
    values.reinit(cell);
    std::vector<Vector<double>> v(1, Vector<double>(2));
    for (std::size_t m = 0; m < prm.motions.size(); ++m) {
      values.get_function_values(solutions[m], v);
      p[m][i] = cplx(v[0](0), v[0](1));
    }
  }
  return p;
}

std::vector<std::vector<cplx>> HelmholtzRadiation::microphone_pressures(double k) const {
  std::vector<std::vector<cplx>> p(prm.motions.size(), std::vector<cplx>(prm.microphones.size()));
  const std::vector<std::vector<cplx>> direct = values_at(microphone_cells);
  for (std::size_t i = 0, d = 0; i < prm.microphones.size(); ++i)
    if (!continued[i]) {
      for (std::size_t m = 0; m < prm.motions.size(); ++m) p[m][i] = direct[m][d];
      ++d;
    }
  if (circle_cells.empty()) return p;
  const bool spherical = prm.geometry == RadiationGeometry::axisymmetric;
  const std::vector<cplx> h_c = outgoing_hankel(spherical, n_modes, k * r_c);
  const std::vector<std::vector<cplx>> on_circle = values_at(circle_cells);
  for (std::size_t i = 0; i < prm.microphones.size(); ++i) {
    if (!continued[i]) continue;
    const double x = prm.microphones[i][0], y = prm.microphones[i][1], r = std::hypot(x, y);
    const std::vector<cplx> h_r = outgoing_hankel(spherical, n_modes, k * r);
    const std::size_t n_max = std::min(h_c.size(), h_r.size()) - 1;
    for (std::size_t m = 0; m < prm.motions.size(); ++m) {
      const std::vector<cplx>& q = on_circle[m];
      cplx sum = 0;
      if (!spherical) {
        // c_n = (1/M) Σ_j p_j e^{−inθ_j}; n and −n share |H_n| (H_{−n} = (−1)ⁿ H_n).
        const double theta = std::atan2(y, x);
        for (std::size_t n = 0; n <= n_max; ++n) {
          cplx c_plus = 0, c_minus = 0;
          for (std::size_t j = 0; j < q.size(); ++j) {
            c_plus += q[j] * std::exp(cplx(0, -double(n) * circle_angle[j]));
            c_minus += q[j] * std::exp(cplx(0, double(n) * circle_angle[j]));
          }
          c_plus /= double(q.size()), c_minus /= double(q.size());
          const cplx ratio = h_r[n] / h_c[n];
          sum += ratio * c_plus * std::exp(cplx(0, double(n) * theta));
          if (n > 0) sum += ratio * c_minus * std::exp(cplx(0, -double(n) * theta));
        }
      } else {
        // a_n = (2n+1)/2 Σ_j w_j p_j P_n(μ_j).
        const std::vector<double> p_mic = legendre(n_max, y / r);
        std::vector<cplx> a(n_max + 1, 0.0);
        for (std::size_t j = 0; j < q.size(); ++j) {
          const std::vector<double> p_j = legendre(n_max, circle_angle[j]);
          for (std::size_t n = 0; n <= n_max; ++n) a[n] += circle_weight[j] * q[j] * p_j[n];
        }
        for (std::size_t n = 0; n <= n_max; ++n)
          sum += (n + 0.5) * a[n] * h_r[n] / h_c[n] * p_mic[n];
      }
      p[m][i] = sum;
    }
  }
  return p;
}

// One VTU per frequency: the field of every motion together (each body with 1 m/s), real and
// imaginary parts, on curved cells subdivided to the element degree.
std::string HelmholtzRadiation::output_results(std::size_t frequency_index) const {
  Vector<double> all(dof_handler.n_dofs());
  for (const auto& s : solutions) all += s;
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  data_out.add_data_vector(all, std::vector<std::string>{"p_re", "p_im"});
  Vector<float> layer(triangulation.n_active_cells());
  for (const auto& cell : triangulation.active_cell_iterators())
    layer(cell->active_cell_index()) = cell->center().norm() > r0 ? 1.f : 0.f;
  data_out.add_data_vector(layer, "pml");
  data_out.build_patches(mapping, fe.degree, DataOut<dim>::curved_inner_cells);
  std::ostringstream name;
  name << prm.vtu_dir << "/radiation_" << std::setw(3) << std::setfill('0') << frequency_index
       << ".vtu";
  std::ofstream out(name.str());
  data_out.write_vtu(out);
  if (!out) throw std::runtime_error("cannot write " + name.str());
  return name.str();
}

HelmholtzResult HelmholtzRadiation::run(MPI_Comm comm) {
  const auto start = std::chrono::steady_clock::now();
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int size = Utilities::MPI::n_mpi_processes(comm);
  // gmsh runs on rank 0 only; every process reads its file.
  if (prm.bodies.size() > 1) {
    int ok = 1;
    std::string error;
    if (rank == 0) try {
        mesh_section();
      } catch (const std::exception& e) {
        ok = 0, error = e.what();
      }
    MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
    if (!ok) throw std::runtime_error(rank == 0 ? error : "gmsh failed (see process 0)");
  }
  make_grid();
  setup_system();

  HelmholtzResult r;
  r.frequencies = prm.frequencies;
  r.n_dofs = dof_handler.n_dofs();
  r.n_cells = triangulation.n_active_cells();
  r.physical_radius = r0, r.pml_thickness = thickness, r.pml_layers = layers;
  r.mpi_processes = size;
  for (const auto& cell : triangulation.active_cell_iterators())
    if (cell->center().norm() < r0) r.largest_cell = std::max(r.largest_cell, cell->diameter());

  const std::size_t nf = prm.frequencies.size(), nm = prm.motions.size(),
                    nx = prm.microphones.size();
  std::vector<double> flat(2 * nf * nm * nx, 0.0);
  for (std::size_t f = rank; f < nf; f += size) {
    const auto t0 = std::chrono::steady_clock::now();
    assemble_system(prm.frequencies[f]);
    const auto t1 = std::chrono::steady_clock::now();
    solve();
    const auto t2 = std::chrono::steady_clock::now();
    const auto p = microphone_pressures(two_pi * prm.frequencies[f] / prm.air.sound_speed);
    for (std::size_t m = 0; m < nm; ++m)
      for (std::size_t i = 0; i < nx; ++i) {
        flat[2 * ((f * nm + m) * nx + i)] = p[m][i].real();
        flat[2 * ((f * nm + m) * nx + i) + 1] = p[m][i].imag();
      }
    if (!prm.vtu_dir.empty()) r.vtu_files.push_back(output_results(f));
    if (prm.verbose)
      std::cout << "  f = " << prm.frequencies[f] << " Hz: assembled in "
                << std::chrono::duration<double>(t1 - t0).count() << " s, solved in "
                << std::chrono::duration<double>(t2 - t1).count() << " s (" << r.n_dofs
                << " unknowns, process " << rank << ")\n";
  }
  // Every value comes from exactly one process and zeros from the others: the sum is exact.
  Utilities::MPI::sum(flat, comm, flat);
  r.pressure.assign(nf, std::vector<std::vector<cplx>>(nm, std::vector<cplx>(nx)));
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t m = 0; m < nm; ++m)
      for (std::size_t i = 0; i < nx; ++i)
        r.pressure[f][m][i] =
            cplx(flat[2 * ((f * nm + m) * nx + i)], flat[2 * ((f * nm + m) * nx + i) + 1]);
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.wall_time = Utilities::MPI::max(r.wall_time, comm);
  return r;
}

}  // namespace

HelmholtzResult solve_helmholtz(const HelmholtzParameters& p, MPI_Comm comm) {
  HelmholtzRadiation problem(p);
  return problem.run(comm);
}

}  // namespace bearing::fem
