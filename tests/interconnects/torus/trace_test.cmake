# cmake -DGCSIM=... -DMACHINE=torus-4x4.toml -DWORK=dir -P trace_test.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${GCSIM} run ping --config ${MACHINE} --nodes 16 --trace ${WORK}/t.json --trace-level full
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the traced run failed (${status}):\n${out}\n${err}")
endif()
file(READ ${WORK}/t.csv csv LIMIT 200)
string(FIND "${csv}" "# gcsim trace; level full; 16 processors; mesh 4x4; interconnect torus; times in picoseconds\n" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "t.csv does not name the torus:\n${csv}")
endif()
file(READ ${WORK}/t.paje paje)
# Node 0 reaches node 3 west, over the wrap-around link (channel 0 * 4 + 1).
if(NOT paje MATCHES "GC-PowerPlus 16 processors, torus 4x4" OR NOT paje MATCHES "\"channel 1 P0->P3 west\"")
  message(FATAL_ERROR "t.paje does not show the torus and its wrap-around channel")
endif()
