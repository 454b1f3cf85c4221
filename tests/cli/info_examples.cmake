# Runs `bearing-sim info <example> --json` for every case in examples/ and checks that the output
# is valid JSON with every key docs/bearing-sim.md documents, each a finite number (or array of
# numbers).
# Invoked by ctest: cmake -DBEARING_SIM=... -DEXAMPLES=... -P info_examples.cmake

file(GLOB cases "${EXAMPLES}/*.toml")
list(LENGTH cases n)
if(n LESS 5)
  message(FATAL_ERROR "expected at least 5 example cases in ${EXAMPLES}, found ${n}")
endif()
list(APPEND cases "")   # the built-in default case (no CASE argument)

set(number_keys
  "kinematics shaft" "kinematics ftf" "kinematics bpfo" "kinematics bpfi" "kinematics bsf"
  "contact inner sum_rho" "contact inner f_rho" "contact inner ellipticity"
  "contact inner delta_star" "contact inner K"
  "contact outer sum_rho" "contact outer f_rho" "contact outer ellipticity"
  "contact outer delta_star" "contact outer K"
  "contact inner exponent" "contact outer exponent"
  "contact K" "contact exponent" "static q_max" "stiffness q_max" "stiffness ball_pass bpfo")
set(array_keys "static deflection" "static ball_loads" "stiffness displacement"
  "stiffness matrix 0" "stiffness matrix 1" "stiffness matrix 2" "stiffness matrix 3"
  "stiffness matrix 4" "stiffness ball_pass cage_angles" "stiffness ball_pass min 1"
  "stiffness ball_pass max 1" "stiffness ball_pass harmonics 0 amplitude 1")

foreach(case IN LISTS cases)
  execute_process(COMMAND "${BEARING_SIM}" info ${case} --json
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "bearing-sim info ${case} --json failed (${rc}): ${err}")
  endif()
  foreach(k IN LISTS number_keys)
    string(REPLACE " " ";" path "${k}")
    string(JSON type ERROR_VARIABLE jerr TYPE "${out}" ${path})
    if(jerr OR NOT type STREQUAL "NUMBER")
      message(FATAL_ERROR "${case}: key '${k}' missing or not a number (${type} ${jerr})\n${out}")
    endif()
  endforeach()
  foreach(k IN LISTS array_keys)
    string(REPLACE " " ";" path "${k}")
    string(JSON len ERROR_VARIABLE jerr LENGTH "${out}" ${path})
    if(jerr OR len EQUAL 0)
      message(FATAL_ERROR "${case}: key '${k}' missing or empty (${jerr})\n${out}")
    endif()
    math(EXPR last "${len} - 1")
    foreach(i RANGE ${last})
      string(JSON type TYPE "${out}" ${path} ${i})
      if(NOT type STREQUAL "NUMBER")
        message(FATAL_ERROR "${case}: ${k}[${i}] is ${type}, not a number\n${out}")
      endif()
    endforeach()
  endforeach()
  string(JSON method GET "${out}" contact method)
  if(method STREQUAL "calibrated")
    # The calibrated law names its file and the ball law's fit residual.
    string(JSON file ERROR_VARIABLE jerr GET "${out}" contact calibration file)
    string(JSON type ERROR_VARIABLE jerr2 TYPE "${out}" contact calibration series_fit_residual)
    if(jerr OR jerr2 OR file STREQUAL "" OR NOT type STREQUAL "NUMBER")
      message(FATAL_ERROR "${case}: contact.calibration.{file,series_fit_residual} missing\n${out}")
    endif()
  endif()
  message(STATUS "ok: ${case} (contact method ${method})")
endforeach()
