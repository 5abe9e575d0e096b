# Compiles SOURCE with COMPILER (the build tree's gcsim-mpicc, or Open MPI's mpicc) and runs it
# with RUNNER (gcsim mpirun or Open MPI's mpirun, each with its options), then checks the exit
# status (EXPECT_EXIT) and that the output matches every regular expression of EXPECT.
#   cmake -DCOMPILER=... -DSOURCE=... -DWORK=... "-DRUNNER=gcsim@@mpirun@@-np@@4" [-DARGS=...]
#         [-DEXPECT_EXIT=0] "-DEXPECT=re1@@re2" [-DOUTPUT=file] -P run_mpi_program.cmake
foreach(list RUNNER ARGS EXPECT)  # joined by @@ on the command line
  string(REPLACE "@@" ";" ${list} "${${list}}")
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/compile_program.cmake)
execute_process(COMMAND ${RUNNER} ${program} ${ARGS} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(OUTPUT)
  file(WRITE ${OUTPUT} "${out}")
endif()
if(NOT DEFINED EXPECT_EXIT)
  set(EXPECT_EXIT 0)
endif()
if(NOT status EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_EXIT}; output:\n${all}")
endif()
foreach(re ${EXPECT})
  if(NOT all MATCHES "${re}")
    message(FATAL_ERROR "output does not match '${re}':\n${all}")
  endif()
endforeach()
message(STATUS "${all}")
