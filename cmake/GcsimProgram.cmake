# gcsim_add_program(TARGET SOURCES file.cpp ... [LIBS target ...])
#
# Builds TARGET, a gcsim command with your applications in it: the sources register them with
# the pipeline as gcsim's own do (apps/pipeline/app_registry.hpp, AppRegistrar), so
# `TARGET run NAME --nodes 16`, `TARGET sweep NAME`, --json, --trace and every machine command
# work for them. Installed beside gcsimConfig.cmake; see examples/ring in gcsim's sources.
function(gcsim_add_program target)
  cmake_parse_arguments(PROGRAM "" "" "SOURCES;LIBS" ${ARGN})
  if(NOT PROGRAM_SOURCES)
    message(FATAL_ERROR "gcsim_add_program(${target}): SOURCES is required")
  endif()
  # Objects, not a library: nothing refers to an application's registrar by name, so a library
  # would let the linker drop it.
  add_library(${target}_apps OBJECT ${PROGRAM_SOURCES})
  target_link_libraries(${target}_apps PUBLIC gcsim::pipeline ${PROGRAM_LIBS})
  add_executable(${target} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/main.cpp)
  target_link_libraries(${target} PRIVATE gcsim::cli ${target}_apps)
endfunction()
