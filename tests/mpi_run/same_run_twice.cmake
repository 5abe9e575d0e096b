# Compiles SOURCE with COMPILER and runs it twice with RUNNER, each run writing a trace, then checks
# that the two runs printed the same lines (all but gcsim's wall-clock and trace-file lines) and wrote byte-identical
# traces (.json and .csv): the simulated times and events of such a run may not vary.
#   cmake -DCOMPILER=... -DSOURCE=... -DWORK=... "-DRUNNER=gcsim@@mpirun@@-np@@4@@--compute@@annotated"
#         [-DARGS=a@@b] [-DEXPECT=re] -P same_run_twice.cmake
string(REPLACE "@@" ";" RUNNER "${RUNNER}")
string(REPLACE "@@" ";" ARGS "${ARGS}")
include(${CMAKE_CURRENT_LIST_DIR}/compile_program.cmake)
foreach(run 1 2)
  execute_process(COMMAND ${RUNNER} --trace ${WORK}/trace${run}.json ${program} ${ARGS}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out${run} ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} exited with ${status}:\n${out${run}}${err}")
  endif()
  string(REGEX REPLACE "\n(wall|trace) [^\n]*" "" out${run} "${out${run}}")  # host time; the file's name
endforeach()
if(NOT out1 STREQUAL out2)
  message(FATAL_ERROR "the two runs printed different lines:\n--- first\n${out1}\n--- second\n${out2}")
endif()
foreach(ext json csv)
  file(SHA256 ${WORK}/trace1.${ext} first)
  file(SHA256 ${WORK}/trace2.${ext} second)
  if(NOT first STREQUAL second)
    message(FATAL_ERROR "the two runs' traces differ: ${WORK}/trace1.${ext} and trace2.${ext}")
  endif()
endforeach()
if(DEFINED EXPECT AND NOT out1 MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match '${EXPECT}':\n${out1}")
endif()
message(STATUS "${out1}")
