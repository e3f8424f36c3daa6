# thinlight-codec-report's command-line contract on bad input (docs/tools.md): bad usage
# exits 2, an output that cannot be written 1 with a message naming it, and a --doc file without
# markers is left unchanged.
#
# The checker of the tests tests/input/CMakeLists.txt adds (tl_add_cli_test), run as
#   cmake -DTOOL=<thinlight-codec-report> -DCHECK=<bad_usage|unwritable_out> -DWORK=<scratch dir> -P codec_report_bad_input.cmake

cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)

function(check_bad_usage)
  run_tool(--no-plot --bogus)
  expect_exit(2 "unknown flag")
  run_tool(--no-plot --json)
  expect_exit(2 "--json without a value")
  run_tool(--quick)
  expect_exit(2 "no --out and no --no-plot")
  run_tool(--help)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "usage:")
    message(FATAL_ERROR "--help: exit '${rc}', stdout:\n${out}")
  endif()
endfunction()

function(check_unwritable_out)
  # A directory below a regular file can be created by nobody, root included.
  file(WRITE "${WORK}/file" "")
  run_tool(--quick --no-plot --out "${WORK}/file/dir")
  expect_exit(1 "--out below a regular file")
  if(NOT err MATCHES "file/dir")
    message(FATAL_ERROR "the message does not name the directory:\n${err}")
  endif()
  run_tool(--quick --no-plot --json "${WORK}/file/report.json")
  expect_exit(1 "--json below a regular file")
  file(WRITE "${WORK}/doc.md" "no markers here\n")
  run_tool(--quick --no-plot --doc "${WORK}/doc.md")
  expect_exit(1 "--doc without markers")
  file(READ "${WORK}/doc.md" doc)
  if(NOT doc STREQUAL "no markers here\n")
    message(FATAL_ERROR "--doc without markers changed the file")
  endif()
endfunction()

cli_run_check()
