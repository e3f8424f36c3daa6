# thinlight-bench's command-line contract on bad input (docs/tools.md): bad usage exits 2,
# bad input 1, each with one line on stderr and no partial output.
#
# The checker of the tests tests/input/CMakeLists.txt adds (tl_add_cli_test), run as
#   cmake -DTOOL=<thinlight-bench> -DCHECK=<bad_usage|bad_input> -DWORK=<scratch dir> -P bench_bad_input.cmake

cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)

function(check_bad_usage)
  # pairs: the arguments ('|' between them), what the case is
  set(cases
    "--no-such-flag" "unknown option"
    "stray" "unexpected argument"
    "--lights" "--lights without a value"
    "--lights|70000" "more than 65536 lights"
    "--lights|8,,64" "empty item in --lights"
    "--lights|eight" "not a count"
    "--size|20000x10" "size over 16384"
    "--size|0x10" "zero size"
    "--size|12by3" "malformed size"
    "--modes|thin-lpp,bogus" "unknown mode"
    "--strategies|tiled,clustered" "unknown light strategy"
    "--strategies" "--strategies without a value"
    "--light-formats|rgba16f,rgb9e5" "unknown light buffer format"
    "--frames|0" "zero frames"
    "--out|${WORK}/out|--lights|-1" "negative light count"
    "--doc|${WORK}/doc.md" "--doc without --out"
    "--effects|ssao,glow" "unknown effect"
    "--effects|ssao,,fog" "empty item in --effects"
    "--effects" "--effects without a value"
    "--bloom-levels|0" "zero bloom levels"
    "--bloom-threshold|-1" "negative bloom threshold"
    "--bloom-scatter|1.5" "bloom scatter over 1"
    "--ssao-samples|65" "too many SSAO samples"
    "--aa|none,msaa3" "unknown AA method"
    "--aa|fxaa,,none" "empty item in --aa"
    "--aa" "--aa without a value")
  list(LENGTH cases n)
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET cases ${i} args)
    string(REPLACE "|" ";" args "${args}") # each case's arguments are '|'-separated
    list(GET cases ${j} what)
    run_tool(${args} --json "${WORK}/x.json")
    expect_exit(2 "${what}")
  endforeach()
  expect_only("bad usage")
endfunction()

function(check_bad_input)
  run_tool(--scene "${WORK}/missing.gltf" --json "${WORK}/x.json" --out "${WORK}/out" --quick)
  expect_exit(1 "unreadable scene")
  if(NOT err MATCHES "missing.gltf")
    message(FATAL_ERROR "the message does not name the scene:\n${err}")
  endif()
  expect_only("unreadable scene")
  file(WRITE "${WORK}/broken.gltf" "{ this is not glTF")
  run_tool(--scene "${WORK}/broken.gltf" --json "${WORK}/x.json" --out "${WORK}/out" --quick)
  expect_exit(1 "malformed scene")
  expect_only("malformed scene" broken.gltf)
  file(REMOVE "${WORK}/broken.gltf")
  # a path below a regular file can be created by nobody, root included
  file(WRITE "${WORK}/file" "")
  run_tool(--quick --no-plot --json "${WORK}/file/x.json")
  expect_exit(1 "--json below a regular file")
  run_tool(--quick --no-plot --out "${WORK}/file/dir")
  expect_exit(1 "--out below a regular file")
  file(WRITE "${WORK}/doc.md" "no markers here\n")
  run_tool(--quick --no-plot --doc "${WORK}/doc.md" --json "${WORK}/x.json")
  expect_exit(1 "--doc without markers")
  file(READ "${WORK}/doc.md" doc)
  if(NOT doc STREQUAL "no markers here\n")
    message(FATAL_ERROR "--doc without markers changed the file")
  endif()
  run_tool(--quick --no-plot --effects bloom --effects-doc "${WORK}/doc.md" --json "${WORK}/x.json")
  expect_exit(1 "--effects-doc without markers")
  file(READ "${WORK}/doc.md" doc)
  if(NOT doc STREQUAL "no markers here\n")
    message(FATAL_ERROR "--effects-doc without markers changed the file")
  endif()
  run_tool(--quick --no-plot --aa none --aa-doc "${WORK}/doc.md" --json "${WORK}/x.json")
  expect_exit(1 "--aa-doc without markers")
  file(READ "${WORK}/doc.md" doc)
  if(NOT doc STREQUAL "no markers here\n")
    message(FATAL_ERROR "--aa-doc without markers changed the file")
  endif()
  expect_only("bad input" file doc.md)
endfunction()

cli_run_check()
