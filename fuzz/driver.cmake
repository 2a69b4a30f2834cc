# The fuzz tests of the main build. The targets are built by clang in a sub-build of this tree
# (build/fuzz, -DBVB_FUZZ=ON) so the main build keeps its own compiler and flags; without clang
# and its libFuzzer runtime (Debian: clang, libclang-rt-14-dev) each fuzz test is reported as
# skipped, with the reason, and nothing else changes.
#
#   ctest -L fuzz                        each target for BVB_FUZZ_SECONDS (60) from its seeds
#   BVB_FUZZ_SECONDS=300 ctest -L fuzz   the same, longer, without reconfiguring
#   ctest -C fuzz-long -L fuzz-long      each target until BVB_FUZZ_LONG_RUNS (1,000,000) inputs
# Every run keeps what it finds in build/fuzz-work/NAME/corpus and starts from it next time;
# a finding fails the test and leaves the input in build/fuzz-work/NAME/ (README: Fuzzing).
include(${CMAKE_CURRENT_LIST_DIR}/targets.cmake)
set(BVB_FUZZ_SECONDS 60 CACHE STRING "How long each fuzz test runs (-max_total_time, seconds)")
set(BVB_FUZZ_LONG_RUNS 1000000 CACHE STRING "Inputs per target of the opt-in fuzz-long tests (-runs)")

option(BVB_FUZZ_TESTS "Build the fuzz targets with clang and run them in the tests" ON)
# The sub-build is one step of the main build, whose other steps keep running beside it: left to
# itself its ninja would start cores + 2 jobs on top of the main build's -j.
set(BVB_FUZZ_BUILD_JOBS 2 CACHE STRING "Parallel jobs of the fuzz sub-build")

find_program(BVB_CLANGXX NAMES clang++ clang++-14)
find_program(BVB_CLANG NAMES clang clang-14)
set(_bvb_fuzz_missing "")
if(NOT BVB_FUZZ_TESTS)
  set(_bvb_fuzz_missing "turned off (-DBVB_FUZZ_TESTS=OFF)")
elseif(NOT BVB_CLANGXX OR NOT BVB_CLANG)
  set(_bvb_fuzz_missing "clang not found (Debian: apt-get install clang libclang-rt-14-dev)")
else()
  # clang prints the name back unchanged when the runtime library is not installed.
  execute_process(COMMAND ${BVB_CLANGXX} -print-file-name=libclang_rt.fuzzer-x86_64.a
                  OUTPUT_VARIABLE _bvb_fuzzer_rt OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT IS_ABSOLUTE "${_bvb_fuzzer_rt}" OR NOT EXISTS "${_bvb_fuzzer_rt}")
    set(_bvb_fuzz_missing "clang's libFuzzer runtime not found (Debian: apt-get install libclang-rt-14-dev)")
  endif()
endif()

set(_bvb_fuzz_dir ${CMAKE_BINARY_DIR}/fuzz)
if(_bvb_fuzz_missing STREQUAL "")
  message(STATUS "fuzz targets: built by ${BVB_CLANGXX} in ${_bvb_fuzz_dir}")
  include(ExternalProject)
  ExternalProject_Add(fuzzers
    SOURCE_DIR ${CMAKE_SOURCE_DIR}
    BINARY_DIR ${_bvb_fuzz_dir}
    CMAKE_ARGS -DBVB_FUZZ=ON
               -DCMAKE_C_COMPILER=${BVB_CLANG} -DCMAKE_CXX_COMPILER=${BVB_CLANGXX}
               -DCMAKE_BUILD_TYPE=RelWithDebInfo
               -DCMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER}
               -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
               -DBVB_FRAMES_REAL=${BVB_FRAMES_REAL}
    BUILD_COMMAND ${CMAKE_COMMAND} --build . --target bvb_fuzzers -j ${BVB_FUZZ_BUILD_JOBS}
    INSTALL_COMMAND ""
    BUILD_ALWAYS ON)
else()
  message(STATUS "fuzz tests skipped: ${_bvb_fuzz_missing}")
endif()

set(_bvb_fuzz_run ${CMAKE_CURRENT_LIST_DIR}/run.sh)
foreach(t ${BVB_FUZZ_TARGETS})
  set(_args --target ${t} --fuzzer ${_bvb_fuzz_dir}/fuzz/fuzz_${t} --source ${CMAKE_SOURCE_DIR}
            --frames-real ${BVB_FRAMES_REAL} --work ${CMAKE_BINARY_DIR}/fuzz-work/${t}
            --max-len ${BVB_FUZZ_${t}_MAX_LEN})
  if(BVB_FUZZ_${t}_DICT)
    list(APPEND _args --dict ${CMAKE_SOURCE_DIR}/${BVB_FUZZ_${t}_DICT})
  endif()
  foreach(s ${BVB_FUZZ_${t}_SEEDS})
    list(APPEND _args --seeds ${s})
  endforeach()
  if(NOT _bvb_fuzz_missing STREQUAL "")
    set(_args --skip "${_bvb_fuzz_missing}")
  endif()
  add_test(NAME fuzz_${t} COMMAND ${_bvb_fuzz_run} ${_args} --seconds ${BVB_FUZZ_SECONDS})
  # 77: run.sh's skip; the timeout leaves room for a longer BVB_FUZZ_SECONDS from the environment.
  set_tests_properties(fuzz_${t} PROPERTIES LABELS fuzz SKIP_RETURN_CODE 77 TIMEOUT 3600)
  add_test(NAME fuzz_long_${t} COMMAND ${_bvb_fuzz_run} ${_args} --runs ${BVB_FUZZ_LONG_RUNS}
           CONFIGURATIONS fuzz-long)
  set_tests_properties(fuzz_long_${t} PROPERTIES LABELS fuzz-long SKIP_RETURN_CODE 77 TIMEOUT 14400)
endforeach()
