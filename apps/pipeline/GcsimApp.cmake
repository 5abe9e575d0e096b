# gcsim_add_app(NAME name SOURCES file.cpp ... [LIBS target ...])
#
# Declares an application of the gcsim command: its sources (which register it with
# apps/pipeline/app_registry.hpp through a static AppRegistrar) become an OBJECT library, so every
# registrar is linked into the executable even though nothing refers to it by name. The app is
# appended to the global property GCSIM_APPS (or GCSIM_<SET>_APPS when GCSIM_APP_SET is set, as
# tests/apps does), from which gcsim_add_gcsim_executable links it.
function(gcsim_add_app)
  cmake_parse_arguments(APP "" "NAME" "SOURCES;LIBS" ${ARGN})
  gcsim_add_registered(app "${APP_NAME}" gcsim_pipeline "${APP_SOURCES}" "${APP_LIBS}")
endfunction()

# gcsim_add_gcsim_executable(target app-name ...): the gcsim command line with these applications.
function(gcsim_add_gcsim_executable target)
  add_executable(${target} ${PROJECT_SOURCE_DIR}/apps/cli/main.cpp)
  target_link_libraries(${target} PRIVATE gcsim_cli)
  # The backends, interconnects, network models and scene formats this build adds from folders of
  # their own (gcsim_add_backend, gcsim_add_interconnect, gcsim_add_network_model,
  # gcsim_add_scene_format).
  foreach(kind backend interconnect network_model scene_format)
    string(TOUPPER ${kind} KIND)
    get_property(parts GLOBAL PROPERTY GCSIM_${KIND}S)
    list(TRANSFORM parts PREPEND gcsim_${kind}_)
    target_link_libraries(${target} PRIVATE ${parts})
  endforeach()
  foreach(app ${ARGN})
    target_link_libraries(${target} PRIVATE gcsim_app_${app})
  endforeach()
endfunction()
