# The FE solvers' parts in plain C++ (toml++ and the lumped core's units, no deal.II): the readers
# of their input files, gmsh meshes (fem/mesh/) and the structure file of `bearing-fem modes`
# (fem/modes/structure_file.*), and the seat's rigid fit (fem/modes/seat_fit.*). Included from the
# top level whether BEARING_WITH_FEM is ON or OFF: the readers read users' files, so the sanitizer
# and fuzz builds (which configure without deal.II) build, test and fuzz them
# (tests/fuzz/fuzz_gmsh_mesh.cc, fuzz_structure_file.cc).
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

# The seat's rigid fit of a mode shape (fem/modes/seat_fit.*): plain C++ arithmetic the elastic
# solver feeds with its quadrature; apart so that the fast set tests it without deal.II.
add_library(bearing_fem_seat_fit STATIC ${CMAKE_CURRENT_LIST_DIR}/modes/seat_fit.cc)
target_link_libraries(bearing_fem_seat_fit PUBLIC bearing_core)
target_include_directories(bearing_fem_seat_fit PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_compile_options(bearing_fem_seat_fit PRIVATE -Wall -Wextra -Wpedantic)
