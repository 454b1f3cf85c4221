// A bearing's 2-D section for the Helmholtz radiation reference (issue 6, fem/README.md):
// `bearing-fem radiate --source bearing CASE`. The fluid around the inner ring (a circle about
// the origin) and the Z balls (equal circles on the pitch circle), out to the physical zone's
// circle R0, and the perfectly matched layer from R0 to R1. All quadrilaterals (recombined, then
// subdivided once, which halves the sizes given here). The FE solver puts the bodies' circles
// back exactly (a polar manifold per body) and refines on them, so this only has to be a valid,
// well-graded mesh. Units: metres. Parameters are set by bearing-fem with -setnumber; the
// defaults are a 608 with a gap between ring and balls.
SetFactory("OpenCASCADE");
DefineConstant[
  ring_radius = 5.3e-3,        // inner ring's radiating radius [m]
  ball_radius = 1.984e-3,      // D/2 [m]
  pitch_radius = 7.5e-3,       // d_m/2 [m]
  balls = 7,                   // Z
  first_angle = -Pi / 2,       // ball 1's angle from +x [rad]
  physical_radius = 30e-3,     // R0 [m]
  outer_radius = 40e-3,        // R1 = R0 + L [m]
  h_far = 10e-3,               // largest element in the fluid [m] (before subdivision)
  h_layer = 2e-3,              // element size in the layer [m] (before subdivision)
  cells_per_turn = 25          // elements along a full circle of any body (before subdivision)
];

Disk(1) = {0, 0, 0, physical_radius};
Disk(2) = {0, 0, 0, ring_radius};
holes[] = {2};
For j In {0 : balls - 1}
  t = first_angle + 2 * Pi * j / balls;
  Disk(10 + j) = {pitch_radius * Cos(t), pitch_radius * Sin(t), 0, ball_radius};
  holes[] += {10 + j};
EndFor
fluid[] = BooleanDifference{ Surface{1}; Delete; }{ Surface{holes[]}; Delete; };
Disk(3) = {0, 0, 0, outer_radius};
Disk(4) = {0, 0, 0, physical_radius};
layer[] = BooleanDifference{ Surface{3}; Delete; }{ Surface{4}; Delete; };
Coherence;  // one shared circle R0 between the fluid and the layer: a conforming mesh

Physical Surface(1) = Surface{:};  // only the cells are written; the solver finds the boundaries

// Sizes: the bodies' curvature near them, h_far in the fluid, h_layer (the layer's cells across
// its thickness, where the near field decays exponentially) outside R0.
Field[1] = Ball;
Field[1].Radius = physical_radius;
Field[1].VIn = h_far;
Field[1].VOut = h_layer;
Background Field = 1;
Mesh.MeshSizeFromCurvature = cells_per_turn;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeMax = h_far;
Mesh.MeshSizeMin = ball_radius / 50;
Mesh.Algorithm = 6;               // frontal-Delaunay (gmsh 4.8.4 crashes on 8 here)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrilaterals
Mesh.MshFileVersion = 2.2;
