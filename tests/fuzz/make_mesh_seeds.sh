#!/usr/bin/env bash
# Writes the gmsh seeds of fuzz_gmsh_mesh (corpus/gmsh_mesh/), which the reader's unit tests
# (tests/fem/test_gmsh_mesh.cc) also read: small meshes gmsh itself writes, in MSH 2.2 and 4.1.
#   tests/fuzz/make_mesh_seeds.sh tests/fuzz/corpus/gmsh_mesh      (gmsh 4.8 on PATH)
set -euo pipefail
out=${1:?the corpus folder}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/tbox.geo" <<'GEO'
// A 20 x 10 x 6 box in tetrahedra, coarse: two physical surfaces and the volume.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 20, 10, 6};
Physical Volume("body") = {1};
Physical Surface("fixed") = {1};
Physical Surface("seat") = {2};
Mesh.MeshSizeMin = 8; Mesh.MeshSizeMax = 8;
GEO
cat >"$work/hbox.geo" <<'GEO'
// A 2 x 1 x 1 box of hexahedra (transfinite, recombined): two physical surfaces, the volume.
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3; Transfinite Curve{2, 4} = 2;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
Physical Volume("body") = {out[1]};
Physical Surface("fixed") = {1};
Physical Surface("seat") = {out[0]};
GEO
cat >"$work/overlap.geo" <<'GEO'
// Tetrahedra of a box whose faces lie in overlapping physical surfaces: "outside" holds all six,
// "bolts" one of them.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 4, 4};
Physical Volume("body") = {1};
Physical Surface("outside") = {1, 2, 3, 4, 5, 6};
Physical Surface("bolts") = {1};
Mesh.MeshSizeMin = 4; Mesh.MeshSizeMax = 4;
GEO
cat >"$work/cyl.geo" <<'GEO'
// A short cylinder in tetrahedra, nodes written with their parametric coordinates.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 3, 5};
Physical Volume("body") = {1};
Physical Surface("mantle") = {1};
Mesh.MeshSizeMin = 4; Mesh.MeshSizeMax = 4;
Mesh.SaveParametric = 1;
GEO
cat >"$work/nophys.geo" <<'GEO'
// A box in tetrahedra without physical groups: gmsh saves every element.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 2, 1};
Mesh.MeshSizeMin = 3; Mesh.MeshSizeMax = 3;
GEO
mesh() { gmsh -3 "$work/$1.geo" -format "$2" -o "$out/$3" "${@:4}" >/dev/null; }
mkdir -p "$out"
mesh tbox msh22 box_tetrahedra_22.msh
mesh tbox msh41 box_tetrahedra_41.msh
mesh hbox msh22 box_hexahedra_22.msh
mesh hbox msh41 box_hexahedra_41.msh
mesh overlap msh22 overlapping_surfaces_22.msh
mesh overlap msh41 overlapping_surfaces_41.msh
mesh cyl msh41 cylinder_parametric_41.msh
mesh nophys msh41 no_physical_groups_41.msh
mesh hbox msh22 second_order_22.msh -order 2
