# gpu_server_build_needs_only_libc_libm_libegl: the GPU-server build (cmake/gpu-server.cmake,
# docs/gpu-servers.md) configured from this source tree into a scratch directory with no C++
# compiler: libthinlight, thinlight-bench and thinlight-render build with the EGL back end alone,
# and their DT_NEEDED entries name nothing beyond libc, libm, libEGL, libOpenGL (and libthinlight
# itself). The build directory is then moved elsewhere and its tools run from there on Mesa's EGL
# (surfaceless, llvmpipe): thinlight-bench --quick --context egl (one light count, one frame) writes
# its JSON, thinlight-render prints its statistics, and every image output is refused with one line
# naming THINLIGHT_WITH_IO.
#
# Included by tests/CMakeLists.txt it adds the test; run with `cmake -P` it is the checker:
#   -DSOURCE_DIR=<tree> -DWORK=<scratch dir> -DCC=<C compiler> -DGENERATOR=<generator>

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
  set(ONE_LINE_EXITS 1 2)
  include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)

  # run(<what> <command>...): fails with its output unless it exits 0; sets `out` and `err`.
  function(run what)
    execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE r OUTPUT_VARIABLE o
      ERROR_VARIABLE e)
    if(NOT r EQUAL 0)
      list(JOIN ARGN " " cmd)
      message(FATAL_ERROR "${what} failed (${r}):\n${cmd}\n${o}\n${e}")
    endif()
    set(out "${o}" PARENT_SCOPE)
    set(err "${e}" PARENT_SCOPE)
  endfunction()

  # The DT_NEEDED entries of an ELF file must all be allowed on a machine with only a GPU driver.
  function(expect_needed_only file)
    run("readelf -d ${file}" readelf -d "${file}")
    string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[[^]\n]+\\]" lines "${out}")
    set(needed)
    foreach(l IN LISTS lines)
      string(REGEX REPLACE ".*\\[([^]]+)\\]" "\\1" lib "${l}")
      list(APPEND needed "${lib}")
      if(NOT lib MATCHES "^(libc|libm|libEGL|libOpenGL|libthinlight)\\.so\\.[0-9]+$" AND
         NOT lib MATCHES "^ld-linux[-a-z0-9_]*\\.so\\.[0-9]+$")
        message(FATAL_ERROR "${file} needs ${lib}: not allowed on a GPU server (all NEEDED: ${needed})")
      endif()
    endforeach()
    get_filename_component(name "${file}" NAME)
    message(STATUS "${name}: NEEDED ${needed}")
  endfunction()

  string(TIMESTAMP t0 "%s")
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  set(build "${WORK}/build")
  run("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${build}" -G "${GENERATOR}"
    -C "${SOURCE_DIR}/cmake/gpu-server.cmake" "-DCMAKE_C_COMPILER=${CC}"
    "-DCMAKE_CXX_COMPILER=${WORK}/no-c++" --no-warn-unused-cli)
  if(EXISTS "${build}/CMakeFiles/${CMAKE_VERSION}/CMakeCXXCompiler.cmake")
    message(FATAL_ERROR "the GPU-server configure enabled C++")
  endif()
  run("build" ${CMAKE_COMMAND} --build "${build}" --target thinlight thinlight-bench thinlight-render
    --parallel 2)
  string(TIMESTAMP t1 "%s")

  # Move the build directory: the tools must find libthinlight relative to themselves.
  set(moved "${WORK}/copied-to-gpu-server")
  file(RENAME "${build}" "${moved}")
  file(GLOB_RECURSE libs "${moved}/libthinlight.so.*.*.*")
  file(GLOB_RECURSE bench "${moved}/thinlight-bench")
  file(GLOB_RECURSE render "${moved}/thinlight-render")
  if(NOT libs OR NOT bench OR NOT render)
    message(FATAL_ERROR "missing outputs in ${moved}: '${libs}' '${bench}' '${render}'")
  endif()
  foreach(f IN LISTS libs bench render)
    expect_needed_only("${f}")
  endforeach()

  set(TOOL "${bench}")
  run_tool(--list-devices)
  expect_exit(0 "thinlight-bench --list-devices")
  run_tool(--quick --context egl --lights 8 --frames 1 --warmup 0 --json "${WORK}/bench.json")
  expect_exit(0 "thinlight-bench --quick --context egl")
  if(NOT err MATCHES "context egl: EGL [^\n]*GL_RENDERER")
    message(FATAL_ERROR "thinlight-bench named no EGL context:\n${err}")
  endif()
  file(READ "${WORK}/bench.json" json)
  string(JSON context GET "${json}" context)
  string(JSON records LENGTH "${json}" records)
  # four modes with volumes and with tiles, thin-lpp/tiled with the R11G11B10F light buffer,
  # thin-lpp with its light buffer at 1/2 and 1/4, the three deferred modes' tiled compute pass,
  # and visibility once, visibility/tiled (it always lights with tiles): 8 + 1 + 2 + 3 + 1
  if(NOT context STREQUAL "egl" OR NOT records EQUAL 15)
    message(FATAL_ERROR "bench.json: context '${context}', ${records} records (expected egl, 15)")
  endif()
  run_tool(--quick --context egl --out "${WORK}/images")
  expect_exit(1 "thinlight-bench --out without io")
  if(NOT err MATCHES "THINLIGHT_WITH_IO" OR EXISTS "${WORK}/images")
    message(FATAL_ERROR "thinlight-bench --out: ${err}")
  endif()
  run_tool(--context osmesa)
  expect_exit(2 "thinlight-bench --context osmesa (not built)")

  set(TOOL "${render}")
  run_tool(default --context egl --size 160x90 --lights 8 --stats)
  expect_exit(0 "thinlight-render --stats")
  if(NOT out MATCHES "160x90, [0-9]+ lights" OR NOT out MATCHES "frame +[0-9.]+ ms")
    message(FATAL_ERROR "thinlight-render --stats printed:\n${out}")
  endif()
  foreach(args "default|-o|${WORK}/x.png" "default|--print-plan|--dump-targets|${WORK}/t" "scene.gltf|--stats")
    string(REPLACE "|" ";" args "${args}")
    run_tool(${args})
    expect_exit(1 "thinlight-render ${args} without io")
    if(NOT err MATCHES "THINLIGHT_WITH_IO")
      message(FATAL_ERROR "thinlight-render ${args}: ${err}")
    endif()
  endforeach()
  file(GLOB left "${WORK}/x.png" "${WORK}/t")
  if(left)
    message(FATAL_ERROR "files left behind: ${left}")
  endif()
  string(TIMESTAMP t2 "%s")
  math(EXPR build_s "${t1} - ${t0}")
  math(EXPR run_s "${t2} - ${t1}")
  message(STATUS "GPU-server build: configure + build ${build_s} s, checks and runs ${run_s} s")
  return()
endif()

# The sub-build is plain Release whatever this tree's flags: under THINLIGHT_SANITIZE it would
# repeat the same work, so it runs in the plain build only.
if(THINLIGHT_WITH_RENDERER AND NOT THINLIGHT_SANITIZE)
  add_test(NAME gpu_server_build_needs_only_libc_libm_libegl
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
      -DWORK=${CMAKE_CURRENT_BINARY_DIR}/gpu_server_build -DCC=${CMAKE_C_COMPILER}
      -DGENERATOR=${CMAKE_GENERATOR} -P ${CMAKE_CURRENT_LIST_FILE})
  set_tests_properties(gpu_server_build_needs_only_libc_libm_libegl PROPERTIES
    LABELS "packaging;egl;tools;full" TIMEOUT 900)
endif()
