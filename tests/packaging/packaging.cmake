# Packaging, ABI and documentation tests (ctest -L packaging; the documentation ones also -L docs):
#
#   packaging_install                       cmake --install into a scratch prefix (fixture
#                                           thinlight_installed) and checks the layout, SONAMEs,
#                                           .pc prefix and version, no internal library installed
#   packaging_exports_only_public_api       libthinlight*.so export tl_* API names and nothing else
#   packaging_every_declared_function_exported   every TL_API function of the installed headers
#                                           is exported by the library that should hold it
#   packaging_consumer_cmake_shared         tests/packaging/consumer via find_package, shared libraries: the
#                                           codec check, one headless frame, the getting-started PNG
#   packaging_consumer_cmake_static         the same with thinlight::thinlight_static / codec_static
#   packaging_consumer_pkgconfig_shared     the same programs built with a plain compiler command
#                                           line from `pkg-config --cflags --libs thinlight`
#   packaging_consumer_pkgconfig_static     ... and from `pkg-config --cflags --libs thinlight-static`
#                                           (thinlight-codec-static): libthinlight.a, no libthinlight*.so NEEDED
#   packaging_codec_consumer_pulls_no_gl    thinlight::codec / thinlight-codec alone: no libGL,
#                                           OSMesa, GLFW, OIIO or C++ runtime NEEDED, no gl*/OSMesa*
#                                           symbol referenced (executables and libthinlight-codec.so)
#   packaging_config_version_same_major     find_package(thinlight <major>.<minor>) is found,
#                                           <major + 1>.0 is not (nor 0.<minor + 1> while major is 0)
#   packaging_codec_only_c_compiler         a separate configure with THINLIGHT_WITH_RENDERER,
#                                           _IO, _OSMESA, _EGL, _GLFW off and no C++ compiler builds
#                                           thinlight_codec, which needs libm and libc only
#   packaging_renderer_without_optional_deps  THINLIGHT_WITH_IO/_OSMESA/_EGL/_GLFW off: libthinlight
#                                           builds and needs none of their libraries
#   version_header_library_and_project_agree  TL_VERSION_*, tl_version(), project(VERSION)
#   getting_started_writes_png              examples/getting_started.c renders and writes a PNG
#   docs_getting_started_matches_source     the program in docs/getting-started.md is the file
#                                           verbatim and under 60 lines
#   engine_loop_runs_and_writes_png         examples/engine_loop.c: 48 frames of changed options, moved,
#                                           hidden, added and removed objects, dirty GL state, a resize;
#                                           no program built after the first round; a PNG
#   docs_engine_loop_matches_source         docs/getting-started.md shows examples/engine_loop.c verbatim
#   gltf_and_own_objects_both_show          examples/gltf_and_own_objects.c: a glTF written at run time, set
#                                           whole, then the program's own texture, material, box and
#                                           light added; its box (red and blue texels) and the file's
#                                           objects each change pixels when hidden; a PNG
#   docs_gltf_and_own_objects_matches_source  docs/getting-started.md shows it verbatim
#   docs_api_reference                      the thinlight_docs target (doxygen, warnings fail)
#
# Included by tests/CMakeLists.txt it adds the tests; run with `cmake -P` it is the checker, with
# -DCHECK=<case> -DWORK=<scratch dir> and the values passed by tl_add_packaging_test below.

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
  separate_arguments(sanitize UNIX_COMMAND "${SANITIZE_FLAGS}")
  set(warnings -Wall -Wextra -Wpedantic -Werror)
  set(libdir "${PREFIX}/${LIBDIR}")
  # Runtime environment of programs linked against the scratch prefix.
  set(run_env "LD_LIBRARY_PATH=${libdir}" "LSAN_OPTIONS=suppressions=${LSAN_SUPP}:print_suppressions=0")

  # run(<what> <command>...): runs it (in WORK), fails with its output unless it exits 0; sets
  # `out` to its output.
  function(run what)
    execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc
      OUTPUT_VARIABLE o ERROR_VARIABLE e)
    if(NOT rc EQUAL 0)
      list(JOIN ARGN " " cmd)
      message(FATAL_ERROR "${what} failed (${rc}):\n${cmd}\n${o}\n${e}")
    endif()
    set(out "${o}" PARENT_SCOPE)
  endfunction()

  # run_program(<exe> [args...]): runs a consumer program against the scratch prefix.
  function(run_program exe)
    run("${exe}" ${CMAKE_COMMAND} -E env ${run_env} ${exe} ${ARGN})
    get_filename_component(name "${exe}" NAME)
    string(STRIP "${out}" o)
    message(STATUS "${name}: ${o}")
  endfunction()

  # elf_needed(<file> <var>): the DT_NEEDED entries of an ELF file.
  function(elf_needed file var)
    run("readelf -d ${file}" readelf -d "${file}")
    string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[[^]\n]+\\]" lines "${out}")
    set(needed)
    foreach(l IN LISTS lines)
      string(REGEX REPLACE ".*\\[([^]]+)\\]" "\\1" lib "${l}")
      list(APPEND needed "${lib}")
    endforeach()
    set(${var} "${needed}" PARENT_SCOPE)
  endfunction()

  # dynamic_symbols(<file> <undefined|defined> <var>): names in the dynamic symbol table.
  function(dynamic_symbols file which var)
    run("nm -D ${file}" nm -D --${which}-only "${file}")
    string(REGEX MATCHALL "[^\n]+" lines "${out}")
    set(names)
    foreach(l IN LISTS lines)
      string(REGEX REPLACE "^.* ([^ ]+)$" "\\1" n "${l}")
      string(REGEX REPLACE "@.*$" "" n "${n}")
      list(APPEND names "${n}")
    endforeach()
    set(${var} "${names}" PARENT_SCOPE)
  endfunction()

  # expect_no_graphics(<file>): no GL/windowing/image/C++ library NEEDED, no GL symbol referenced.
  function(expect_no_graphics file)
    elf_needed("${file}" needed)
    foreach(lib IN LISTS needed)
      if(lib MATCHES "^lib(GL|EGL|OSMesa|glfw|glapi|OpenImageIO|stdc\\+\\+|c\\+\\+|thinlight\\.so)")
        message(FATAL_ERROR "${file} needs ${lib} (all NEEDED: ${needed})")
      endif()
    endforeach()
    dynamic_symbols("${file}" undefined undefined)
    foreach(sym IN LISTS undefined)
      if(sym MATCHES "^(gl[A-Z]|OSMesa|glfw|glad)")
        message(FATAL_ERROR "${file} references ${sym}")
      endif()
    endforeach()
    get_filename_component(name "${file}" NAME)
    message(STATUS "${name}: NEEDED ${needed}; no GL symbol")
  endfunction()

  # pkg(<var> <args>...): pkg-config against the scratch prefix only.
  function(pkg var)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env "PKG_CONFIG_PATH=${libdir}/pkgconfig"
      ${PKG_CONFIG} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e
      OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "pkg-config ${ARGN} failed:\n${e}")
    endif()
    set(${var} "${o}" PARENT_SCOPE)
  endfunction()

  # configure_consumer(<build dir> <-D...>...): configures and builds tests/packaging/consumer.
  function(configure_consumer dir)
    string(JOIN " " cflags ${warnings} ${sanitize})
    set(cxx_args)
    if(CXX)
      set(cxx_args "-DCMAKE_CXX_COMPILER=${CXX}" "-DCMAKE_CXX_FLAGS=${SANITIZE_FLAGS}")
    endif()
    run("configure tests/packaging/consumer" ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/packaging/consumer" -B "${dir}"
      -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${CC}" ${cxx_args}
      "-DCMAKE_BUILD_TYPE=${CONFIG}" "-DCMAKE_C_FLAGS=${cflags}"
      "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DCONSUMER_EXPECTED_VERSION=${VERSION}"
      -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON ${ARGN})
    run("build tests/packaging/consumer" ${CMAKE_COMMAND} --build "${dir}")
  endfunction()

  # cc(<output> <sources and flags>...): a plain compiler command line.
  function(cc output)
    run("compile ${output}" ${CC} -std=c11 ${warnings} ${sanitize} ${ARGN} -o "${output}")
  endfunction()

  # expect_png(<file>): exists, non-empty, starts with the PNG signature.
  function(expect_png file)
    if(NOT EXISTS "${file}")
      message(FATAL_ERROR "${file} was not written")
    endif()
    file(SIZE "${file}" size)
    file(READ "${file}" head LIMIT 8 HEX)
    if(size EQUAL 0 OR NOT head STREQUAL "89504e470d0a1a0a")
      message(FATAL_ERROR "${file} is not a PNG (${size} bytes, starts with ${head})")
    endif()
    message(STATUS "${file}: PNG, ${size} bytes")
  endfunction()

  # The programs a consumer build made, run against the prefix.
  # docs/getting-started.md shows examples/FILE verbatim: the ```c block after "<!-- examples/FILE -->".
  function(expect_doc_program file)
    file(READ "${SOURCE_DIR}/examples/${file}" program)
    file(READ "${SOURCE_DIR}/docs/getting-started.md" md)
    set(marker "<!-- examples/${file} -->\n```c\n")
    string(FIND "${md}" "${marker}" start)
    if(start EQUAL -1)
      message(FATAL_ERROR "docs/getting-started.md has no '<!-- examples/${file} -->' + ```c block")
    endif()
    string(LENGTH "${marker}" skip)
    math(EXPR start "${start} + ${skip}")
    string(SUBSTRING "${md}" ${start} -1 rest)
    string(FIND "${rest}" "```\n" end)
    string(SUBSTRING "${rest}" 0 ${end} block)
    if(NOT block STREQUAL program)
      file(WRITE "${WORK}/block.c" "${block}")
      execute_process(COMMAND diff -u "${SOURCE_DIR}/examples/${file}" "${WORK}/block.c" OUTPUT_VARIABLE d)
      message(FATAL_ERROR "the program in docs/getting-started.md differs from examples/${file}:\n${d}")
    endif()
    message(STATUS "docs/getting-started.md holds examples/${file} verbatim")
  endfunction()

  function(run_consumer_programs dir)
    run_program("${dir}/codec_only")
    if(WITH_OSMESA)
      run_program("${dir}/render_frame")
      if(WITH_IO)
        file(REMOVE "${WORK}/getting_started.png")
        run_program("${dir}/getting_started" "${WORK}/getting_started.png")
        expect_png("${WORK}/getting_started.png")
      endif()
    endif()
  endfunction()

  if(NOT CHECK STREQUAL "install")
    file(REMOVE_RECURSE "${WORK}")
  endif()
  file(MAKE_DIRECTORY "${WORK}")

  if(CHECK STREQUAL "install")
    file(REMOVE_RECURSE "${PREFIX}")
    run("cmake --install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}")
    # Headers: exactly include/thinlight/*.h.
    file(GLOB src_headers RELATIVE "${SOURCE_DIR}/include/thinlight" "${SOURCE_DIR}/include/thinlight/*.h")
    file(GLOB inst_headers RELATIVE "${PREFIX}/${INCLUDEDIR}/thinlight" "${PREFIX}/${INCLUDEDIR}/thinlight/*")
    list(SORT src_headers)
    list(SORT inst_headers)
    if(NOT src_headers STREQUAL inst_headers)
      message(FATAL_ERROR "installed headers ${inst_headers}, expected ${src_headers}")
    endif()
    # Libraries: shared with VERSION and SOVERSION links, static, nothing internal.
    string(REGEX MATCH "^[0-9]+" major "${VERSION}")
    set(expected libthinlight-codec.a libthinlight-codec.so libthinlight-codec.so.${major}
      libthinlight-codec.so.${VERSION})
    if(WITH_RENDERER)
      list(APPEND expected libthinlight.a libthinlight.so libthinlight.so.${major} libthinlight.so.${VERSION})
    endif()
    file(GLOB libs RELATIVE "${libdir}" "${libdir}/lib*")
    list(SORT libs)
    list(SORT expected)
    if(NOT libs STREQUAL expected)
      message(FATAL_ERROR "libraries in ${libdir}: ${libs}\nexpected: ${expected}")
    endif()
    foreach(lib IN LISTS expected)
      if(lib MATCHES "\\.so$")
        run("readelf -d ${lib}" readelf -d "${libdir}/${lib}")
        if(NOT out MATCHES "\\(SONAME\\)[^\n]*\\[${lib}\\.${major}\\]")
          message(FATAL_ERROR "${lib}: no SONAME ${lib}.${major}:\n${out}")
        endif()
      endif()
    endforeach()
    foreach(f thinlightConfig.cmake thinlightConfigVersion.cmake thinlightTargets.cmake)
      if(NOT EXISTS "${libdir}/cmake/thinlight/${f}")
        message(FATAL_ERROR "missing ${libdir}/cmake/thinlight/${f}")
      endif()
    endforeach()
    # pkg-config: the install prefix, the version, libraries that exist.
    if(PKG_CONFIG)
      set(pcs thinlight-codec thinlight-codec-static)
      if(WITH_RENDERER)
        list(APPEND pcs thinlight thinlight-static)
      endif()
      foreach(pc IN LISTS pcs)
        pkg(prefix --variable=prefix ${pc})
        pkg(version --modversion ${pc})
        pkg(libs --libs ${pc})
        if(NOT prefix STREQUAL PREFIX OR NOT version STREQUAL VERSION)
          message(FATAL_ERROR "${pc}.pc: prefix '${prefix}', version '${version}'; expected '${PREFIX}', '${VERSION}'")
        endif()
        # the shared libraries by -L and -l; the archives by their path (an -l would find the .so)
        string(REGEX REPLACE "-static$" "" base "${pc}")
        if(pc MATCHES "-static$")
          set(expect "(^| )${libdir}/lib${base}\\.a( |$)")
        else()
          set(expect "-L${libdir}( |$)")
        endif()
        if(NOT libs MATCHES "${expect}" OR (pc MATCHES "-static$" AND libs MATCHES "-l${base}( |$)"))
          message(FATAL_ERROR "${pc}.pc: --libs gives '${libs}'")
        endif()
        message(STATUS "${pc}.pc ${version}: ${libs}")
      endforeach()
    endif()

  elseif(CHECK STREQUAL "exports")
    set(libs thinlight-codec)
    if(WITH_RENDERER)
      list(APPEND libs thinlight)
    endif()
    foreach(lib IN LISTS libs)
      dynamic_symbols("${libdir}/lib${lib}.so" defined defined)
      set(api 0)
      foreach(sym IN LISTS defined)
        if(sym MATCHES "^tl_[a-z0-9]" OR sym MATCHES "^_(init|fini|edata|end|_bss_start)$")
          if(sym MATCHES "^tl_")
            math(EXPR api "${api} + 1")
          endif()
        else()
          message(FATAL_ERROR "lib${lib}.so exports '${sym}', which is not thinlight's public API")
        endif()
      endforeach()
      message(STATUS "lib${lib}.so exports ${api} tl_* functions and nothing else")
    endforeach()

  elseif(CHECK STREQUAL "declared")
    # Every TL_API function of every installed header, exported by the library that holds it.
    dynamic_symbols("${libdir}/libthinlight-codec.so" defined codec_syms)
    set(all_syms)
    if(WITH_RENDERER)
      dynamic_symbols("${libdir}/libthinlight.so" defined all_syms)
    endif()
    file(GLOB headers "${PREFIX}/${INCLUDEDIR}/thinlight/*.h")
    set(missing)
    foreach(h IN LISTS headers)
      get_filename_component(name "${h}" NAME)
      file(READ "${h}" text)
      string(REGEX MATCHALL "TL_API[^;(]*[ *](tl_[a-z0-9_]+)[ ]*\\(" decls "${text}")
      foreach(d IN LISTS decls)
        string(REGEX REPLACE ".*[ *](tl_[a-z0-9_]+)[ ]*\\($" "\\1" fn "${d}")
        if(name MATCHES "^(base|version|codec|metrics|file)\\.h$" AND NOT fn IN_LIST codec_syms)
          list(APPEND missing "${fn} (${name}) in libthinlight-codec.so")
        endif()
        if(WITH_RENDERER AND (WITH_IO OR NOT name STREQUAL "io.h") AND NOT fn IN_LIST all_syms)
          list(APPEND missing "${fn} (${name}) in libthinlight.so")
        endif()
      endforeach()
    endforeach()
    if(missing)
      list(JOIN missing "\n  " missing)
      message(FATAL_ERROR "declared but not exported:\n  ${missing}")
    endif()

  elseif(CHECK STREQUAL "cmake_shared")
    configure_consumer("${WORK}/build")
    run_consumer_programs("${WORK}/build")
    elf_needed("${WORK}/build/codec_only" needed)
    if(NOT "libthinlight-codec.so.${VERSION_MAJOR}" IN_LIST needed)
      message(FATAL_ERROR "codec_only does not use libthinlight-codec.so (NEEDED: ${needed})")
    endif()

  elseif(CHECK STREQUAL "cmake_static")
    configure_consumer("${WORK}/build" -DCONSUMER_STATIC=ON)
    run_consumer_programs("${WORK}/build")
    file(GLOB exes "${WORK}/build/codec_only" "${WORK}/build/render_frame" "${WORK}/build/getting_started")
    foreach(exe IN LISTS exes)
      elf_needed("${exe}" needed)
      if(needed MATCHES "libthinlight")
        message(FATAL_ERROR "${exe} is linked statically but needs ${needed}")
      endif()
    endforeach()

  elseif(CHECK STREQUAL "pkgconfig_shared" OR CHECK STREQUAL "pkgconfig_static")
    # The command lines of docs/getting-started.md, "Link with pkg-config", as they are written:
    # `thinlight` and `thinlight-codec` for the shared libraries, `thinlight-static` and
    # `thinlight-codec-static` for the archives (nothing rewritten here).
    set(suffix)
    if(CHECK STREQUAL "pkgconfig_static")
      set(suffix -static)
    endif()
    pkg(codec_cflags --cflags thinlight-codec${suffix})
    pkg(codec_libs --libs thinlight-codec${suffix})
    separate_arguments(codec_cflags UNIX_COMMAND "${codec_cflags}")
    separate_arguments(codec_libs UNIX_COMMAND "${codec_libs}")
    cc("${WORK}/codec_only" ${codec_cflags} "-DEXPECTED_VERSION=\"${VERSION}\""
      "${SOURCE_DIR}/tests/packaging/consumer/codec_only.c" ${codec_libs})
    if(WITH_RENDERER AND WITH_OSMESA)
      pkg(cflags --cflags thinlight${suffix})
      pkg(libs --libs thinlight${suffix})
      message(STATUS "pkg-config --cflags --libs thinlight${suffix}: ${cflags} ${libs}")
      separate_arguments(cflags UNIX_COMMAND "${cflags}")
      separate_arguments(libs UNIX_COMMAND "${libs}")
      cc("${WORK}/render_frame" ${cflags} "${SOURCE_DIR}/tests/packaging/consumer/render_frame.c" ${libs})
      if(WITH_IO)
        cc("${WORK}/getting_started" ${cflags} "${SOURCE_DIR}/examples/getting_started.c" ${libs})
      endif()
    endif()
    run_consumer_programs("${WORK}")
    file(GLOB exes "${WORK}/codec_only" "${WORK}/render_frame" "${WORK}/getting_started")
    foreach(exe IN LISTS exes)
      elf_needed("${exe}" needed)
      if(suffix AND needed MATCHES "libthinlight")
        message(FATAL_ERROR "${exe} is linked statically but needs ${needed}")
      elseif(NOT suffix AND NOT needed MATCHES "libthinlight")
        message(FATAL_ERROR "${exe} is linked with the shared libraries but needs none of them: ${needed}")
      endif()
      get_filename_component(name "${exe}" NAME)
      message(STATUS "${name}: NEEDED ${needed}")
    endforeach()

  elseif(CHECK STREQUAL "codec_no_gl")
    expect_no_graphics("${libdir}/libthinlight-codec.so")
    configure_consumer("${WORK}/shared" -DCONSUMER_RENDER=OFF)
    run_program("${WORK}/shared/codec_only")
    expect_no_graphics("${WORK}/shared/codec_only")
    configure_consumer("${WORK}/static" -DCONSUMER_RENDER=OFF -DCONSUMER_STATIC=ON)
    run_program("${WORK}/static/codec_only")
    expect_no_graphics("${WORK}/static/codec_only")
    if(PKG_CONFIG)
      pkg(cflags --cflags thinlight-codec)
      pkg(libs --libs thinlight-codec)
      separate_arguments(cflags UNIX_COMMAND "${cflags}")
      separate_arguments(libs UNIX_COMMAND "${libs}")
      cc("${WORK}/codec_only_pc" ${cflags} "${SOURCE_DIR}/tests/packaging/consumer/codec_only.c" ${libs})
      run_program("${WORK}/codec_only_pc")
      expect_no_graphics("${WORK}/codec_only_pc")
    endif()

  elseif(CHECK STREQUAL "config_version")
    string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" mm "${VERSION}")
    set(major ${CMAKE_MATCH_1})
    math(EXPR next "${major} + 1")
    math(EXPR next_minor "${CMAKE_MATCH_2} + 1")
    set(refused "${next}.0")
    if(major EQUAL 0) # while the major version is 0 a minor release may break (docs/versioning.md)
      list(APPEND refused "0.${next_minor}")
    endif()
    foreach(request "${mm}" ${refused})
      file(WRITE "${WORK}/${request}/CMakeLists.txt"
        "cmake_minimum_required(VERSION 3.25)\nproject(v LANGUAGES NONE)\n"
        "find_package(thinlight ${request} CONFIG REQUIRED)\n"
        "message(STATUS \"found thinlight \${thinlight_VERSION}\")\n")
      execute_process(COMMAND ${CMAKE_COMMAND} -S "${WORK}/${request}" -B "${WORK}/${request}/build"
        "-DCMAKE_PREFIX_PATH=${PREFIX}" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
        RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
      if(request STREQUAL mm AND NOT rc EQUAL 0)
        message(FATAL_ERROR "find_package(thinlight ${request}) failed:\n${o}\n${e}")
      elseif(NOT request STREQUAL mm AND rc EQUAL 0)
        message(FATAL_ERROR "find_package(thinlight ${request}) accepted ${VERSION}")
      endif()
    endforeach()
    message(STATUS "thinlight ${VERSION}: ${mm} found, ${refused} refused")

  elseif(CHECK STREQUAL "codec_only_c_compiler" OR CHECK STREQUAL "no_optional_deps")
    # A configure of the source tree that must not need what the options turn off. No C++
    # compiler (a path that does not exist) and no pkg-config for the codec alone.
    set(args -DTHINLIGHT_WITH_IO=OFF -DTHINLIGHT_WITH_OSMESA=OFF -DTHINLIGHT_WITH_EGL=OFF -DTHINLIGHT_WITH_GLFW=OFF
      -DTHINLIGHT_BUILD_TESTS=OFF -DTHINLIGHT_BUILD_EXAMPLES=OFF "-DCMAKE_CXX_COMPILER=${WORK}/no-c++")
    if(CHECK STREQUAL "codec_only_c_compiler")
      list(APPEND args -DTHINLIGHT_WITH_RENDERER=OFF "-DPKG_CONFIG_EXECUTABLE=${WORK}/no-pkg-config"
        "-DTHINLIGHT_GLAD_PYTHON=${WORK}/no-python")
      set(target thinlight_codec)
      set(lib libthinlight-codec.so)
    else()
      set(target thinlight)
      set(lib libthinlight.so)
    endif()
    run("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK}/build" -G "${GENERATOR}"
      "-DCMAKE_C_COMPILER=${CC}" -DCMAKE_BUILD_TYPE=Release ${args})
    if(EXISTS "${WORK}/build/CMakeFiles/${CMAKE_VERSION}/CMakeCXXCompiler.cmake")
      message(FATAL_ERROR "configure enabled C++")
    endif()
    run("build ${target}" ${CMAKE_COMMAND} --build "${WORK}/build" --target ${target} --parallel 2)
    file(GLOB_RECURSE built "${WORK}/build/${lib}")
    if(NOT built)
      message(FATAL_ERROR "no ${lib} in ${WORK}/build")
    endif()
    list(GET built 0 built)
    elf_needed("${built}" needed)
    foreach(n IN LISTS needed)
      if(NOT n MATCHES "^(libm|libc|ld-linux[^.]*)\\.so")
        message(FATAL_ERROR "${built} needs ${n} (all: ${needed})")
      endif()
    endforeach()
    message(STATUS "${lib} built with ${args}: NEEDED ${needed}")

  elseif(CHECK STREQUAL "getting_started" OR CHECK STREQUAL "engine_loop")
    # The in-tree build (its own RUNPATH), not the scratch prefix.
    set(png "${WORK}/${CHECK}.png")
    file(REMOVE "${png}")
    run("${CHECK}" ${CMAKE_COMMAND} -E env "LSAN_OPTIONS=suppressions=${LSAN_SUPP}:print_suppressions=0"
      "${PROGRAM}" "${png}")
    expect_png("${png}")

  elseif(CHECK STREQUAL "engine_loop_doc")
    expect_doc_program(engine_loop.c)

  elseif(CHECK STREQUAL "gltf_and_own_objects")
    # A glTF written now (make_gltf_scenes: a floor and a box under the file's lights), then the
    # program adds its own texture, material, box and light; it fails unless both show.
    run("make_gltf_scenes" "${MAKE_SCENES}" "${WORK}")
    set(png "${WORK}/gltf_and_own_objects.png")
    run("gltf_and_own_objects" ${CMAKE_COMMAND} -E env "LSAN_OPTIONS=suppressions=${LSAN_SUPP}:print_suppressions=0"
      "${PROGRAM}" "${WORK}/lights.gltf" "${png}")
    message(STATUS "${out}")
    expect_png("${png}")

  elseif(CHECK STREQUAL "gltf_and_own_objects_doc")
    expect_doc_program(gltf_and_own_objects.c)

  elseif(CHECK STREQUAL "getting_started_doc")
    file(STRINGS "${SOURCE_DIR}/examples/getting_started.c" lines)
    list(LENGTH lines n)
    if(n GREATER_EQUAL 60)
      message(FATAL_ERROR "examples/getting_started.c has ${n} lines; the guide promises fewer than 60")
    endif()
    expect_doc_program(getting_started.c)

  else()
    message(FATAL_ERROR "unknown CHECK '${CHECK}'")
  endif()
  return()
endif()

# ---- adding the tests -----------------------------------------------------------------------------
set(TL_PACKAGING_SCRIPT ${CMAKE_CURRENT_LIST_FILE})
set(TL_PACKAGING_WORK ${CMAKE_CURRENT_BINARY_DIR}/packaging)
set(TL_PACKAGING_PREFIX ${TL_PACKAGING_WORK}/prefix)
set(TL_PACKAGING_CXX "")
if(THINLIGHT_HAVE_CXX)
  set(TL_PACKAGING_CXX ${CMAKE_CXX_COMPILER})
endif()
set(TL_PACKAGING_PKG_CONFIG "")
if(PKG_CONFIG_EXECUTABLE)
  set(TL_PACKAGING_PKG_CONFIG ${PKG_CONFIG_EXECUTABLE})
endif()
list(JOIN THINLIGHT_SANITIZE_FLAGS " " _tl_sanitize_flags)

# tl_add_packaging_test(<name> <check> [LABELS l...] [FIXTURE] [TIMEOUT s] [ARGS -D...])
function(tl_add_packaging_test name check)
  cmake_parse_arguments(P "FIXTURE;FULL" "TIMEOUT" "LABELS;ARGS" ${ARGN})
  if(NOT P_LABELS)
    set(P_LABELS packaging)
  endif()
  if(P_FULL)
    list(APPEND P_LABELS full)
  endif()
  if(NOT P_TIMEOUT)
    set(P_TIMEOUT 300)
  endif()
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND}
      -DCHECK=${check} -DWORK=${TL_PACKAGING_WORK}/${name}
      -DPREFIX=${TL_PACKAGING_PREFIX} -DBUILD_DIR=${PROJECT_BINARY_DIR}
      -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DCONFIG=$<CONFIG>
      -DVERSION=${PROJECT_VERSION} -DVERSION_MAJOR=${PROJECT_VERSION_MAJOR}
      -DLIBDIR=${CMAKE_INSTALL_LIBDIR} -DINCLUDEDIR=${CMAKE_INSTALL_INCLUDEDIR}
      -DCC=${CMAKE_C_COMPILER} -DCXX=${TL_PACKAGING_CXX} -DGENERATOR=${CMAKE_GENERATOR}
      -DPKG_CONFIG=${TL_PACKAGING_PKG_CONFIG} "-DSANITIZE_FLAGS=${_tl_sanitize_flags}"
      -DLSAN_SUPP=${PROJECT_SOURCE_DIR}/tests/common/lsan.supp
      -DWITH_RENDERER=${THINLIGHT_WITH_RENDERER} -DWITH_IO=${THINLIGHT_WITH_IO}
      -DWITH_OSMESA=${THINLIGHT_WITH_OSMESA} -DWITH_GLFW=${THINLIGHT_WITH_GLFW}
      ${P_ARGS}
      -P ${TL_PACKAGING_SCRIPT})
  set_tests_properties(${name} PROPERTIES LABELS "${P_LABELS}" TIMEOUT ${P_TIMEOUT})
  if(P_FIXTURE)
    set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED thinlight_installed)
  endif()
endfunction()

if(THINLIGHT_INSTALL)
  tl_add_packaging_test(packaging_install install)
  set_tests_properties(packaging_install PROPERTIES FIXTURES_SETUP thinlight_installed)
  tl_add_packaging_test(packaging_exports_only_public_api exports FIXTURE)
  tl_add_packaging_test(packaging_every_declared_function_exported declared FIXTURE)
  tl_add_packaging_test(packaging_consumer_cmake_shared cmake_shared FIXTURE)
  tl_add_packaging_test(packaging_codec_consumer_pulls_no_gl codec_no_gl FIXTURE)
  tl_add_packaging_test(packaging_config_version_same_major config_version FIXTURE)
  if(THINLIGHT_WITH_RENDERER)
    tl_add_packaging_test(packaging_consumer_cmake_static cmake_static FIXTURE FULL)
  endif()
  if(TL_PACKAGING_PKG_CONFIG)
    tl_add_packaging_test(packaging_consumer_pkgconfig_shared pkgconfig_shared FIXTURE FULL)
    tl_add_packaging_test(packaging_consumer_pkgconfig_static pkgconfig_static FIXTURE)
  endif()
endif()

# Separate configures of this source tree: the codec with a C compiler alone, and libthinlight
# with every optional dependency off.
tl_add_packaging_test(packaging_codec_only_c_compiler codec_only_c_compiler TIMEOUT 300)
if(THINLIGHT_WITH_RENDERER)
  tl_add_packaging_test(packaging_renderer_without_optional_deps no_optional_deps FULL TIMEOUT 900)
endif()

# The version: header macros, tl_version(), tl_version_string() and project(VERSION) agree.
add_executable(tl_version_check ${CMAKE_CURRENT_LIST_DIR}/consumer/codec_only.c)
target_compile_definitions(tl_version_check PRIVATE "EXPECTED_VERSION=\"${PROJECT_VERSION}\"")
target_link_libraries(tl_version_check PRIVATE thinlight::codec thinlight_warnings)
add_test(NAME version_header_library_and_project_agree COMMAND tl_version_check)
set_tests_properties(version_header_library_and_project_agree PROPERTIES LABELS packaging)

# docs/getting-started.md: its program is built and run, and is what the page shows.
if(TARGET thinlight_io AND THINLIGHT_WITH_OSMESA)
  add_executable(tl_getting_started ${PROJECT_SOURCE_DIR}/examples/getting_started.c)
  target_link_libraries(tl_getting_started PRIVATE thinlight::thinlight thinlight_warnings)
  tl_add_packaging_test(getting_started_writes_png getting_started LABELS "packaging;docs;gl"
    ARGS -DPROGRAM=$<TARGET_FILE:tl_getting_started>)
endif()
tl_add_packaging_test(docs_getting_started_matches_source getting_started_doc LABELS "packaging;docs")
# examples/engine_loop.c: an engine's frame loop (options, scene updates, GL state, a resize, an
# application pass) runs, builds no program after its first round of options, and is on the page.
if(TARGET thinlight_io AND THINLIGHT_WITH_OSMESA)
  add_executable(tl_engine_loop ${PROJECT_SOURCE_DIR}/examples/engine_loop.c)
  target_link_libraries(tl_engine_loop PRIVATE thinlight::thinlight thinlight_warnings m)
  tl_add_packaging_test(engine_loop_runs_and_writes_png engine_loop LABELS "packaging;docs;gl"
    ARGS -DPROGRAM=$<TARGET_FILE:tl_engine_loop>)
endif()
tl_add_packaging_test(docs_engine_loop_matches_source engine_loop_doc LABELS "packaging;docs")
# examples/gltf_and_own_objects.c: a loaded glTF and the application's own texture, material, box and
# light in one renderer; both show in the frame, and the program is on the page.
if(TARGET thinlight_io AND THINLIGHT_WITH_OSMESA AND TARGET make_gltf_scenes)
  add_executable(tl_gltf_and_own_objects ${PROJECT_SOURCE_DIR}/examples/gltf_and_own_objects.c)
  target_link_libraries(tl_gltf_and_own_objects PRIVATE thinlight::thinlight thinlight_warnings m)
  tl_add_packaging_test(gltf_and_own_objects_both_show gltf_and_own_objects LABELS "packaging;docs;gl;gltf"
    ARGS -DPROGRAM=$<TARGET_FILE:tl_gltf_and_own_objects> -DMAKE_SCENES=$<TARGET_FILE:make_gltf_scenes>)
endif()
tl_add_packaging_test(docs_gltf_and_own_objects_matches_source gltf_and_own_objects_doc LABELS "packaging;docs")

if(TARGET thinlight_docs)
  add_test(NAME docs_api_reference
    COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --config $<CONFIG> --target thinlight_docs)
  set_tests_properties(docs_api_reference PROPERTIES LABELS "packaging;docs" TIMEOUT 300
    RESOURCE_LOCK thinlight_build_tree)
endif()
