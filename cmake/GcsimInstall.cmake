# What `cmake --install build/release --prefix P` puts under P, so that a program outside this
# tree builds against gcsim:
#   bin/gcsim                              the command (with `gcsim mpirun`)
#   bin/gcsim-mpicc, bin/gcsim-mpicxx      compile MPI programs for it (apps/mpi/README.md)
#   include/gcsim/mpi/                     gcsim's mpi.h, mpi_functions.h, gcsim/mpi_ext.h
#   include/gcsim/{machine,parix,apps}/    the public headers, by the paths the sources use
#   lib/libgcsim_*.a                       the libraries a program links
#   lib/cmake/gcsim/                       find_package(gcsim CONFIG): gcsim::parix, gcsim::pipeline,
#                                          ..., and gcsim_add_program() (cmake/GcsimProgram.cmake)
#   lib/pkgconfig/gcsim.pc                 for builds without CMake (the PARIX API and its runtime)
#   share/gcsim/{configs,scenes,traces}/   machine files, scene files, the plotting package
# and `cpack -G DEB` in the build directory makes a Debian package of the same files.
include(CMakePackageConfigHelpers)

# The libraries a user's program links, exported as gcsim::<name>. gcsim::machine is an interface
# over machine_core (libgcsim_machine.a) and machine_registered, linked whole (machine/CMakeLists.txt).
set(GCSIM_EXPORTED machine machine_core machine_registered parix common scene programs pipeline cli)
foreach(name ${GCSIM_EXPORTED})
  set_target_properties(gcsim_${name} PROPERTIES EXPORT_NAME ${name})
  get_target_property(type gcsim_${name} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_compile_features(gcsim_${name} INTERFACE cxx_std_20)
  else()
    target_compile_features(gcsim_${name} PUBLIC cxx_std_20)
  endif()
endforeach()
list(TRANSFORM GCSIM_EXPORTED PREPEND gcsim_ OUTPUT_VARIABLE GCSIM_EXPORTED_TARGETS)

set(GCSIM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gcsim)
install(TARGETS gcsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${GCSIM_EXPORTED_TARGETS} EXPORT gcsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gcsim)
install(EXPORT gcsimTargets NAMESPACE gcsim:: DESTINATION ${GCSIM_CMAKE_DIR})

# Headers keep the paths the sources include them by ("parix/processor.hpp").
foreach(dir machine parix apps/common apps/pipeline apps/programs apps/cli)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gcsim/${dir}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/gcsimConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/gcsimConfig.cmake INSTALL_DESTINATION ${GCSIM_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gcsimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gcsimConfig.cmake ${PROJECT_BINARY_DIR}/gcsimConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/GcsimProgram.cmake ${PROJECT_SOURCE_DIR}/cmake/GcsimMpiProgram.cmake
              ${PROJECT_SOURCE_DIR}/apps/cli/main.cpp
        DESTINATION ${GCSIM_CMAKE_DIR})

file(RELATIVE_PATH GCSIM_PC_TO_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)  # "../..": relocatable
configure_file(${PROJECT_SOURCE_DIR}/cmake/gcsim.pc.in ${PROJECT_BINARY_DIR}/gcsim.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/gcsim.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# Data an installed gcsim finds beside its binary (apps/common/data_file.hpp: <bin>/../share/gcsim).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/configs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gcsim/configs
        FILES_MATCHING PATTERN "*.toml")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gcsim/scenes)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/traces/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gcsim/traces
        FILES_MATCHING PATTERN "*.py" PATTERN "*.md" PATTERN "*.csv" PATTERN "*.json" PATTERN "*.paje"
        PATTERN "__pycache__" EXCLUDE)

# cpack -G DEB: a Debian package whose dependencies dpkg-shlibdeps reads off the binary, plus
# what it runs but does not link (Python and Matplotlib for `gcsim plot`).
set(CPACK_PACKAGE_NAME gcsim)
set(CPACK_PACKAGE_VENDOR "gcsim developers")
set(CPACK_PACKAGE_CONTACT "gcsim developers <gcsim@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Simulator of the Parsytec GC-PowerPlus running parallel graphics applications")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-matplotlib, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "openmpi-bin")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
include(CPack)
