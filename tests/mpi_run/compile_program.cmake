# Compiles SOURCE with COMPILER into WORK (made if missing): sets `program`, or fails naming the
# compiler's errors. Included by the scripts that then run it (run_mpi_program, same_trace, same_run_twice).
file(MAKE_DIRECTORY ${WORK})
get_filename_component(name ${SOURCE} NAME_WE)
set(program ${WORK}/${name})
execute_process(COMMAND ${COMPILER} -O2 -o ${program} ${SOURCE} -lm RESULT_VARIABLE built ERROR_VARIABLE build_errors)
if(NOT built EQUAL 0)
  message(FATAL_ERROR "${COMPILER} failed on ${SOURCE}:\n${build_errors}")
endif()
