# Runs one fuzz target for SECONDS on a fresh scratch copy of its seed corpus (libFuzzer writes new
# inputs into the first corpus directory only), with the regressions as a read-only second corpus.
# Usage: cmake -DFUZZER=... -DSEEDS=dir -DREGRESSIONS=dir -DSCRATCH=dir -DSECONDS=n -P run_fuzzer.cmake
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/corpus ${SCRATCH}/artifacts)
file(COPY ${SEEDS}/ DESTINATION ${SCRATCH}/corpus)
set(corpora ${SCRATCH}/corpus)
if(IS_DIRECTORY ${REGRESSIONS})
  list(APPEND corpora ${REGRESSIONS})
endif()
execute_process(
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -rss_limit_mb=2048 -timeout=10 -print_final_stats=1
          -artifact_prefix=${SCRATCH}/artifacts/ ${corpora}
  WORKING_DIRECTORY ${SCRATCH}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a problem (exit ${result}); the input is in ${SCRATCH}/artifacts/")
endif()
