# Installing gfec: the compiler, the runtime library and its headers, and a CMake package so
# that another project's find_package(gfec) finds gfec::gfec, gfec::runtime and
# gfec_add_chart(). Included from the top-level CMakeLists.txt once every target exists.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GFEC_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/gfec" CACHE STRING
    "Where the CMake package files of gfec are installed")

# The names other projects use, in gfec's own build as after installing.
if(NOT TARGET gfec::gfec)
  add_executable(gfec::gfec ALIAS gfec)
endif()
set_target_properties(afp_runtime PROPERTIES EXPORT_NAME runtime)

# Two export sets: the compiler (a host tool, needed by every user, also in a cross build) and
# the plan runtime (a host library that needs Threads), so that a project using only the
# compiler never has to find Threads (gfecConfig.cmake.in loads the runtime as a component).
install(TARGETS gfec EXPORT gfecTargets RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(TARGETS afp_runtime EXPORT gfecRuntimeTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
  INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/runtime/include/afp" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")

install(EXPORT gfecTargets NAMESPACE gfec:: DESTINATION "${GFEC_INSTALL_CMAKEDIR}")
install(EXPORT gfecRuntimeTargets NAMESPACE gfec:: DESTINATION "${GFEC_INSTALL_CMAKEDIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/gfecConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/gfecConfig.cmake" INSTALL_DESTINATION "${GFEC_INSTALL_CMAKEDIR}")
# ARCH_INDEPENDENT: gfec is a host tool. Without it the version file compares pointer sizes and
# rejects every 32-bit consumer -- which is what a Cortex-M cross build is.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/gfecConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES
  "${PROJECT_BINARY_DIR}/gfecConfig.cmake"
  "${PROJECT_BINARY_DIR}/gfecConfigVersion.cmake"
  "${CMAKE_CURRENT_LIST_DIR}/GfecChart.cmake"
  DESTINATION "${GFEC_INSTALL_CMAKEDIR}")

# The manual page (written by hand in roff: docs/man/) and bash completion, where man and
# bash-completion look (bash-completion loads a file named for the command on the first <Tab>).
# carbot-sim's page and completion stay in the source: the simulator is not installed, and a page
# for a command the user does not have is a dead end.
install(FILES "${PROJECT_SOURCE_DIR}/docs/man/gfec.1" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
install(FILES "${PROJECT_SOURCE_DIR}/tools/completion/gfec.bash"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/bash-completion/completions" RENAME gfec)
# The guides, which gfec --help and the man page cite: share/doc/gfec/ (CMAKE_INSTALL_DOCDIR).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION "${CMAKE_INSTALL_DOCDIR}"
  FILES_MATCHING PATTERN "*.md" PATTERN "*.svg" PATTERN "*.png" PATTERN "*.json" PATTERN "*.yml"
  PATTERN "man" EXCLUDE)
