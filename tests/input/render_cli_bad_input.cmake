# thinlight-render's command-line contract on bad input (DESIGN.md section 6): exit 1 on bad
# input with one line naming the problem, 2 on bad usage, and no partial output.
# The checker of the tests tests/input/CMakeLists.txt adds (tl_add_cli_test), run as
#   cmake -DTOOL=<thinlight-render> -DCHECK=<bad_usage|bad_input> -DWORK=<scratch dir> -P render_cli_bad_input.cmake

cmake_minimum_required(VERSION 3.25)
set(ONE_LINE_EXITS 1) # bad usage (2) prints the usage text after its line
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)

function(check_bad_usage)
  run_tool(default -o "${WORK}/x.png" --no-such-flag)
  expect_exit(2 "unknown flag")
  run_tool(default -o "${WORK}/x.png" --size 12by3)
  expect_exit(2 "malformed size")
  run_tool(default -o "${WORK}/x.png" --lighting phong)
  expect_exit(2 "unknown lighting model")
  run_tool(default -o "${WORK}/x.png" --fresnel exact)
  expect_exit(2 "unknown Fresnel layout")
  run_tool(default)
  expect_exit(2 "no output")
  run_tool()
  expect_exit(2 "no arguments")
  expect_only("bad usage")
endfunction()

function(check_bad_input)
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
endfunction()

cli_run_check()
