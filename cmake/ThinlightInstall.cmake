# Install rules: libraries, headers, the CMake package (thinlightConfig.cmake, version file,
# exported targets) and the pkg-config files. Layout under the prefix (GNUInstallDirs):
#
#   include/thinlight/*.h
#   lib/libthinlight-codec.so.<version>, .so.<major>, .so, libthinlight-codec.a
#   lib/libthinlight.so.<version>, .so.<major>, .so, libthinlight.a       (THINLIGHT_WITH_RENDERER)
#   lib/cmake/thinlight/thinlightConfig.cmake, thinlightConfigVersion.cmake,
#       thinlightTargets*.cmake, thinlightStaticTargets*.cmake
#   lib/pkgconfig/thinlight-codec.pc, thinlight.pc, thinlight-codec-static.pc, thinlight-static.pc
#
# Components: Runtime (shared libraries), Development (the rest).

include_guard(GLOBAL)
include(CMakePackageConfigHelpers)

set(THINLIGHT_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/thinlight" CACHE STRING
  "Where thinlightConfig.cmake is installed, relative to the prefix")
set(THINLIGHT_INSTALL_PKGCONFIGDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig" CACHE STRING
  "Where the .pc files are installed, relative to the prefix")

# Export set "thinlight": the shared libraries, the codec archive and thinlight::io. Export set
# "thinlightStatic": libthinlight.a, whose consumers must also find libthinlight's dependencies;
# thinlightConfig.cmake loads it only when they are found (or requires them for COMPONENTS static).
set(_tl_main_targets thinlight_codec thinlight_codec_static)
if(TARGET thinlight)
  list(APPEND _tl_main_targets thinlight)
endif()
if(TARGET thinlight_io)
  list(APPEND _tl_main_targets thinlight_io)
endif()

install(TARGETS ${_tl_main_targets}
  EXPORT thinlightTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Runtime NAMELINK_COMPONENT Development
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
install(EXPORT thinlightTargets
  NAMESPACE thinlight::
  FILE thinlightTargets.cmake
  DESTINATION ${THINLIGHT_INSTALL_CMAKEDIR}
  COMPONENT Development)

if(TARGET thinlight_static)
  install(TARGETS thinlight_static
    EXPORT thinlightStaticTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development)
  install(EXPORT thinlightStaticTargets
    NAMESPACE thinlight::
    FILE thinlightStaticTargets.cmake
    DESTINATION ${THINLIGHT_INSTALL_CMAKEDIR}
    COMPONENT Development)
endif()

# Every public header (the codec's users get the renderer's headers too: one include tree).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/thinlight
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT Development
  FILES_MATCHING PATTERN "*.h")

# ---- CMake package ------------------------------------------------------------------------------
set(THINLIGHT_CONFIG_HAS_RENDERER ${THINLIGHT_WITH_RENDERER})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/thinlightConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/thinlightConfig.cmake
  INSTALL_DESTINATION ${THINLIGHT_INSTALL_CMAKEDIR}
  NO_SET_AND_CHECK_MACRO)
# Same major version = same ABI (README "Using thinlight as a library").
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/thinlightConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/package/thinlightConfig.cmake
  ${PROJECT_BINARY_DIR}/package/thinlightConfigVersion.cmake
  DESTINATION ${THINLIGHT_INSTALL_CMAKEDIR}
  COMPONENT Development)

# ---- pkg-config ---------------------------------------------------------------------------------
# The prefix is written at install time, so `cmake --install build --prefix P` gets P (not the
# configure-time CMAKE_INSTALL_PREFIX). Everything else is filled in now; the template keeps the
# literal @CMAKE_INSTALL_PREFIX@ for the install step.
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(THINLIGHT_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(THINLIGHT_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
set(THINLIGHT_PC_PREFIX "@CMAKE_INSTALL_PREFIX@")
set(THINLIGHT_PC_REQUIRES_PRIVATE "")
foreach(pair IN LISTS THINLIGHT_PKG_MODULES)
  string(REGEX REPLACE "^[^=]*=" "" module "${pair}")
  list(APPEND THINLIGHT_PC_REQUIRES_PRIVATE ${module})
endforeach()
list(JOIN THINLIGHT_PC_REQUIRES_PRIVATE " " THINLIGHT_PC_REQUIRES_PRIVATE)
set(THINLIGHT_PC_EXTRA_LIBS_PRIVATE "")
if("glfw3" IN_LIST THINLIGHT_CMAKE_PACKAGES)
  set(THINLIGHT_PC_EXTRA_LIBS_PRIVATE " -lglfw") # GLFW found by its CMake package, no .pc
endif()

# The -static files name the archive by its path: -lthinlight would pick the shared library that
# lies beside it, so `pkg-config --libs thinlight-static` links libthinlight.a and what it needs.
set(THINLIGHT_PC_STATIC_CODEC "${CMAKE_STATIC_LIBRARY_PREFIX}thinlight-codec${CMAKE_STATIC_LIBRARY_SUFFIX}")
set(THINLIGHT_PC_STATIC_THINLIGHT "${CMAKE_STATIC_LIBRARY_PREFIX}thinlight${CMAKE_STATIC_LIBRARY_SUFFIX}")
set(_tl_pc_files thinlight-codec thinlight-codec-static)
if(TARGET thinlight)
  list(APPEND _tl_pc_files thinlight)
endif()
if(TARGET thinlight_static)
  list(APPEND _tl_pc_files thinlight-static)
endif()
if(IS_ABSOLUTE "${THINLIGHT_INSTALL_PKGCONFIGDIR}")
  set(_tl_pc_destination "${THINLIGHT_INSTALL_PKGCONFIGDIR}")
else()
  set(_tl_pc_destination "\${CMAKE_INSTALL_PREFIX}/${THINLIGHT_INSTALL_PKGCONFIGDIR}")
endif()
foreach(pc IN LISTS _tl_pc_files)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/package/${pc}.pc.in @ONLY)
  install(CODE "
    configure_file(\"${PROJECT_BINARY_DIR}/package/${pc}.pc.in\"
                   \"${PROJECT_BINARY_DIR}/package/install/${pc}.pc\" @ONLY)
    file(INSTALL \"${PROJECT_BINARY_DIR}/package/install/${pc}.pc\"
         DESTINATION \"${_tl_pc_destination}\")"
    COMPONENT Development)
endforeach()
