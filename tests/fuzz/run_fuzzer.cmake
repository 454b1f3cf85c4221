# fuzz.<target>.run: libFuzzer on a scratch corpus (SCRATCH, in the build tree: new inputs land
# there) that starts from the seeds and regressions (SEEDS, read only). A crash, leak, UB report
# or an input slower than 1 s makes libFuzzer exit non-zero, and this script with it; the input is
# saved under ARTIFACTS (README.md says how to keep it as a regression).
foreach(v FUZZER SECONDS DICT SCRATCH ARTIFACTS SEEDS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${v}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${SCRATCH} ${ARTIFACTS})
execute_process(
  # -max_len: inputs up to 8 kB keep the search fast; the larger regression files (deep nesting)
  # are replayed whole by fuzz.<target>.replay.
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -max_len=8192 -timeout=1 -rss_limit_mb=2048
          -dict=${DICT}
          -artifact_prefix=${ARTIFACTS} -print_final_stats=1 ${SCRATCH} ${SEEDS}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} exited with ${rc}: see the report above; the input is in "
                      "${ARTIFACTS}")
endif()
