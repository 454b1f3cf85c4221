// Motor end shield for a 6205 bearing (issue 40): the example housing of `bearing-fem modes`
// (meshes/end_shield_6205.toml) and of the lumped model's housing modes (examples/cwru/).
//
// Assumed dimensions [mm] (an end shield of a small motor, not a drawing of a real one): a web
// (disc) 200 mm across and 10 mm thick; a hub around the bearing seat, bore 52 mm (the 6205's
// outside diameter), 80 mm across and 22 mm wide; a rim 20 mm deep at the web's edge, 12 mm
// thick (radially), that sits on the motor frame; four bolt pads (16 mm across, 3 mm proud of the
// rim's face) at 45, 135, 225 and 315 degrees on a 188 mm circle. Material (in the .toml): grey
// cast iron EN-GJL-250, E = 110 GPa, nu = 0.26, rho = 7200 kg/m^3.
//
// Frame: z is the shaft axis (the web's inner face at z = 0, the motor's inside at z < 0), y up,
// x horizontal; the seat's axial centre at z = 5.
//
// Physical surfaces: "seat" (the bore, 22 mm long, where the bearing's outer ring sits), "bolts"
// (the pads' end faces, held by the bolts: fixed in the .toml). Mesh: tetrahedra of ~6 mm (about
// two through the web's thickness), 4 mm within 45 mm of the axis (the hub and the seat); with
// degree-2 elements 93 000 unknowns. `bearing-fem modes` runs gmsh on this file itself (the
// structure file names it) and keeps the mesh beside its results (DIR/mesh.msh).
SetFactory("OpenCASCADE");
web_r = 100; web_t = 10;
hub_r = 40; bore_r = 26; hub_z0 = -6; hub_z1 = 16;
rim_ri = 88; rim_depth = 20;
pad_r = 8; pad_rc = 94; pad_h = 3;

Cylinder(1) = {0, 0, 0, 0, 0, web_t, web_r};                           // web
Cylinder(2) = {0, 0, hub_z0, 0, 0, hub_z1 - hub_z0, hub_r};            // hub
Cylinder(3) = {0, 0, -rim_depth, 0, 0, rim_depth, web_r};              // rim (outer)
Cylinder(4) = {0, 0, -rim_depth, 0, 0, rim_depth, rim_ri};             // rim (hole)
rim() = BooleanDifference{ Volume{3}; Delete; }{ Volume{4}; Delete; };
For k In {0:3}
  a = Pi / 4 + k * Pi / 2;
  Cylinder(10 + k) = {pad_rc * Cos(a), pad_rc * Sin(a), -rim_depth - pad_h, 0, 0, pad_h, pad_r};
EndFor
Cylinder(20) = {0, 0, hub_z0 - 1, 0, 0, hub_z1 - hub_z0 + 2, bore_r};  // the bore
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2, rim(), 10, 11, 12, 13}; Delete; };
shield() = BooleanDifference{ Volume{body()}; Delete; }{ Volume{20}; Delete; };

Physical Volume("shield") = {shield()};
Physical Surface("seat") = {Surface In BoundingBox{-bore_r - 0.1, -bore_r - 0.1, hub_z0 - 0.1,
                                                   bore_r + 0.1, bore_r + 0.1, hub_z1 + 0.1}};
pads() = Surface In BoundingBox{-web_r, -web_r, -rim_depth - pad_h - 0.1,
                                web_r, web_r, -rim_depth - pad_h + 0.1};
Physical Surface("bolts") = {pads()};

Mesh.MeshSizeMax = 6;
Mesh.MeshSizeMin = 3;
Field[1] = Ball;
Field[1].Radius = 45; Field[1].Thickness = 10;
Field[1].VIn = 4; Field[1].VOut = 6;
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
