# Fuzzing (tests/fuzz/README.md). Two parts:
#  - always: the regression inputs of every target (tests/fuzz/regressions) replayed through the
#    target's code built with this build's compiler (replay_main.c), so a past finding fails the
#    suite in every build, the sanitizer build included (fuzz_regressions_<target>);
#  - with clang and libFuzzer (Debian: clang, libclang-rt-14-dev) and THINLIGHT_FUZZ on: the
#    libFuzzer targets, built by clang as a project of their own (tests/fuzz/CMakeLists.txt, an
#    ExternalProject, since the default compiler is gcc), each fuzzed for THINLIGHT_FUZZ_SECONDS
#    from a seed corpus generated at test time (fuzz_seeds) plus the regression inputs
#    (fuzz_<target>). Label: fuzz.
if(NOT (TARGET thinlight AND THINLIGHT_WITH_IO))
  return()
endif()

set(_tl_fuzz_dir ${CMAKE_CURRENT_LIST_DIR}/fuzz)
set(_tl_fuzz_work ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
# target: regression folders, seed folders (under the work folder), dictionary
set(_tl_fuzz_targets gltf image codec)
set(_tl_fuzz_gltf_seeds seeds/gltf_json seeds/gltf_glb)
set(_tl_fuzz_image_seeds seeds/image)
set(_tl_fuzz_codec_seeds seeds/codec)
set(_tl_fuzz_gltf_dict ${_tl_fuzz_dir}/gltf.dict)
set(_tl_fuzz_image_dict ${_tl_fuzz_dir}/image.dict)
set(_tl_fuzz_codec_dict "")
# The largest single allocation each target may make, in MB: twice the glTF target's load budget
# (64 MiB); the image target's pixels are at most 4 MiB (max_pixels 2^20); the codec allocates
# nothing.
set(_tl_fuzz_gltf_malloc_mb 128)
set(_tl_fuzz_image_malloc_mb 32)
set(_tl_fuzz_codec_malloc_mb 32)

foreach(t IN LISTS _tl_fuzz_targets)
  add_executable(fuzz_replay_${t} ${_tl_fuzz_dir}/replay_main.c ${_tl_fuzz_dir}/fuzz_${t}.c)
  target_include_directories(fuzz_replay_${t} PRIVATE ${_tl_fuzz_dir})
  target_link_libraries(fuzz_replay_${t} PRIVATE thinlight::thinlight thinlight_warnings m)
  set_target_properties(fuzz_replay_${t} PROPERTIES LINKER_LANGUAGE CXX)
  add_test(NAME fuzz_regressions_${t} COMMAND fuzz_replay_${t} ${_tl_fuzz_dir}/regressions/${t})
  set_tests_properties(fuzz_regressions_${t} PROPERTIES LABELS "fuzz;io" TIMEOUT 300)
endforeach()

# libFuzzer needs clang and its runtime; the fuzz targets carry their own sanitizers, so a
# sanitizer build does not build them again.
find_program(THINLIGHT_FUZZ_CC NAMES clang clang-14 DOC "clang for the libFuzzer targets")
find_program(THINLIGHT_FUZZ_CXX NAMES clang++ clang++-14 DOC "clang++ for the libFuzzer targets")
set(_tl_fuzz_default OFF)
if(THINLIGHT_FUZZ_CC AND THINLIGHT_FUZZ_CXX AND NOT THINLIGHT_SANITIZE)
  if(NOT DEFINED THINLIGHT_FUZZ_WORKS)
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/fuzz_probe.c
      "#include <stdint.h>\n#include <stddef.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }\n")
    execute_process(COMMAND ${THINLIGHT_FUZZ_CC} -fsanitize=fuzzer,address ${CMAKE_CURRENT_BINARY_DIR}/fuzz_probe.c
                      -o ${CMAKE_CURRENT_BINARY_DIR}/fuzz_probe
                    RESULT_VARIABLE _tl_probe OUTPUT_QUIET ERROR_QUIET)
    if(_tl_probe EQUAL 0)
      set(THINLIGHT_FUZZ_WORKS ON CACHE INTERNAL "clang links -fsanitize=fuzzer")
    else()
      set(THINLIGHT_FUZZ_WORKS OFF CACHE INTERNAL "clang links -fsanitize=fuzzer")
    endif()
  endif()
  set(_tl_fuzz_default ${THINLIGHT_FUZZ_WORKS})
endif()
option(THINLIGHT_FUZZ "Build the libFuzzer targets with clang and fuzz each in ctest" ${_tl_fuzz_default})
set(THINLIGHT_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzz_<target> test fuzzes")
if(NOT THINLIGHT_FUZZ)
  message(STATUS "thinlight: libFuzzer targets off (need clang and libclang-rt-14-dev; not in sanitizer builds)")
  return()
endif()
message(STATUS "thinlight: libFuzzer targets with ${THINLIGHT_FUZZ_CC}, ${THINLIGHT_FUZZ_SECONDS} s each in ctest")

include(ExternalProject)
ExternalProject_Add(thinlight_fuzz_targets
  SOURCE_DIR ${_tl_fuzz_dir}
  BINARY_DIR ${CMAKE_CURRENT_BINARY_DIR}/fuzz-build
  CMAKE_ARGS -DCMAKE_C_COMPILER=${THINLIGHT_FUZZ_CC} -DCMAKE_CXX_COMPILER=${THINLIGHT_FUZZ_CXX}
             -DTHINLIGHT_SOURCE_DIR=${PROJECT_SOURCE_DIR}
             -DTHINLIGHT_TINYGLTF_INCLUDE_DIR=${THINLIGHT_TINYGLTF_INCLUDE_DIR}
             -DTHINLIGHT_NLOHMANN_JSON_INCLUDE_DIR=${THINLIGHT_NLOHMANN_JSON_INCLUDE_DIR}
  BUILD_ALWAYS ON
  INSTALL_COMMAND "")

# The seed corpora, generated into the work folder before the fuzz tests run.
add_executable(fuzz_seeds ${_tl_fuzz_dir}/fuzz_seeds.c)
target_link_libraries(fuzz_seeds PRIVATE tl_gltf_fixtures thinlight_warnings)
set_target_properties(fuzz_seeds PROPERTIES LINKER_LANGUAGE CXX)
add_test(NAME fuzz_seed_corpus COMMAND fuzz_seeds ${_tl_fuzz_work}/seeds)
set_tests_properties(fuzz_seed_corpus PROPERTIES FIXTURES_SETUP tl_fuzz_seeds LABELS fuzz)

foreach(t IN LISTS _tl_fuzz_targets)
  file(MAKE_DIRECTORY ${_tl_fuzz_work}/corpus/${t} ${_tl_fuzz_work}/artifacts)
  set(seeds "")
  foreach(s IN LISTS _tl_fuzz_${t}_seeds)
    list(APPEND seeds ${_tl_fuzz_work}/${s})
  endforeach()
  set(dict "")
  if(_tl_fuzz_${t}_dict)
    set(dict -dict=${_tl_fuzz_${t}_dict})
  endif()
  # The corpus folder (first) keeps what each run finds; the seeds and regressions are read only.
  # -malloc_limit_mb: no single allocation may pass the target's limit above, so an allocation the
  # budget does not govern is a finding. -timeout is wall time: generous, for a
  # busy 2-core machine. A crash, leak, timeout or OOM fails the test and leaves the input in
  # artifacts/.
  add_test(NAME fuzz_${t}
    COMMAND ${CMAKE_CURRENT_BINARY_DIR}/fuzz-build/fuzz_${t}
            -max_total_time=${THINLIGHT_FUZZ_SECONDS} -timeout=60 -rss_limit_mb=2560 -malloc_limit_mb=${_tl_fuzz_${t}_malloc_mb}
            -print_final_stats=1 -artifact_prefix=${_tl_fuzz_work}/artifacts/${t}- ${dict}
            ${_tl_fuzz_work}/corpus/${t} ${seeds} ${_tl_fuzz_dir}/regressions/${t})
  math(EXPR _tl_timeout "${THINLIGHT_FUZZ_SECONDS} + 240")
  set_tests_properties(fuzz_${t} PROPERTIES LABELS fuzz FIXTURES_REQUIRED tl_fuzz_seeds TIMEOUT ${_tl_timeout})
endforeach()
