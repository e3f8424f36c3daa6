# Every C example in the public headers (@code ... @endcode) and in README.md and docs/*.md
# (```c blocks) compiles. A block with a main() is a whole program; any other block is a fragment:
# its #include lines go to the top and the rest becomes the body of a function that declares the
# names the fragments share (scene, rgba, my_loader, my_logger) and returns an int.
#
# Included by tests/CMakeLists.txt it adds the test; run with `cmake -P` it is the checker:
#   -DSOURCE_DIR=<source tree> -DCC=<C compiler> -DWORK=<scratch dir>

if(CMAKE_SCRIPT_MODE_FILE)
  file(MAKE_DIRECTORY "${WORK}")
  file(GLOB headers "${SOURCE_DIR}/include/thinlight/*.h")
  file(GLOB docs "${SOURCE_DIR}/docs/*.md")
  set(prelude [=[
  #include <stdint.h>
  #include <stdio.h>
  #include <stdlib.h>
  #include <string.h>
  #include <thinlight/base.h>
  #include <thinlight/codec.h>
  #include <thinlight/context.h>
  #include <thinlight/io.h>
  #include <thinlight/metrics.h>
  #include <thinlight/renderer.h>
  #include <thinlight/scene.h>
  #include <thinlight/version.h>
  static tl_gl_function my_loader(void *user, const char *name) { (void)user; (void)name; return NULL; }
static void my_log(void *user, tl_log_level level, const char *message)
{
    (void)user;
    if (level == TL_LOG_ERROR) fprintf(stderr, "%s\n", message);
}
static const tl_logger my_logger = {my_log, NULL};
static tl_scene *scene;
static uint8_t *rgba;
  ]=])
  set(count 0)
  set(failed "")

  # CMake lists split on ';' and balance brackets: code is encoded while it travels in a list.
  function(encode out text)
    string(REPLACE ";" "<:SEMI:>" text "${text}")
    string(REPLACE "[" "<:LB:>" text "${text}")
    string(REPLACE "]" "<:RB:>" text "${text}")
    set(${out} "${text}" PARENT_SCOPE)
  endfunction()

  function(check_snippet origin text)
    string(REPLACE "<:SEMI:>" ";" text "${text}")
    string(REPLACE "<:LB:>" "[" text "${text}")
    string(REPLACE "<:RB:>" "]" text "${text}")
    math(EXPR n "${count} + 1")
    set(count ${n} PARENT_SCOPE)
    set(path "${WORK}/example_${n}.c")
    if(text MATCHES "[^a-z_]main[ ]*\\(")
      file(WRITE "${path}" "${text}\n")
    else()
      string(REGEX MATCHALL "#include[^\n]*" includes "${text}")
      string(REGEX REPLACE "#include[^\n]*" "" body "${text}")
      list(JOIN includes "\n" includes)
      file(WRITE "${path}" "${prelude}${includes}\nint tl_doc_example(void);\nint tl_doc_example(void)\n{\n${body}\n"
           "return 0;\n}\n")
    endif()
    execute_process(COMMAND "${CC}" -std=c11 -Wall -Wextra -Werror -Wno-unused-variable -Wno-unused-parameter
                            -Wno-unused-function -Wno-unused-but-set-variable -fsyntax-only
                            -I "${SOURCE_DIR}/include" "${path}"
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0)
      message(STATUS "${origin} (${path}):\n${out}")
      set(failed "${failed} ${origin}" PARENT_SCOPE)
    endif()
  endfunction()

  foreach(h IN LISTS headers)
    file(READ "${h}" text)
    encode(text "${text}")
    get_filename_component(name "${h}" NAME)
    string(REGEX MATCHALL "@code[^@]*@endcode" blocks "${text}")
    foreach(b IN LISTS blocks)
      string(REGEX REPLACE "^@code|@endcode$" "" b "${b}")
      string(REGEX REPLACE "\n[ ]*\\*[ ]?" "\n" b "${b}") # the comment's leading " * "
      check_snippet("include/thinlight/${name}" "${b}")
    endforeach()
  endforeach()
  foreach(md "${SOURCE_DIR}/README.md" ${docs})
    file(READ "${md}" text)
    encode(text "${text}")
    get_filename_component(name "${md}" NAME)
    string(REGEX MATCHALL "```c\n[^`]*```" blocks "${text}")
    foreach(b IN LISTS blocks)
      string(REGEX REPLACE "^```c\n|```$" "" b "${b}")
      check_snippet("${name}" "${b}")
    endforeach()
  endforeach()
  if(count LESS 4)
    message(FATAL_ERROR "only ${count} code examples found; the extraction is broken")
  endif()
  if(failed)
    message(FATAL_ERROR "code examples that do not compile:${failed}")
  endif()
  message(STATUS "${count} code examples compile")
  return()
endif()

add_test(NAME docs_code_examples_compile
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DCC=${CMAKE_C_COMPILER}
          -DWORK=${CMAKE_CURRENT_BINARY_DIR}/docs_examples -P ${CMAKE_CURRENT_LIST_FILE})
set_tests_properties(docs_code_examples_compile PROPERTIES LABELS "docs" TIMEOUT 120)
