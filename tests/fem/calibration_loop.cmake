# The calibration loop end to end: `bearing-fem calibrate` on the 6308 case (coarse mesh), then
# the lumped `bearing-sim info` reads the file back with contact = "calibrated" — its constants
# must be the file's and lie within this resolution's error of exact Hertz (+1 to +3.5 %, the
# coarse level of tests/fem/test_hertz_contact.cc) — and rejects it for another bearing (6304).
# -DBEARING_FEM=<exe> -DBEARING_SIM=<exe> -DCASE=<6308 toml> -DOTHER=<6304 toml> -DOUT=<dir>
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(
  COMMAND ${BEARING_FEM} calibrate ${CASE} --out ${OUT}/calibration.json --cells 4 --grading 3
          --steps 3 --quiet
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bearing-fem calibrate failed (${rc})")
endif()
file(READ ${OUT}/calibration.json cal)
foreach(key format date geometry method mesh)
  string(JSON v ERROR_VARIABLE err GET "${cal}" ${key})
  if(err)
    message(FATAL_ERROR "calibration.json has no ${key}")
  endif()
endforeach()
string(JSON k_inner GET "${cal}" inner K)
string(JSON n_inner GET "${cal}" inner exponent)
string(JSON k_outer GET "${cal}" outer K)
string(JSON n_outer GET "${cal}" outer exponent)
string(JSON h_inner GET "${cal}" inner hertz_K)

# The lumped side: the same case with the calibrated law.
execute_process(
  COMMAND ${BEARING_SIM} info ${CASE} --set model.contact=calibrated
          --set model.calibration=${OUT}/calibration.json --json
  RESULT_VARIABLE rc OUTPUT_VARIABLE info ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bearing-sim info rejected its own bearing's calibration (${rc}): ${err}")
endif()
string(JSON method GET "${info}" contact method)
string(JSON li GET "${info}" contact inner K)
string(JSON ni GET "${info}" contact inner exponent)
string(JSON lo GET "${info}" contact outer K)
if(NOT method STREQUAL "calibrated")
  message(FATAL_ERROR "info shows contact.method = ${method}")
endif()
execute_process(
  COMMAND /usr/bin/python3 -c
    "import sys; ki,ni,ko,hi,li,lni,lo=map(float,sys.argv[1:]); \
ok = abs(li/ki-1) < 1e-12 and abs(lni-ni) < 1e-12 and abs(lo/ko-1) < 1e-12; \
print('K_i %.6g N/m^%.4f (Hertz %.6g), K_o %.6g; lumped reads %.6g, %.6g' % (ki, ni, hi, ko, li, lo)); \
sys.exit(0 if ok and 1.5 - 0.02 < ni < 1.5 + 0.02 else 1)"
    ${k_inner} ${n_inner} ${k_outer} ${h_inner} ${li} ${ni} ${lo}
  RESULT_VARIABLE cmp)
if(NOT cmp EQUAL 0)
  message(FATAL_ERROR "the lumped constants differ from the file's, or the exponent is off")
endif()

# Another bearing: rejected with exit status 2 and a message naming the field.
execute_process(
  COMMAND ${BEARING_SIM} info ${OTHER} --set model.contact=calibrated
          --set model.calibration=${OUT}/calibration.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "bearing\\.ball_diameter")
  message(FATAL_ERROR "a 6308 calibration was not rejected for the 6304 (${rc}): ${err}")
endif()
message(STATUS "rejected for the 6304: ${err}")
