# roofsweep_library(NAME SOURCES ... DEPS ...)
#   A static library for one domain folder (algorithms/edges, io, ...). Headers
#   are included as "algorithms/edges/foo.h" from the source root.
function(roofsweep_library name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${A_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${A_DEPS})
endfunction()

# roofsweep_test(NAME SOURCES ... DEPS ...)
#   One GoogleTest program per domain folder, discovered by CTest. Each test
#   gets ROOFSWEEP_SHARED_DIR so it can find ../shared.
function(roofsweep_test name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${A_SOURCES})
  target_link_libraries(${name} PRIVATE ${A_DEPS} roofsweep_test_support GTest::gtest_main)
  gtest_discover_tests(${name}
    DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "ROOFSWEEP_SHARED_DIR_DEFAULT=${ROOFSWEEP_SHARED_DIR};ROOFSWEEP_SOURCE_DIR=${PROJECT_SOURCE_DIR};ROOFSWEEP_BINARY_DIR=${PROJECT_BINARY_DIR}")
endfunction()

# roofsweep_benchmark(NAME SOURCES ... DEPS ...)
function(roofsweep_benchmark name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  if(ROOFSWEEP_BENCHMARKS)
    add_executable(${name} ${A_SOURCES})
    target_link_libraries(${name} PRIVATE ${A_DEPS} benchmark::benchmark_main)
  endif()
endfunction()
