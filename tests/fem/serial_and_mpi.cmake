# Shared by the serial-vs-mpirun checks: run_serial_and_mpi2(JSON_NAME ARGS...) runs
# `${BEARING_FEM} ARGS... --out ${OUT}/<run>` once serially and once under `${MPIEXEC} -np 2`,
# fails on a non-zero exit or if the mpirun run does not report 2 processes, and returns each
# run's ${OUT}/<run>/JSON_NAME text in json_serial and json_mpi2.
function(run_serial_and_mpi2 json_name)
  foreach(run serial mpi2)
    set(cmd ${BEARING_FEM} ${ARGN} --out ${OUT}/${run})
    if(run STREQUAL "mpi2")
      set(cmd ${MPIEXEC} --allow-run-as-root --oversubscribe -np 2 ${cmd})
    endif()
    execute_process(COMMAND ${cmd} RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${run} run failed (${rc}): ${cmd}")
    endif()
    file(READ ${OUT}/${run}/${json_name} json)
    set(json_${run} "${json}" PARENT_SCOPE)
    if(run STREQUAL "mpi2")
      string(JSON processes GET "${json}" mpi_processes)
      if(NOT processes EQUAL 2)
        message(FATAL_ERROR "the mpirun run reports ${processes} processes")
      endif()
    endif()
  endforeach()
endfunction()
