# What `cmake --install` puts under a prefix, the package config that lets another CMake
# project find_package(curvebench), and the .deb that `cpack -G DEB` builds of the same:
#
#   bin/curvebench                         the command
#   lib/libcurvebench_*.a                  one static library per layer
#   include/curvebench/LAYER/...h          the public headers, included as "LAYER/..."
#   lib/cmake/curvebench/                  curvebenchConfig.cmake, its version and targets,
#                                          curvebench_add_program (curvebenchProgram.cmake)
#   share/curvebench/data, bench/report    the bundled data and the report's scripts
#   lib/python3/dist-packages/curvebench   the Python module, when it is built (its own
#                                          install rules: python/CMakeLists.txt)
include(CMakePackageConfigHelpers)

# The layers' libraries, exported as curvebench::NAME for curvebench_NAME.
set(curvebench_exported_libraries
  curvebench_geometry curvebench_geometry_io curvebench_geometry_curves curvebench_geometry_lfs
  curvebench_geometry_sampling curvebench_geometry_image curvebench_geometry_metrics
  curvebench_graphs curvebench_algorithms curvebench_certify curvebench_runner curvebench_cli
  curvebench_fuzz_main)
if(TARGET curvebench_benchmark_main)
  list(APPEND curvebench_exported_libraries curvebench_benchmark_main)
endif()
# The same names in the build tree (aliases), so that code written against the package
# (python/, a user's subproject) builds in-tree unchanged.
foreach(library IN LISTS curvebench_exported_libraries)
  string(REGEX REPLACE "^curvebench_" "" export_name ${library})
  set_target_properties(${library} PROPERTIES EXPORT_NAME ${export_name})
  add_library(curvebench::${export_name} ALIAS ${library})
endforeach()

set(curvebench_install_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/curvebench)
set(CURVEBENCH_INSTALL_RESOURCE_DIR ${CMAKE_INSTALL_DATADIR}/curvebench)

install(TARGETS curvebench ${curvebench_exported_libraries} EXPORT curvebenchTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

# The public headers (CURVEBENCH_PUBLIC_HEADERS, in the top CMakeLists.txt): whole layers,
# and single files of layers whose other headers stay private.
foreach(item IN LISTS CURVEBENCH_PUBLIC_HEADERS)
  if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/${item})
    install(DIRECTORY ${item}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curvebench/${item} FILES_MATCHING PATTERN "*.h")
  else()
    get_filename_component(folder ${item} DIRECTORY)
    install(FILES ${item} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curvebench/${folder})
  endif()
endforeach()

install(DIRECTORY data/ DESTINATION ${CURVEBENCH_INSTALL_RESOURCE_DIR}/data)
install(DIRECTORY bench/report/ DESTINATION ${CURVEBENCH_INSTALL_RESOURCE_DIR}/bench/report
        FILES_MATCHING PATTERN "*.py" PATTERN "*.html")

install(EXPORT curvebenchTargets NAMESPACE curvebench:: DESTINATION ${curvebench_install_cmake_dir})
configure_package_config_file(cmake/curvebenchConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/curvebenchConfig.cmake
                              INSTALL_DESTINATION ${curvebench_install_cmake_dir}
                              PATH_VARS CURVEBENCH_INSTALL_RESOURCE_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/curvebenchConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/curvebenchConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/curvebenchConfigVersion.cmake
              cmake/curvebenchProgram.cmake
        DESTINATION ${curvebench_install_cmake_dir})
# A user's program gets the command line's own main; the fuzz sub-build's project.
install(FILES bench/cli/main.cpp DESTINATION ${curvebench_install_cmake_dir} RENAME curvebench_program_main.cpp)
install(DIRECTORY cmake/fuzz_program DESTINATION ${curvebench_install_cmake_dir})

# cpack -G DEB: the same files under /usr. A library user compiles against the headers, so
# the package depends on the -dev packages of what they include and link.
set(CPACK_PACKAGE_NAME curvebench)
set(CPACK_PACKAGE_VENDOR "curvebench")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "planar curve reconstruction on exact geometry: library, command and benchmark")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "curvebench developers")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libcgal-dev, libgmp-dev, libmpfr-dev, libboost-graph-dev, libtbb-dev, libfreetype-dev, fonts-dejavu-core, libcli11-dev, nlohmann-json3-dev, librapidcheck-dev, python3, python3-matplotlib, cmake")
if(CURVEBENCH_PYTHON_MODULE)  # the module is built for this python3's minor version and imports numpy
  math(EXPR curvebench_python_next_minor "${Python3_VERSION_MINOR} + 1")
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", python3-numpy, python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), "
                                             "python3 (<< ${Python3_VERSION_MAJOR}.${curvebench_python_next_minor})")
endif()
# The benchmark program needs Google Benchmark; the fuzz target, clang's libFuzzer.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libbenchmark-dev, clang-14, libclang-rt-14-dev")
if(CURVEBENCH_PYTHON_MODULE)  # curvebench.run() gives DataFrames
  string(APPEND CPACK_DEBIAN_PACKAGE_RECOMMENDS ", python3-pandas")
endif()
include(CPack)
