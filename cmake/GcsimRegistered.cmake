# gcsim_add_registered(KIND NAME BASE SOURCES LIBS): the one mechanism behind gcsim_add_app,
# gcsim_add_backend, gcsim_add_interconnect, gcsim_add_network_model and gcsim_add_scene_format.
# The sources register themselves from a static registrar, so they become an OBJECT library
# gcsim_<kind>_<name> (a library would let the linker drop what nothing names), linked to BASE and
# LIBS, and listed in the global property GCSIM_<KIND>S, or GCSIM_<SET>_<KIND>S when
# GCSIM_<KIND>_SET is set (as the test folders tests/apps, tests/backends, tests/interconnects,
# tests/networks and tests/scene_formats do).
function(gcsim_add_registered kind name base sources libs)
  string(TOUPPER ${kind} KIND)
  if(NOT name OR NOT sources)
    message(FATAL_ERROR "gcsim_add_${kind}: NAME and SOURCES are required")
  endif()
  set(target gcsim_${kind}_${name})
  add_library(${target} OBJECT ${sources})
  target_link_libraries(${target} PUBLIC ${base} ${libs})
  if(GCSIM_${KIND}_SET)
    set_property(GLOBAL APPEND PROPERTY GCSIM_${GCSIM_${KIND}_SET}_${KIND}S ${name})
  else()
    set_property(GLOBAL APPEND PROPERTY GCSIM_${KIND}S ${name})
  endif()
endfunction()
