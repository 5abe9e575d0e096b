# gcsim_add_scene_format(NAME name SOURCES file.cpp ... [LIBS target ...])
#
# A scene format added from its own file or folder: its sources register it with the scene
# catalogue (apps/common/scene/scene_catalogue.hpp, a static SceneFormatRegistrar), so they become
# an OBJECT library gcsim_scene_format_<name> (a library would let the linker drop the registrar),
# listed in the global property GCSIM_SCENE_FORMATS (or GCSIM_<SET>_SCENE_FORMATS when
# GCSIM_SCENE_FORMAT_SET is set, as tests/scene_formats does), from which
# gcsim_add_gcsim_executable links it. The formats of the scene layer's own table need none of this.
function(gcsim_add_scene_format)
  cmake_parse_arguments(FORMAT "" "NAME" "SOURCES;LIBS" ${ARGN})
  gcsim_add_registered(scene_format "${FORMAT_NAME}" gcsim_scene "${FORMAT_SOURCES}" "${FORMAT_LIBS}")
endfunction()
