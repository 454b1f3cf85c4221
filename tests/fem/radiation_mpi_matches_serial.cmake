# Runs `bearing-fem radiate --source bearing` (the 608's section, two frequencies) serially and
# under `mpirun -np 2`, and requires the same radiation.csv to 1e-8 relative (each frequency is
# solved whole by one process, so it is the same computation).
# -DBEARING_FEM=<exe> -DMPIEXEC=<mpiexec> -DCASE=<toml> -DOUT=<dir>
include(${CMAKE_CURRENT_LIST_DIR}/serial_and_mpi.cmake)
run_serial_and_mpi2(radiation.json radiate --source bearing ${CASE} --frequencies 500,8000
                    --no-vtu --quiet)
execute_process(
  COMMAND /usr/bin/python3 -c "
import csv, sys
a = list(csv.reader(open(sys.argv[1]))); b = list(csv.reader(open(sys.argv[2])))
assert a[0] == b[0] and len(a) == len(b) and len(a) > 1, 'different shapes'
worst = 0.0
for ra, rb in zip(a[1:], b[1:]):
    pa = complex(float(ra[1]), float(ra[2])); pb = complex(float(rb[1]), float(rb[2]))
    worst = max(worst, abs(pa - pb) / max(abs(pa), abs(pb)))
print('%d rows, largest relative difference %.2e' % (len(a) - 1, worst))
sys.exit(0 if worst < 1e-8 else 1)"
    ${OUT}/serial/radiation.csv ${OUT}/mpi2/radiation.csv
  RESULT_VARIABLE cmp)
if(NOT cmp EQUAL 0)
  message(FATAL_ERROR "serial and mpirun -np 2 differ by more than 1e-8")
endif()
