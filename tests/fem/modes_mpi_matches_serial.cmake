# Runs `bearing-fem modes` on a small structure serially and under `mpirun -np 2` and requires
# the same frequencies, the same seat translations and sensor values of each mode (mass-normalised
# shapes with a sign fixed by the support points, not the DoF numbers) to 1e-8: SLEPc's tolerance
# is 1e-10 and MUMPS factorises exactly up to rounding, whatever the partition.
# -DBEARING_FEM=<exe> -DMPIEXEC=<mpiexec> -DMESH=<the box seed .msh> -DOUT=<dir>
include(${CMAKE_CURRENT_LIST_DIR}/serial_and_mpi.cmake)
file(MAKE_DIRECTORY ${OUT})
file(WRITE ${OUT}/structure.toml "mesh = \"${MESH}\"
mesh_unit = \"mm\"
[material]
young = \"210 GPa\"
poisson = 0.3
density = \"7850 kg/m^3\"
[boundary]
fixed = [\"fixed\"]
seat = \"seat\"
[sensors]
top = [10, 10, 3]
")
run_serial_and_mpi2(modes.json modes ${OUT}/structure.toml --count 8 --refine 1 --no-vtu --quiet)
file(WRITE ${OUT}/serial.json "${json_serial}")
file(WRITE ${OUT}/mpi2.json "${json_mpi2}")
execute_process(
  COMMAND /usr/bin/python3 -c "
import json, sys
a, b = (json.load(open(sys.argv[k])) for k in (1, 2))
def rel(x, y):
    return abs(x - y) / max(abs(x), abs(y), 1e-300)
worst = max(rel(x, y) for x, y in zip(a['frequencies'], b['frequencies']))
scale = max(abs(v) for d in 'xyz' for v in a['seat'][d])
shapes = max(abs(x - y) / scale for d in 'xyz' for x, y in zip(a['seat'][d], b['seat'][d]))
shapes = max([shapes] + [abs(x - y) / scale for d in 'xyz'
                         for x, y in zip(a['sensors'][0][d], b['sensors'][0][d])])
print('frequencies', a['frequencies'])
print('largest relative difference: frequencies %.2e, seat and sensor values %.2e' % (worst, shapes))
sys.exit(0 if len(a['frequencies']) == 8 and worst < 1e-8 and shapes < 1e-8 else 1)
" ${OUT}/serial.json ${OUT}/mpi2.json
  RESULT_VARIABLE cmp)
if(NOT cmp EQUAL 0)
  message(FATAL_ERROR "serial and mpirun -np 2 differ by more than 1e-8")
endif()
