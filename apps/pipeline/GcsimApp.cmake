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
  get_property(backends GLOBAL PROPERTY GCSIM_BACKENDS)  # those this build has (gcsim_add_backend)
  list(TRANSFORM backends PREPEND gcsim_backend_)
  target_link_libraries(${target} PRIVATE ${backends})
  get_property(formats GLOBAL PROPERTY GCSIM_SCENE_FORMATS)  # registered scene formats (gcsim_add_scene_format)
  list(TRANSFORM formats PREPEND gcsim_scene_format_)
  target_link_libraries(${target} PRIVATE ${formats})
  foreach(app ${ARGN})
    target_link_libraries(${target} PRIVATE gcsim_app_${app})
  endforeach()
endfunction()
