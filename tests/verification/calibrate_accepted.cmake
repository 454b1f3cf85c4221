# bearing-verify calibrate writes calibration.json that bearing-sim accepts, and the report.
#   -DVERIFY=... -DSIM=... -DCASE=... -DOUT=...
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${VERIFY} calibrate ${CASE} --out ${OUT} --cells 4 --grading 3 --quiet
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "calibrate failed (${status}):\n${out}\n${err}")
endif()
foreach(f calibration.json calibration_report.html calibration_report.md calibration_report.json
          figures/calibration-inner.png figures/calibration-outer.png figures/calibration-spectra.png)
  if(NOT EXISTS "${OUT}/${f}")
    message(FATAL_ERROR "calibrate wrote no ${f}")
  endif()
endforeach()
execute_process(COMMAND ${SIM} info ${CASE} --json --set model.contact=\"calibrated\"
                        --set model.calibration=\"${OUT}/calibration.json\"
                RESULT_VARIABLE status OUTPUT_VARIABLE info ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "bearing-sim rejected the calibration (${status}):\n${err}")
endif()
string(JSON law GET "${info}" contact method)
if(NOT law STREQUAL "calibrated")
  message(FATAL_ERROR "bearing-sim info says contact ${law}, not calibrated")
endif()
file(READ "${OUT}/calibration_report.md" md)
foreach(law exact hamrock-brewe harris-table calibrated)
  string(FIND "${md}" "| ${law} |" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "calibration_report.md has no response row for ${law}")
  endif()
endforeach()
