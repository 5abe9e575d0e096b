# gcsim mpirun --ranks-per-node K: included by this folder's CMakeLists.txt.
#  - the rank-to-node mapping, the node-local message formula and the shared CPU (a test suite);
#  - K ranks per node print what one rank per node prints (Jacobi's residuals, the Mandelbrot
#    farm's checksum over MPI_ANY_SOURCE, the ring's sums);
#  - one rank per node is byte-identical to the runs before ranks could share a node: the trace
#    (every record's times in picoseconds) and the simulated time of recorded runs (one_per_node/).
gcsim_add_test_suite(mpi_ranks_per_node_tests ranks_per_node_test.cpp)
target_link_libraries(mpi_ranks_per_node_tests PRIVATE gcsim_app_mpi)

function(gcsim_mpi_packed_same_output name np match)
  cmake_parse_arguments(T "" "" "KS;ARGS" ${ARGN})
  set(files "")
  foreach(k 1 ${T_KS})
    set(test mpi_run_packed_${name}_${np}_k${k})
    gcsim_mpi_run_test(${test} ${examples}/${name}.c ${np} OPTIONS --ranks-per-node@@${k} ARGS ${T_ARGS})
    set_tests_properties(${test} PROPERTIES FIXTURES_SETUP packed_${name}_runs)
    list(APPEND files ${CMAKE_CURRENT_BINARY_DIR}/${test}/output.txt)
  endforeach()
  string(REPLACE ";" "@@" files "${files}")
  add_test(NAME mpi_run_packed_${name}_same_output
           COMMAND ${CMAKE_COMMAND} "-DFILES=${files}" "-DMATCH=${match}" -P ${CMAKE_CURRENT_SOURCE_DIR}/same_lines.cmake)
  set_tests_properties(mpi_run_packed_${name}_same_output PROPERTIES LABELS mpi_run FIXTURES_REQUIRED packed_${name}_runs)
endfunction()
gcsim_mpi_packed_same_output(jacobi 6 "^jacobi " KS 2 3 6 ARGS 48 400)
gcsim_mpi_packed_same_output(mandelbrot 5 "^mandelbrot " KS 2 5 ARGS 256 192)
gcsim_mpi_packed_same_output(ring 16 "ring sum" KS 4 16)

# Recorded before ranks could share a node (one_per_node/NAME.csv, .txt): rerun with and without
# --ranks-per-node 1, each must give the same trace and simulated time, byte for byte.
foreach(run ring_16 jacobi_4)
  string(REGEX MATCH "^[a-z]+" program ${run})
  string(REGEX MATCH "[0-9]+$" np ${run})
  set(args "")
  if(program STREQUAL "jacobi")
    set(args "24@@50")
  endif()
  foreach(option none k1)
    set(extra "")
    if(option STREQUAL "k1")
      set(extra "--ranks-per-node@@1@@")
    endif()
    add_test(NAME mpi_run_one_per_node_identical_${run}_${option}
             COMMAND ${CMAKE_COMMAND} -DCOMPILER=${GCSIM_MPICC} -DSOURCE=${examples}/${program}.c
                     -DWORK=${CMAKE_CURRENT_BINARY_DIR}/one_per_node_${run}_${option}
                     "-DRUNNER=$<TARGET_FILE:gcsim>@@mpirun@@-np@@${np}@@${extra}--model@@analytic@@--compute@@annotated" "-DARGS=${args}"
                     -DEXPECTED=${CMAKE_CURRENT_SOURCE_DIR}/one_per_node/${run} -P ${CMAKE_CURRENT_SOURCE_DIR}/same_trace.cmake)
    set_tests_properties(mpi_run_one_per_node_identical_${run}_${option} PROPERTIES TIMEOUT 120 LABELS mpi_run)
  endforeach()
endforeach()

# Bad input: K outside 1..N is refused, naming the option, exit 2.
gcsim_mpi_run_test(mpi_run_packed_refuses_zero_per_node ${examples}/ring.c 4 OPTIONS --ranks-per-node@@0 EXIT 2
                   EXPECT "--ranks-per-node expects 1..N \\(the ranks, -np\\)")
gcsim_mpi_run_test(mpi_run_packed_refuses_more_per_node_than_ranks ${examples}/ring.c 4 OPTIONS --ranks-per-node@@5 EXIT 2
                   EXPECT "--ranks-per-node expects 1..N")
gcsim_mpi_run_test(mpi_run_packed_refuses_a_word ${examples}/ring.c 4 OPTIONS --ranks-per-node@@two EXIT 2
                   EXPECT "--ranks-per-node expects a whole number, got 'two'")
