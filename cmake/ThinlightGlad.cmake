# Generates the GL loader with glad2 at build time (never committed).
#
#   thinlight_glad_generate(
#     OUT_DIR      <dir>                 # where include/ and src/ are written (build tree)
#     API          <api>                 # e.g. gl:core=4.5
#     EXTENSIONS   <ext>...              # e.g. GL_KHR_debug GL_ARB_timer_query
#     SOURCES_VAR  <var>                 # receives the generated .c file (and headers)
#     INCLUDE_DIR_VAR <var>)             # receives <dir>/include
#
# The generator is glad 2 (Debian package python3-glad), run as `python -m glad ... c --mx`: one
# GladGLContext struct per context, loaded through a caller-supplied getprocaddress. Debian installs
# glad only for the system interpreter, while a python3 earlier on PATH (pyenv, a venv) usually
# cannot import it, so the interpreter is chosen by trying candidates (see
# thinlight_find_glad_python). Override with -DTHINLIGHT_GLAD_PYTHON=/path/to/python.

include_guard(GLOBAL)

# Sets <out_var> to the first interpreter that can `import glad` with glad 2.x; fails configure
# otherwise with a message naming the package.
function(thinlight_find_glad_python out_var)
  set(probe "import glad, glad.generator.c; print(glad.__version__)")
  if(THINLIGHT_GLAD_PYTHON)
    execute_process(COMMAND "${THINLIGHT_GLAD_PYTHON}" -c "${probe}"
      RESULT_VARIABLE rc OUTPUT_VARIABLE ver ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(rc EQUAL 0 AND ver MATCHES "^2\\.")
      set(${out_var} "${THINLIGHT_GLAD_PYTHON}" PARENT_SCOPE)
      return()
    endif()
    if(THINLIGHT_GLAD_PYTHON_PROBED)
      # A cached choice that stopped working: probe again below.
      unset(THINLIGHT_GLAD_PYTHON CACHE)
    else()
      message(FATAL_ERROR "THINLIGHT_GLAD_PYTHON=${THINLIGHT_GLAD_PYTHON} cannot import glad 2.x "
        "(got '${ver}'). Install glad 2 for it (Debian/Ubuntu: apt-get install python3-glad) or "
        "unset THINLIGHT_GLAD_PYTHON.")
    endif()
  endif()

  set(candidates)
  if(Python3_EXECUTABLE)
    list(APPEND candidates "${Python3_EXECUTABLE}")
  endif()
  find_program(tl__glad_path_python NAMES python3 python NO_CACHE)
  if(tl__glad_path_python)
    list(APPEND candidates "${tl__glad_path_python}")
  endif()
  list(APPEND candidates /usr/bin/python3 /usr/local/bin/python3 /bin/python3)
  list(REMOVE_DUPLICATES candidates)

  set(tried "")
  set(seen "")
  foreach(py IN LISTS candidates)
    if(NOT EXISTS "${py}")
      continue()
    endif()
    file(REAL_PATH "${py}" real)
    if(real IN_LIST seen)
      continue() # /bin/python3 is /usr/bin/python3 on merged-/usr systems
    endif()
    list(APPEND seen "${real}")
    execute_process(COMMAND "${py}" -c "${probe}"
      RESULT_VARIABLE rc OUTPUT_VARIABLE ver ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(rc EQUAL 0 AND ver MATCHES "^2\\.")
      message(STATUS "glad ${ver}: ${py}")
      set(THINLIGHT_GLAD_PYTHON "${py}" CACHE FILEPATH "Python interpreter that can import glad 2.x")
      set(THINLIGHT_GLAD_PYTHON_PROBED ON CACHE INTERNAL "")
      set(${out_var} "${py}" PARENT_SCOPE)
      return()
    endif()
    if(rc EQUAL 0)
      string(APPEND tried "\n  ${py}: glad ${ver} (need 2.x)")
    else()
      string(APPEND tried "\n  ${py}: cannot import glad")
    endif()
  endforeach()
  message(FATAL_ERROR "No Python interpreter can import the glad 2 loader generator. Tried:${tried}\n"
    "Install it (Debian/Ubuntu: apt-get install python3-glad, which installs it for /usr/bin/python3)"
    " or point -DTHINLIGHT_GLAD_PYTHON=/path/to/python at an interpreter that has glad 2.x.")
endfunction()

function(thinlight_glad_generate)
  cmake_parse_arguments(G "" "OUT_DIR;API;SOURCES_VAR;INCLUDE_DIR_VAR" "EXTENSIONS" ${ARGN})
  if(NOT G_OUT_DIR OR NOT G_API OR NOT G_SOURCES_VAR)
    message(FATAL_ERROR "thinlight_glad_generate: OUT_DIR, API and SOURCES_VAR are required")
  endif()
  thinlight_find_glad_python(python)

  set(args --quiet --reproducible --api "${G_API}")
  if(G_EXTENSIONS)
    list(JOIN G_EXTENSIONS "," exts)
    list(APPEND args --extensions "${exts}")
  endif()
  list(APPEND args --out-path "${G_OUT_DIR}" c --mx)

  # The command line lives in a file the rule depends on, so changing the API or the extension
  # list regenerates the loader with every generator (Makefiles do not track command changes).
  string(REPLACE ";" " " args_text "${args}")
  file(CONFIGURE OUTPUT "${G_OUT_DIR}.args" CONTENT "${python} -m glad ${args_text}\n")

  set(outputs
    "${G_OUT_DIR}/src/gl.c"
    "${G_OUT_DIR}/include/glad/gl.h"
    "${G_OUT_DIR}/include/KHR/khrplatform.h")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND "${CMAKE_COMMAND}" -E rm -rf "${G_OUT_DIR}"
    COMMAND "${python}" -m glad ${args}
    DEPENDS "${G_OUT_DIR}.args"
    COMMENT "Generating the GL loader (glad ${G_API})"
    VERBATIM)
  set(${G_SOURCES_VAR} ${outputs} PARENT_SCOPE)
  if(G_INCLUDE_DIR_VAR)
    set(${G_INCLUDE_DIR_VAR} "${G_OUT_DIR}/include" PARENT_SCOPE)
  endif()
endfunction()
