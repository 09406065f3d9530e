# One precompiled header for every C++ target of the default build. Parsing CGAL's
# kernels costs about 8 s per file, most of what each file takes to compile, so sharing
# one parse halves the build. Every target that reuses it must compile with the same
# flags and definitions, which is why CGAL::CGAL_Core is linked by curvebench_geometry
# (everyone) and the tests have their own header with GoogleTest and RapidCheck.
# The fuzz build's libraries share it too, but not its libFuzzer binaries: clang rejects a
# header precompiled without their -fsanitize=fuzzer.

set(curvebench_common_headers
  <algorithm> <cstdint> <functional> <map> <optional> <span> <string> <string_view> <vector>
  <boost/graph/adjacency_list.hpp>
  <CGAL/Exact_predicates_exact_constructions_kernel.h>
  <CGAL/Exact_predicates_inexact_constructions_kernel.h>
  <CGAL/Delaunay_triangulation_2.h>
  <CGAL/Triangulation_vertex_base_with_info_2.h>)

add_library(curvebench_pch OBJECT ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
target_link_libraries(curvebench_pch PRIVATE CGAL::CGAL CGAL::CGAL_Core Boost::boost)
target_precompile_headers(curvebench_pch PRIVATE ${curvebench_common_headers})

if(CURVEBENCH_TESTS)
  add_library(curvebench_test_pch OBJECT ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
  target_link_libraries(curvebench_test_pch PRIVATE CGAL::CGAL CGAL::CGAL_Core Boost::boost
                                                    rapidcheck_gtest rapidcheck GTest::gtest_main)
  target_precompile_headers(curvebench_test_pch PRIVATE ${curvebench_common_headers}
                            <gtest/gtest.h> <rapidcheck.h> <rapidcheck/gtest.h>)
endif()

# Every library and executable below `directory` reuses the header for its kind.
function(curvebench_reuse_precompiled_headers directory)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$" OR target MATCHES "(_pch$|^fuzz_)")
      continue()
    endif()
    get_target_property(source_dir ${target} SOURCE_DIR)
    if(source_dir MATCHES "^${PROJECT_SOURCE_DIR}/tests(/|$)")
      target_precompile_headers(${target} REUSE_FROM curvebench_test_pch)
    else()
      target_precompile_headers(${target} REUSE_FROM curvebench_pch)
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    curvebench_reuse_precompiled_headers(${subdirectory})
  endforeach()
endfunction()
curvebench_reuse_precompiled_headers(${PROJECT_SOURCE_DIR})
