# curvebench_add_program(NAME SOURCE...): one's own algorithms, registered in SOURCE...
# (curvebench::algorithms::Registration; docs/own-algorithm.md), in three programs:
#
#   NAME            the curvebench command line, every verb, with them beside the built-ins
#   NAME-benchmark  Google Benchmark over growing n, with Complexity()  (needs libbenchmark-dev)
#   NAME-fuzz       a libFuzzer target under ASan and UBSan             (needs clang-14)
#
# libFuzzer needs clang. With another compiler, NAME-fuzz is built by a sub-build that
# compiles the same sources with clang++-14 (or clang++), found on the PATH; it lands in
# this directory like the others. A program that cannot be built is skipped with a message.
#
# curvebench_add_command, curvebench_add_benchmark and curvebench_add_fuzz_target make one
# each. Link more libraries to NAME and NAME-benchmark as to any target; the fuzz
# sub-build sees only the SOURCE files (and what they #include by relative path).
include_guard(GLOBAL)
include(ExternalProject)

set(_curvebench_cmake_dir ${CMAKE_CURRENT_LIST_DIR})

function(curvebench_add_command name)
  add_executable(${name} ${ARGN} ${_curvebench_cmake_dir}/curvebench_program_main.cpp)
  target_link_libraries(${name} PRIVATE curvebench::cli)
  target_compile_definitions(${name} PRIVATE CURVEBENCH_RESOURCE_ROOT="${CURVEBENCH_RESOURCE_ROOT}")
endfunction()

function(curvebench_add_benchmark name)
  if(NOT TARGET benchmark::benchmark OR NOT TARGET curvebench::benchmark_main)
    message(STATUS "curvebench: no ${name} (Google Benchmark not found: Debian's libbenchmark-dev)")
    return()
  endif()
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE curvebench::benchmark_main)
endfunction()

function(curvebench_add_fuzz_target name)
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    add_executable(${name} ${ARGN})
    set(sanitizers -fsanitize=fuzzer,address,undefined)
    target_compile_options(${name} PRIVATE ${sanitizers} -fno-sanitize-recover=undefined -g)
    target_link_options(${name} PRIVATE ${sanitizers})
    target_link_libraries(${name} PRIVATE curvebench::fuzz_main)
    return()
  endif()
  find_program(CURVEBENCH_CLANGXX NAMES clang++-14 clang++ DOC "clang for curvebench's libFuzzer targets")
  if(NOT CURVEBENCH_CLANGXX)
    message(STATUS "curvebench: no ${name} (libFuzzer needs clang: Debian's clang-14 and libclang-rt-14-dev)")
    return()
  endif()
  set(sources)
  foreach(source IN LISTS ARGN)
    get_filename_component(source ${source} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND sources ${source})
  endforeach()
  string(REPLACE ";" "|" sources "${sources}")
  ExternalProject_Add(${name}-clang-build
    SOURCE_DIR ${_curvebench_cmake_dir}/fuzz_program
    BINARY_DIR ${CMAKE_CURRENT_BINARY_DIR}/${name}-clang-build
    LIST_SEPARATOR |
    CMAKE_ARGS -DCMAKE_CXX_COMPILER=${CURVEBENCH_CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
               -Dcurvebench_DIR=${curvebench_DIR} -DCMAKE_PREFIX_PATH=${CMAKE_PREFIX_PATH}
               -DCURVEBENCH_FUZZ_TARGET=${name} -DCURVEBENCH_FUZZ_SOURCES=${sources}
    BUILD_ALWAYS ON
    INSTALL_COMMAND ${CMAKE_COMMAND} -E copy <BINARY_DIR>/${name} ${CMAKE_CURRENT_BINARY_DIR}/${name}
    BUILD_BYPRODUCTS ${CMAKE_CURRENT_BINARY_DIR}/${name})
endfunction()

function(curvebench_add_program name)
  if(NOT ARGN)
    message(FATAL_ERROR "curvebench_add_program(${name} SOURCE...): no source file")
  endif()
  curvebench_add_command(${name} ${ARGN})
  curvebench_add_benchmark(${name}-benchmark ${ARGN})
  curvebench_add_fuzz_target(${name}-fuzz ${ARGN})
endfunction()
