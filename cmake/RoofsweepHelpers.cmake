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
#   With ROOFSWEEP_PCH, TARGET uses the precompiled cmake/pch/HEADER. Parsing
#   the standard library, Eigen, OpenCV and GoogleTest is about half of a
#   source's compile time here, and CI builds everything twice (release and
#   sanitizers). Each header is precompiled once, by a donor target of its
#   own (roofsweep_pch_donors below), and reused: one per target cost 25
#   precompilations of about 10 s each per build. Applied at the end of the
#   directory, once roofsweep_precompile_own may have been called.
function(roofsweep_precompile target header)
  if(ROOFSWEEP_PCH)
    cmake_language(EVAL CODE
      "cmake_language(DEFER CALL _roofsweep_apply_pch [[${target}]] [[${header}]])")
  endif()
endfunction()

# roofsweep_precompile_own(TARGET)
#   TARGET precompiles its header itself instead of reusing the donor's: for
#   a target compiled with options that change what the header means. GCC
#   refuses a precompiled header built under other predefined macros (e.g.
#   __NO_MATH_ERRNO__ from -fno-math-errno, or the sanitizers' own) and then
#   silently parses the header again (-Winvalid-pch tells).
function(roofsweep_precompile_own target)
  set_property(TARGET ${target} PROPERTY ROOFSWEEP_OWN_PCH ON)
endfunction()

function(_roofsweep_apply_pch target header)
  get_property(own TARGET ${target} PROPERTY ROOFSWEEP_OWN_PCH)
  if(own)
    target_precompile_headers(${target} PRIVATE ${PROJECT_SOURCE_DIR}/cmake/pch/${header})
  else()
    string(REPLACE ".h" "" donor "roofsweep_pch_${header}")
    target_precompile_headers(${target} REUSE_FROM ${donor})
  endif()
endfunction()

# The donors: object libraries of one empty source that see every header
# the precompiled one may take (it takes only those it can see, by
# __has_include), so that what a consumer gets does not depend on which
# target happened to be first.
function(roofsweep_pch_donors)
  if(NOT ROOFSWEEP_PCH)
    return()
  endif()
  set(dir ${PROJECT_SOURCE_DIR}/cmake/pch)
  add_library(roofsweep_pch_common OBJECT ${dir}/donor.cc)
  target_link_libraries(roofsweep_pch_common PRIVATE Eigen3::Eigen roofsweep_opencv)
  target_precompile_headers(roofsweep_pch_common PRIVATE ${dir}/common.h)
  add_library(roofsweep_pch_test OBJECT ${dir}/donor.cc)
  target_link_libraries(roofsweep_pch_test PRIVATE Eigen3::Eigen roofsweep_opencv GTest::gtest)
  target_precompile_headers(roofsweep_pch_test PRIVATE ${dir}/test.h)
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
    target_link_libraries(${name} PRIVATE ${A_DEPS} rs_bench_main)
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
    # The shared precompiled header was built with the sanitizers.
    roofsweep_precompile_own(${target})
  endif()
endfunction()
