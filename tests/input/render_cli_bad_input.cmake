# thinlight-render's command-line contract on bad input (DESIGN.md section 6): exit 1 on bad
# input with one line naming the problem, 2 on bad usage, and no partial output.
# Included by tests/input/CMakeLists.txt it adds the tests; run with `cmake -P` it is the checker:
#   -DTOOL=<thinlight-render> -DCHECK=<bad_usage|bad_input> -DWORK=<scratch dir>

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
  set(ONE_LINE_EXITS 1) # bad usage (2) prints the usage text after its line
  include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")

  if(CHECK STREQUAL "bad_usage")
    run_tool(default -o "${WORK}/x.png" --no-such-flag)
    expect_exit(2 "unknown flag")
    run_tool(default -o "${WORK}/x.png" --size 12by3)
    expect_exit(2 "malformed size")
    run_tool(default)
    expect_exit(2 "no output")
    run_tool()
    expect_exit(2 "no arguments")
    expect_only("bad usage")
  elseif(CHECK STREQUAL "bad_input")
    run_tool("${WORK}/missing.gltf" -o "${WORK}/x.png")
    expect_exit(1 "scene file")
    run_tool(default -o "${WORK}/x.png" --size 0x10)
    expect_exit(1 "zero size")
    run_tool(default -o "${WORK}/x.png" --size 100000x10)
    expect_exit(1 "absurd size")
    run_tool(default -o "${WORK}/x.png" --lights 1000000)
    expect_exit(1 "absurd light count")
    run_tool(default -o "${WORK}/x.bmp" --size 32x32)
    expect_exit(1 "unsupported output type")
    run_tool(default -o "${WORK}/no/such/dir/x.png" --size 32x32 --lights 8)
    expect_exit(1 "unwritable output")
    expect_only("bad input")
  else()
    message(FATAL_ERROR "unknown CHECK '${CHECK}'")
  endif()
  return()
endif()

if(NOT TARGET thinlight-render)
  return()
endif()
foreach(check bad_usage bad_input)
  tl_add_cli_test(render_cli_${check} thinlight-render ${check} LABELS input tools gl
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
endforeach()
