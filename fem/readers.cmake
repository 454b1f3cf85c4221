# The readers of the FE solvers' input files: gmsh meshes (fem/mesh/) and the structure file of
# `bearing-fem modes` (fem/modes/structure_file.*). Plain C++ (toml++ and the lumped core's units,
# no deal.II), included from the top level whether BEARING_WITH_FEM is ON or OFF: they read
# users' files, so the sanitizer and fuzz builds (which configure without deal.II) build, test
# and fuzz them (tests/fuzz/fuzz_gmsh_mesh.cc, fuzz_structure_file.cc).
add_library(bearing_fem_mesh STATIC
  ${CMAKE_CURRENT_LIST_DIR}/mesh/gmsh_mesh.cc
  ${CMAKE_CURRENT_LIST_DIR}/mesh/gmsh_cells.cc)
target_include_directories(bearing_fem_mesh PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(bearing_fem_mesh PUBLIC bearing_core)
target_compile_options(bearing_fem_mesh PRIVATE -Wall -Wextra -Wpedantic)

add_library(bearing_fem_structure STATIC ${CMAKE_CURRENT_LIST_DIR}/modes/structure_file.cc)
target_link_libraries(bearing_fem_structure PUBLIC bearing_fem_mesh bearing_core
                      PRIVATE bearing_case tomlplusplus_header)
target_compile_options(bearing_fem_structure PRIVATE -Wall -Wextra -Wpedantic)
