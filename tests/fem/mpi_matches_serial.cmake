# Runs the coarse Hertz contact serially and under `mpirun -np 2`, and requires the same K and
# exponent to 1e-8 (the CG tolerance is 1e-11; the contact sets are decided by the node owners).
# -DBEARING_FEM=<exe> -DMPIEXEC=<mpiexec> -DCASE=<toml> -DOUT=<dir>
include(${CMAKE_CURRENT_LIST_DIR}/serial_and_mpi.cmake)
run_serial_and_mpi2(contact.json contact ${CASE} --race outer --cells 4 --grading 3 --steps 3
                    --no-vtu --quiet)
foreach(run serial mpi2)
  string(JSON k_${run} GET "${json_${run}}" fe K)
  string(JSON n_${run} GET "${json_${run}}" fe exponent)
endforeach()
# CMake has no floating point: compare with a tiny awk-free trick through math on scaled digits
# is not possible, so let Python (Debian's /usr/bin/python3, which setup.sh installs) compare.
execute_process(
  COMMAND /usr/bin/python3 -c
    "import sys; a,b,c,d=map(float,sys.argv[1:]); e=max(abs(b/a-1),abs(d-c)); print('K serial %r mpi %r, exponent %r %r, difference %.2e'%(a,b,c,d,e)); sys.exit(0 if e<1e-8 else 1)"
    ${k_serial} ${k_mpi2} ${n_serial} ${n_mpi2}
  RESULT_VARIABLE cmp)
if(NOT cmp EQUAL 0)
  message(FATAL_ERROR "serial and mpirun -np 2 differ by more than 1e-8")
endif()
