# The Debian package of gfec, built by CPack from the install rules of GfecInstall.cmake:
#   cpack -G DEB --config build/CPackConfig.cmake      -> gfec_<version>_amd64.deb
# It holds what cmake --install installs, under /usr: the compiler, the plan runtime and its
# headers, the CMake package, the manual page, the guides and the bash completion
# (docs/build-integration.md "The Debian package"; tests/cli/deb_package.sh builds and uses it).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gfec)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# gfec_<version>_<arch>.deb, Debian's own naming.
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(GFEC_PACKAGE_MAINTAINER "gfec maintainers <maintainers@users.noreply.h-seed-2e3a376a.example>"
    CACHE STRING "The Maintainer field of the Debian package")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${GFEC_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "chart compiler for robot engines (sfc, fsm, plan to C and C++)")
# The extended description, in lines under 80 columns as Debian asks (CPack indents them).
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "gfec compiles sequential function charts, state machines and action flow plans"
  "into C99 engines and C++17 plan wiring for robots and microcontrollers, with"
  "gcc's flags and diagnostics. The package holds the compiler, the plan runtime"
  "library and headers, the CMake package (find_package(gfec), gfec_add_chart()),"
  "the manual page, the guides and bash completion.")
# The libraries gfec links dynamically (libc, libstdc++, libfmt ...) are found by dpkg-shlibdeps
# (Debian package dpkg-dev) when it is there; without it, the ones every such build needs.
find_program(GFEC_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(GFEC_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
else()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "libc6, libstdc++6, libgcc-s1")
  message(STATUS "No dpkg-shlibdeps (dpkg-dev): the .deb's Depends will lack libfmt")
endif()
# gfec test builds the C engine with the host's C compiler (--reference-only needs none);
# the runtime and gfec_add_chart() are for C++ and CMake builds; --emit=svg runs Graphviz's dot.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gcc | c-compiler")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "g++, cmake, graphviz, bash-completion")
# A smaller package; the build tree keeps the debug information.
set(CPACK_STRIP_FILES ON)
include(CPack)
