# gcsim_add_mpi_program(TARGET SOURCES file.c ... [LIBS target ...])
#
# Builds TARGET, an ordinary MPI program (C or C++) for `gcsim mpirun -np N ./TARGET`, as
# gcsim-mpicc builds one: a position-independent shared object with gcsim's <mpi.h>, whose MPI
# calls resolve against the gcsim executable, and which run directly says to use gcsim mpirun.
# Installed beside gcsimConfig.cmake; see examples/mpi/CMakeLists.txt in gcsim's sources.
function(gcsim_add_mpi_program target)
  cmake_parse_arguments(PROGRAM "" "" "SOURCES;LIBS" ${ARGN})
  if(NOT PROGRAM_SOURCES)
    message(FATAL_ERROR "gcsim_add_mpi_program(${target}): SOURCES is required")
  endif()
  add_library(${target} MODULE ${PROGRAM_SOURCES} ${GCSIM_MPI_DIRECT_ENTRY})
  if(NOT CMAKE_C_COMPILER_LOADED)  # a C++-only project compiles the entry as C++ (it is both)
    set_source_files_properties(${GCSIM_MPI_DIRECT_ENTRY} PROPERTIES LANGUAGE CXX)
  endif()
  set_target_properties(${target} PROPERTIES PREFIX "" SUFFIX "" POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PRIVATE ${GCSIM_MPI_INCLUDE_DIR})
  target_compile_options(${target} PRIVATE -fexceptions)
  target_link_options(${target} PRIVATE "LINKER:-e,gcsim_mpi_direct_entry" "LINKER:-z,lazy")
  target_link_libraries(${target} PRIVATE ${PROGRAM_LIBS})
endfunction()
