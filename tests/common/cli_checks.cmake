# Helpers for the command-line contract checkers (tests/tools, tests/input), `cmake -P` scripts
# run by the tests that tl_add_cli_test adds (-DTOOL, -DCHECK, -DWORK); they include this file,
# which starts each check with an empty scratch directory WORK. A checker defines one function
# check_<name> per check and ends with cli_run_check().
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Runs ${TOOL} with ARGN; sets rc, out and err in the caller.
function(run_tool)
  execute_process(COMMAND ${TOOL} ${ARGN} RESULT_VARIABLE r OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(rc "${r}" PARENT_SCOPE)
  set(out "${o}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

# Fails unless the run exited with `expected`; for the exit codes in ONE_LINE_EXITS (default 1
# and 2) stderr must be one line saying why.
function(expect_exit expected what)
  if(NOT rc STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: exit status '${rc}', expected ${expected}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(NOT DEFINED ONE_LINE_EXITS)
    set(ONE_LINE_EXITS 1 2)
  endif()
  if(expected IN_LIST ONE_LINE_EXITS)
    string(STRIP "${err}" e)
    if(e STREQUAL "" OR e MATCHES "\n")
      message(FATAL_ERROR "${what}: expected one line on stderr, got:\n${err}")
    endif()
  endif()
endfunction()

# Fails when WORK holds anything but the names in ARGN (no partial output left behind).
function(expect_only what)
  file(GLOB left RELATIVE "${WORK}" "${WORK}/*")
  foreach(keep IN LISTS ARGN)
    list(REMOVE_ITEM left "${keep}")
  endforeach()
  if(left)
    message(FATAL_ERROR "${what}: left files behind: ${left}")
  endif()
endfunction()

# Runs check_${CHECK}, the function of the check the test named.
function(cli_run_check)
  if(NOT COMMAND check_${CHECK})
    message(FATAL_ERROR "unknown CHECK '${CHECK}'")
  endif()
  cmake_language(CALL check_${CHECK})
endfunction()
