# Runs `GCSIM ARGS --host-threads T --trace WORK/tT.json --image WORK/tT.png` for T = 1 and each
# of THREADS (default 2 and 4) and checks that the three trace files, the PNG and the printed report
# (all but its wall-time line) are the same byte for byte: host threads change only the host's wall time.
#   cmake -DGCSIM=path -DWORK=dir "-DARGS=run;APP;..." [-DTHREADS=2,3] -P host_threads_test.cmake
if(NOT DEFINED THREADS)
  set(THREADS 2,4)
endif()
string(REPLACE "," ";" THREADS "${THREADS}")
file(MAKE_DIRECTORY ${WORK})
foreach(threads 1 ${THREADS})
  execute_process(COMMAND ${GCSIM} ${ARGS} --host-threads ${threads} --trace ${WORK}/t${threads}.json
                          --image ${WORK}/t${threads}.png
                  OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--host-threads ${threads}: exit status ${rc}\n${out}")
  endif()
  string(REGEX REPLACE "\nwall [^\n]*" "" out "${out}")
  string(REPLACE "t${threads}." "tN." out_${threads} "${out}")
endforeach()
foreach(threads ${THREADS})
  foreach(ext json csv paje png)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/t1.${ext} ${WORK}/t${threads}.${ext} RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "t1.${ext} and t${threads}.${ext} differ: --host-threads changed the run")
    endif()
  endforeach()
  if(NOT out_1 STREQUAL out_${threads})
    message(FATAL_ERROR "the report differs between --host-threads 1 and ${threads}:\n${out_1}\n---\n${out_${threads}}")
  endif()
endforeach()
file(SIZE ${WORK}/t1.csv trace_bytes)
message(STATUS "the same trace (${trace_bytes} bytes of CSV), image and report with 1 and ${THREADS} host threads")
