# Run after each build of a tl_add_test executable (cmake -P, with -DEXE=<executable>
# -DOUT=<file>): writes the executable's case names, one a line ("name" or "name full" for the full
# tier), from `EXE --list` into OUT, which the executable's ctest include file reads (tl_add_test in
# tests/CMakeLists.txt).
# Listing is not the test: no leak report of the GL stack loaded with the executable.
set(ENV{ASAN_OPTIONS} "detect_leaks=0")
execute_process(COMMAND ${EXE} --list RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} --list failed (${rc}):\n${err}")
endif()
string(REGEX MATCHALL "[^\n]+" names "${out}")
if(NOT names)
  message(FATAL_ERROR "${EXE} --list printed no test case")
endif()
foreach(n IN LISTS names)
  if(NOT n MATCHES "^[A-Za-z_][A-Za-z0-9_]*( full)?$")
    message(FATAL_ERROR "${EXE} --list: '${n}' is not a test case name")
  endif()
endforeach()
list(JOIN names "\n" text)
file(CONFIGURE OUTPUT "${OUT}" CONTENT "${text}\n" @ONLY)
