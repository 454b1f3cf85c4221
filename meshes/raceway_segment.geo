// Raceway segment with its true groove: the coarse hexahedral mesh of the FE contact reference
// `bearing-fem contact CASE --geometry groove` (issue 4, fem/README.md). The FE solver refines it
// toward the contact on the exact geometry (a cylindrical manifold about the bearing axis, and
// the groove torus for the raceway faces), so this mesh only has to put its vertices on the true
// surfaces; it is deliberately coarse.
//
// Frame (SI, metres): the ball touches the groove bottom at the origin; z points from the ring
// into the ball (radially outward for the inner ring, inward for the outer ring); y is axial (the
// groove's mid-plane is y = 0); x is the rolling direction. By symmetry only the quarter x >= 0,
// y >= 0 is meshed. The bearing axis is the line x = 0, z = axis_z (−R_b inner, +R_b outer).
//
// Cross-section (the x = 0 plane, coordinates y, z), the same for both races in this frame:
//   groove  circle of radius r_g = f D about (y, z) = (0, r_g), from the bottom (0, 0) up to the
//           land at depth h: (y_s, h), y_s = r_g sin psi_s, cos psi_s = 1 − h / r_g;
//   land    z = h from y_s to the ring's half-width W;
//   back    z = z_back (the bore, inner ring; the outside diameter, outer ring), clamped by the
//           solver;
// rotated about the bearing axis by the segment angle (half the ball pitch by default).
//
// Parameters (all given by bearing-fem with -setnumber; the defaults are the 6308 inner ring):
DefineConstant[
  race = 0,                    // 0 inner ring, 1 outer ring
  groove_radius = 0.52 * 15.081e-3,   // r_g = f D [m]
  groove_bottom = 49.912e-3 / 2,      // R_b: d_i/2 (inner) or d_o/2 (outer) [m]
  groove_depth = 0.2 * 15.081e-3,     // h, groove bottom to land [m]
  back_radius = 40e-3 / 2,            // bore radius (inner) or outside radius (outer) [m]
  half_width = 23e-3 / 2,             // W = B/2 [m]
  segment_angle = Pi / 8,             // Phi [rad]
  cells_groove = 2, cells_land = 1, cells_depth = 2, cells_angle = 4
];

r = groove_radius;
h = groove_depth;
cos_s = 1 - h / r;
If (cos_s < -0.999)
  cos_s = -0.999;
EndIf
y_s = r * Sqrt(1 - cos_s * cos_s);
If (y_s > 0.95 * half_width)  // a groove as wide as the ring: it ends at the ring's side
  y_s = 0.95 * half_width;
  h = r - Sqrt(r * r - y_s * y_s);
EndIf
If (race == 0)
  axis_z = -groove_bottom;
  z_back = back_radius - groove_bottom;
  angle = segment_angle;
Else
  axis_z = groove_bottom;
  z_back = groove_bottom - back_radius;
  angle = -segment_angle;  // rotating the other way keeps the segment at x >= 0
EndIf

Point(1) = {0, 0, z_back};
Point(2) = {0, y_s, z_back};
Point(3) = {0, half_width, z_back};
Point(4) = {0, half_width, h};
Point(5) = {0, y_s, h};
Point(6) = {0, 0, 0};
Point(7) = {0, 0, r};  // groove centre

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Circle(5) = {5, 7, 6};  // the groove
Line(6) = {6, 1};
Line(7) = {2, 5};

Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};  // under the groove
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};  // under the land

Transfinite Curve{1, 5} = cells_groove + 1;
Transfinite Curve{2, 4} = cells_land + 1;
Transfinite Curve{3, 6, 7} = cells_depth + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Extrude {{0, 1, 0}, {0, 0, axis_z}, angle} {
  Surface{1, 2}; Layers{cells_angle}; Recombine;
}
Physical Volume("ring", 1) = {1, 2};
Mesh.MshFileVersion = 2.2;
