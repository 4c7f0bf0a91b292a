# roofsweep_library(NAME SOURCES ... DEPS ...)
#   A static library for one domain folder (algorithms/edges, io, ...). Headers
#   are included as "algorithms/edges/foo.h" from the source root.
function(roofsweep_library name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${A_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${A_DEPS})
  roofsweep_precompile(${name} common.h)
endfunction()

# roofsweep_precompile(TARGET HEADER)
#   With ROOFSWEEP_PCH, TARGET precompiles cmake/pch/HEADER. Parsing the
#   standard library, Eigen, OpenCV and GoogleTest is about half of a source's
#   compile time here, and CI builds everything twice (release and sanitizers).
function(roofsweep_precompile target header)
  if(ROOFSWEEP_PCH)
    target_precompile_headers(${target} PRIVATE ${PROJECT_SOURCE_DIR}/cmake/pch/${header})
  endif()
endfunction()

# roofsweep_test(NAME SOURCES ... DEPS ...)
#   One GoogleTest program per domain folder, discovered by CTest. Each test
#   gets ROOFSWEEP_SHARED_DIR so it can find ../shared.
function(roofsweep_test name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${A_SOURCES})
  target_link_libraries(${name} PRIVATE ${A_DEPS} roofsweep_test_support GTest::gtest_main)
  roofsweep_precompile(${name} test.h)
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

# roofsweep_uninstrumented(TARGET [SOURCES ...])
#   In the sanitizer build, TARGET (or only the given sources of it) is built
#   without sanitizers and at -O2. For the measuring instruments only: the
#   simulator and the tests' ray caster render every test scene and took most
#   of the sanitized test time (ten times their release time) while checking
#   none of the pipeline. Their results are checked by the release build's
#   tests, which all run there.
function(roofsweep_uninstrumented target)
  if(NOT ROOFSWEEP_SANITIZE)
    return()
  endif()
  set(flags -fno-sanitize=all -O2)
  if(ARGN)
    # A source compiled with other flags cannot use the target's
    # precompiled header.
    set_source_files_properties(${ARGN} TARGET_DIRECTORY ${target}
      PROPERTIES COMPILE_OPTIONS "${flags}" SKIP_PRECOMPILE_HEADERS ON)
  else()
    target_compile_options(${target} PRIVATE ${flags})
  endif()
endfunction()
