# Every output of the tools is whole or absent (docs/tools.md, docs/outputs.md), checked
# with the fault injector (common/fault_inject.h) preloaded into the tool:
#   full disk   the k-th write fails (ENOSPC, and every later one), for every k until the run
#               succeeds; the last fsync and the last close fail (EIO; every fsync and close of
#               every format: tests/input/file_outputs.c). Each failing run exits 1 with one line naming the output and the reason;
#               each output is then its old content or the whole new file, the failing one old,
#               and nothing else is in the folder. The run past the last k writes every output
#               whole.
#   not_regular an output path that is a FIFO, a device node, a directory, a symbolic link,
#               `-` or /dev/null is refused with exit 1 and one line, and left as it was.
# The checker of the tests tests/tools/CMakeLists.txt adds (tl_add_cli_test), run as
#   cmake -DTOOL=<tool> -DCHECK=<check> -DWORK=<scratch dir> -DINJECT=<libtl_fault_inject.so>
#         -P outputs_faults.cmake

cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)
file(REAL_PATH "${WORK}" WORK) # the injector matches the real paths of open files

set(OLD_TEXT "OLD CONTENT\n")
set(DOC_TEXT "# doc\n\n<!-- codec-report:begin -->\nold tables\n<!-- codec-report:end -->\n")
# A sanitized tool checks that its runtime comes first; the injector is preloaded before it.
set(asan_options "verify_asan_link_order=0")
if(DEFINED ENV{ASAN_OPTIONS} AND NOT "$ENV{ASAN_OPTIONS}" STREQUAL "")
  set(asan_options "$ENV{ASAN_OPTIONS}:verify_asan_link_order=0")
endif()

# Runs TOOL with ARGN (@OUT@ replaced by `dir`), the injector armed on `dir` for `call` at `k`
# (0: count only); sets rc and err in the caller and, with `report`, the calls counted there.
function(faulted_run dir call k report)
  list(TRANSFORM ARGN REPLACE "@OUT@" "${dir}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "LD_PRELOAD=${INJECT}" "TL_FAULT_DIR=${dir}"
      "TL_FAULT_CALL=${call}" "TL_FAULT_AT=${k}" "TL_FAULT_REPORT=${report}" "ASAN_OPTIONS=${asan_options}"
      ${TOOL} ${ARGN}
    RESULT_VARIABLE r OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 120)
  set(rc "${r}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

# The calls of each kind one clean run made (summed over its processes: gnuplot too).
function(read_counts report)
  foreach(kind write fsync close)
    set(n_${kind} 0)
  endforeach()
  file(STRINGS "${report}" lines)
  foreach(l IN LISTS lines)
    if(l MATCHES "write ([0-9]+) fsync ([0-9]+) close ([0-9]+)")
      math(EXPR n_write "${n_write} + ${CMAKE_MATCH_1}")
      math(EXPR n_fsync "${n_fsync} + ${CMAKE_MATCH_2}")
      math(EXPR n_close "${n_close} + ${CMAKE_MATCH_3}")
    endif()
  endforeach()
  foreach(kind write fsync close)
    set(n_${kind} ${n_${kind}} PARENT_SCOPE)
  endforeach()
endfunction()

# The bytes of a file as hex, with dates ("YYYY:MM:DD HH:MM:SS": EXR's capDate) blanked.
function(masked_hex file var)
  file(READ "${file}" hex HEX)
  set(d "3[0-9]")
  string(REGEX REPLACE "${d}${d}${d}${d}3a${d}${d}3a${d}${d}20${d}${d}3a${d}${d}3a${d}${d}" "DATE" hex "${hex}")
  set(${var} "${hex}" PARENT_SCOPE)
endfunction()

# Whether `file` is the whole new output: the clean run's bytes, or for an output named by
# VOLATILE (timings inside: JSON, plots) a whole file of its type.
function(whole_output file ref name var)
  set(ok 0)
  if(NOT EXISTS "${file}")
  elseif(DEFINED VOLATILE AND name MATCHES "${VOLATILE}")
    file(READ "${file}" hex HEX)
    if(name MATCHES "\\.png$")
      if(hex MATCHES "^89504e470d0a1a0a.*0000000049454e44ae426082$")
        set(ok 1)
      endif()
    elseif(name MATCHES "\\.json$")
      file(READ "${file}" text)
      string(JSON type ERROR_VARIABLE jerr TYPE "${text}")
      if(type STREQUAL "OBJECT" AND NOT jerr)
        set(ok 1)
      endif()
    elseif(hex MATCHES "0a$") # text: ends with its last newline
      set(ok 1)
    endif()
  else()
    masked_hex("${file}" a)
    masked_hex("${ref}" b)
    if(a STREQUAL b)
      set(ok 1)
    endif()
  endif()
  set(${var} ${ok} PARENT_SCOPE)
endfunction()

# Old content under every output name, as an earlier run would have left; the doc a real doc.
function(prepare_old dir)
  file(REMOVE_RECURSE "${dir}")
  file(MAKE_DIRECTORY "${dir}")
  foreach(name IN LISTS outputs)
    if(name MATCHES "\\.md$")
      file(WRITE "${dir}/${name}" "${DOC_TEXT}")
    else()
      file(WRITE "${dir}/${name}" "${OLD_TEXT}${name}\n")
    endif()
  endforeach()
endfunction()

function(is_old file name var)
  file(READ "${file}" text)
  if(name MATCHES "\\.md$")
    set(want "${DOC_TEXT}")
  else()
    set(want "${OLD_TEXT}${name}\n")
  endif()
  if(text STREQUAL want)
    set(${var} 1 PARENT_SCOPE)
  else()
    set(${var} 0 PARENT_SCOPE)
  endif()
endfunction()

# After one run over old outputs: expectations of a failing (want_fail) or succeeding run.
function(check_run dir what want_fail reason)
  file(GLOB_RECURSE now RELATIVE "${dir}" "${dir}/*")
  set(extra ${now})
  list(REMOVE_ITEM extra ${outputs})
  if(extra)
    message(FATAL_ERROR "${what}: left beside the outputs: ${extra}\n${err}")
  endif()
  set(failing "")
  if(want_fail)
    if(NOT rc EQUAL 1)
      message(FATAL_ERROR "${what}: exit status '${rc}', expected 1\n${err}")
    endif()
    string(REGEX MATCHALL "[^\n]*${reason}[^\n]*" lines "${err}")
    list(LENGTH lines n)
    if(NOT n EQUAL 1 OR NOT lines MATCHES "${dir}/([^:]+): ")
      message(FATAL_ERROR "${what}: expected one line naming an output and '${reason}', got:\n${err}")
    endif()
    set(failing "${CMAKE_MATCH_1}")
  elseif(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: exit status '${rc}', expected 0\n${err}")
  endif()
  foreach(name IN LISTS outputs)
    is_old("${dir}/${name}" "${name}" old)
    whole_output("${dir}/${name}" "${WORK}/clean/${name}" "${name}" whole)
    if(name STREQUAL failing AND NOT old)
      message(FATAL_ERROR "${what}: ${name}, whose write failed, lost its old content\n${err}")
    endif()
    if(NOT old AND NOT whole)
      file(SIZE "${dir}/${name}" size)
      message(FATAL_ERROR "${what}: ${name} is neither its old content nor the whole new file (${size} bytes)\n${err}")
    endif()
    if(NOT want_fail AND (old OR NOT whole))
      message(FATAL_ERROR "${what}: ${name} was not written\n${err}")
    endif()
  endforeach()
endfunction()

# The full-disk loops over one command line (ARGN, outputs under @OUT@).
function(full_disk)
  set(clean "${WORK}/clean")
  file(MAKE_DIRECTORY "${clean}")
  faulted_run("${clean}" write 0 "${WORK}/clean.counts" ${ARGN})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the clean run failed (${rc}):\n${err}")
  endif()
  file(GLOB_RECURSE outputs RELATIVE "${clean}" "${clean}/*")
  read_counts("${WORK}/clean.counts")
  list(LENGTH outputs n_outputs)
  if(n_write EQUAL 0)
    message(FATAL_ERROR "the injector counted no write in ${clean}: is it preloaded?")
  endif()
  set(out "${WORK}/out")
  set(runs 0)
  foreach(call write fsync close)
    set(ks ${n_${call}})
    if(call STREQUAL "write")
      math(EXPR past "${n_write} + 1")
      set(ks RANGE 1 ${past})
    endif()
    foreach(k ${ks})
      prepare_old("${out}")
      faulted_run("${out}" ${call} ${k} "" ${ARGN})
      set(fail 1)
      if(k GREATER n_${call})
        set(fail 0)
      endif()
      set(reason "No space left on device")
      if(NOT call STREQUAL "write")
        set(reason "${call} failed: Input/output error")
      endif()
      check_run("${out}" "${call} failing at k=${k} of ${n_${call}}" ${fail} "${reason}")
      math(EXPR runs "${runs} + 1")
    endforeach()
  endforeach()
  message(STATUS "${n_outputs} outputs (${outputs}); ${n_write} writes, ${n_fsync} fsyncs, ${n_close} closes: "
    "${runs} runs, each failing one kept every output old or whole and left nothing else")
endfunction()

# ---- full disk ----------------------------------------------------------------------------------

set(RENDER_ARGS default --size 32x32 --lights 8)

function(check_render_png)
  full_disk(${RENDER_ARGS} -o @OUT@/out.png)
endfunction()

function(check_render_exr_dump_targets)
  full_disk(${RENDER_ARGS} -o @OUT@/out.exr --dump-targets @OUT@/targets)
endfunction()

function(check_bench_json_images)
  set(VOLATILE "\\.json$")
  full_disk(--size 32x18 --lights 8 --modes thin-lpp --strategies volumes --light-formats rgba16f --frames 1
    --warmup 0 --json @OUT@/bench.json --out @OUT@/images --no-plot)
endfunction()

function(check_codec_report_json_plot_doc)
  set(VOLATILE "\\.(json|md|dat|gp|png)$")
  # the doc must exist with its markers before the run, as it does in docs/
  set(outputs doc.md)
  prepare_old("${WORK}/clean")
  full_disk(--quick --json @OUT@/codec.json --out @OUT@/plot --doc @OUT@/doc.md)
endfunction()

# ---- outputs that are not regular files ---------------------------------------------------------

# What a path is now: type, inode, device numbers, size ("absent" when nothing is there).
function(node_id path var)
  execute_process(COMMAND stat -c "%F %i %t:%T %s" "${path}" OUTPUT_VARIABLE o ERROR_QUIET RESULT_VARIABLE r)
  if(NOT r EQUAL 0)
    set(o "absent")
  endif()
  set(${var} "${o}" PARENT_SCOPE)
endfunction()

# The lines of stderr that say something went wrong (not the context line, progress or "wrote").
function(error_lines var)
  string(REPLACE ";" "," text "${err}") # one list element a line
  string(REGEX MATCHALL "[^\n]+" all "${text}")
  set(kept)
  foreach(l IN LISTS all)
    if(NOT l MATCHES "^[a-z-]+: context |^wrote |^\\[[# ]")
      list(APPEND kept "${l}")
    endif()
  endforeach()
  set(${var} "${kept}" PARENT_SCOPE)
endfunction()

# TOOL with ARGN (@PATH@ replaced by `path`, run inside `dir`) must refuse `path` with exit 1
# and one line, and leave it as it was; `dir` must hold nothing new. Sets `refused`.
function(expect_refused dir path what)
  set(node "${path}")
  if(path STREQUAL "-")
    set(node "${dir}/-") # what a writer that took `-` for a file name would make
  endif()
  node_id("${node}" before)
  file(GLOB_RECURSE had RELATIVE "${dir}" LIST_DIRECTORIES true "${dir}/*")
  list(TRANSFORM ARGN REPLACE "@PATH@" "${path}")
  execute_process(COMMAND ${TOOL} ${ARGN} WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err
    TIMEOUT 60) # (a tool that opens a FIFO to read it waits for a writer)
  node_id("${node}" after)
  file(GLOB_RECURSE has RELATIVE "${dir}" LIST_DIRECTORIES true "${dir}/*")
  error_lines(lines)
  list(LENGTH lines n)
  set(ok 1)
  if(NOT rc EQUAL 1 OR NOT n EQUAL 1 OR NOT before STREQUAL after OR NOT had STREQUAL has)
    set(ok 0)
    message(SEND_ERROR "${what}: exit '${rc}' (want 1), ${n} error lines (want 1), '${path}' was "
      "'${before}' and is '${after}', folder held '${had}' and holds '${has}':\n${err}")
  else()
    message(STATUS "${what}: ${lines}")
  endif()
  set(refused ${ok} PARENT_SCOPE)
endfunction()

# One output option, ARGN naming the output @PATH@, given a FIFO, a directory, a symbolic link
# (to a regular file, which must keep its content), a dangling link, a device node (where this
# process may make one), `-`, and last, once all those were refused, /dev/null.
function(not_regular ext)
  set(all 1)
  foreach(kind fifo directory link dangling device dash)
    set(dir "${WORK}/${kind}")
    file(REMOVE_RECURSE "${dir}")
    file(MAKE_DIRECTORY "${dir}")
    set(path "${dir}/out${ext}")
    if(kind STREQUAL "fifo")
      execute_process(COMMAND mkfifo "${path}" RESULT_VARIABLE r)
    elseif(kind STREQUAL "directory")
      file(MAKE_DIRECTORY "${path}")
      set(r 0)
    elseif(kind STREQUAL "link")
      file(WRITE "${dir}/target${ext}" "${OLD_TEXT}")
      file(CREATE_LINK "target${ext}" "${path}" RESULT r SYMBOLIC)
    elseif(kind STREQUAL "dangling")
      file(CREATE_LINK "nowhere${ext}" "${path}" RESULT r SYMBOLIC)
    elseif(kind STREQUAL "device")
      execute_process(COMMAND mknod "${path}" c 1 3 RESULT_VARIABLE r ERROR_QUIET)
    else()
      set(path "-")
      set(r 0)
    endif()
    if(NOT r EQUAL 0)
      message(STATUS "${kind}: cannot be made here (${r}); skipped")
      continue()
    endif()
    expect_refused("${dir}" "${path}" "${kind} as the output" ${ARGN})
    if(kind STREQUAL "link")
      file(READ "${dir}/target${ext}" text)
      if(NOT text STREQUAL OLD_TEXT)
        message(SEND_ERROR "the link's target was written through")
        set(refused 0)
      endif()
    endif()
    if(NOT refused)
      set(all 0)
    endif()
  endforeach()
  # A writer that replaced the nodes above would replace /dev/null too, run as root.
  if(NOT all)
    message(FATAL_ERROR "not trying /dev/null: the tool replaced what is not a regular file")
  endif()
  expect_refused("${WORK}" /dev/null "/dev/null as the output" ${ARGN})
  node_id(/dev/null now)
  if(NOT now MATCHES "^character special file .* 1:3 ")
    message(FATAL_ERROR "/dev/null is now '${now}'")
  endif()
endfunction()

function(check_render_not_regular)
  not_regular(.png ${RENDER_ARGS} -o @PATH@)
  # a dump target that is a FIFO: refused when its turn comes, after the frame
  set(dir "${WORK}/dump")
  file(MAKE_DIRECTORY "${dir}/targets")
  execute_process(COMMAND mkfifo "${dir}/targets/depth.exr")
  expect_refused("${dir}" "${dir}/targets/depth.exr" "a FIFO among the dumped targets" ${RENDER_ARGS} --stats
    --dump-targets "${dir}/targets")
endfunction()

set(BENCH_ARGS --size 32x18 --lights 8 --modes thin-lpp --strategies volumes --light-formats rgba16f --frames 1
  --warmup 0 --no-plot)

function(check_bench_not_regular)
  not_regular(.json ${BENCH_ARGS} --json @PATH@)
  not_regular(.md ${BENCH_ARGS} --doc @PATH@)
endfunction()

function(check_codec_report_not_regular)
  not_regular(.json --quick --no-plot --json @PATH@)
  not_regular(.md --quick --no-plot --doc @PATH@)
endfunction()

cli_run_check()
