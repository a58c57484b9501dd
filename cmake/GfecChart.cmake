# gfec_add_chart(): compile a chart with gfec as part of a CMake build.
#
#   gfec_add_chart(<target> <chart>
#                  [OUTPUT <file>]            # default: <binary dir>/<chart name>.c (.cpp for a .plan)
#                  [EMIT c|cpp|json|dot|svg]   # default: cpp for *.plan, else c
#                  [CHART <name>]              # when the file declares several charts
#                  [INCLUDE_DIRECTORIES <dir>...]  # -I: where imports are looked for
#                  [OPTIONS <gfec flag>...])   # e.g. -Werror -Wconflict
#
# For c and cpp, <target> is a static library holding the engine; it publishes the folder of the
# generated header (#include "<name>.h" / "<name>.hpp"), and a plan's library links gfec::runtime.
# Link your robot library (the interface's functions) and your main program against it.
# For json, dot and svg, <target> is a custom target (built by `all`) that makes the file.
#
# gfec writes a make dependency file (-MD) naming every file the chart imports, passed to
# add_custom_command(DEPFILE): editing an imported .iface or .toolbox recompiles the chart.
# Needs CMake 3.20 (DEPFILE with every generator).
include_guard(GLOBAL)

cmake_policy(PUSH)
cmake_policy(VERSION 3.20)
# DEPFILE paths relative to the binary dir and rewritten for Ninja (policy recorded with the
# function, so callers with older policy settings get it too).
if(POLICY CMP0116)
  cmake_policy(SET CMP0116 NEW)
endif()

# _gfec_compiler(<var> <caller>): sets <var> to the gfec to run: the installed package's
# gfec::gfec, or the gfec target of gfec's own build (where gfec::gfec is an alias, and a
# command must name the real target). <caller> names the function in the error without one.
function(_gfec_compiler var caller)
  if(TARGET gfec::gfec)
    set(compiler gfec::gfec)
    get_target_property(aliased gfec::gfec ALIASED_TARGET)
    if(aliased)
      set(compiler ${aliased})
    endif()
  elseif(TARGET gfec)
    set(compiler gfec)
  else()
    message(FATAL_ERROR "${caller}: no gfec compiler; call find_package(gfec) first")
  endif()
  set(${var} ${compiler} PARENT_SCOPE)
endfunction()

function(gfec_add_chart target chart)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "" "OUTPUT;EMIT;CHART" "INCLUDE_DIRECTORIES;OPTIONS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gfec_add_chart(${target}): unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()

  _gfec_compiler(compiler "gfec_add_chart(${target})")

  get_filename_component(chart_path "${chart}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(chart_name "${chart}" NAME_WE)
  get_filename_component(chart_ext "${chart}" LAST_EXT)
  set(emit "${ARG_EMIT}")
  if(NOT emit)
    if(chart_ext STREQUAL ".plan")
      set(emit cpp)
    else()
      set(emit c)
    endif()
  endif()
  set(ext_c .c)
  set(ext_cpp .cpp)
  set(ext_json .json)
  set(ext_dot .dot)
  set(ext_svg .svg)
  if(NOT DEFINED ext_${emit})
    message(FATAL_ERROR "gfec_add_chart(${target}): EMIT must be c, cpp, json, dot or svg, not '${emit}'")
  endif()

  set(output "${ARG_OUTPUT}")
  if(NOT output)
    set(output "${CMAKE_CURRENT_BINARY_DIR}/${chart_name}${ext_${emit}}")
  endif()
  get_filename_component(output "${output}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  get_filename_component(output_dir "${output}" DIRECTORY)
  get_filename_component(output_we "${output}" NAME_WE)
  set(outputs "${output}")
  if(emit STREQUAL "c")
    list(APPEND outputs "${output_dir}/${output_we}.h")
  elseif(emit STREQUAL "cpp")
    list(APPEND outputs "${output_dir}/${output_we}.hpp")
  endif()

  set(flags --emit=${emit})
  if(ARG_CHART)
    list(APPEND flags --chart ${ARG_CHART})
  endif()
  foreach(dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    file(RELATIVE_PATH dir "${CMAKE_CURRENT_BINARY_DIR}" "${dir}")
    if(dir STREQUAL "")
      set(dir .)
    endif()
    list(APPEND flags -I "${dir}")
  endforeach()

  set(depfile "${output}.d")
  # gfec runs in the binary folder with paths relative to it, so the #line directives and the
  # dependency file hold no absolute path: the generated files are the same in every checkout
  # and build folder (reproducible builds, shareable caches).
  file(RELATIVE_PATH rel_chart "${CMAKE_CURRENT_BINARY_DIR}" "${chart_path}")
  file(RELATIVE_PATH rel_output "${CMAKE_CURRENT_BINARY_DIR}" "${output}")
  file(RELATIVE_PATH rel_depfile "${CMAKE_CURRENT_BINARY_DIR}" "${depfile}")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${compiler} ${flags} ${ARG_OPTIONS} -MD -MF "${rel_depfile}" -o "${rel_output}" "${rel_chart}"
    MAIN_DEPENDENCY "${chart_path}"
    DEPENDS ${compiler}
    DEPFILE "${depfile}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}"
    COMMENT "gfec: compiling ${chart} (${emit})"
    VERBATIM)

  if(emit STREQUAL "c" OR emit STREQUAL "cpp")
    add_library(${target} STATIC ${outputs})
    target_include_directories(${target} PUBLIC "${output_dir}")
    if(emit STREQUAL "cpp")
      if(TARGET gfec::runtime)
        target_link_libraries(${target} PUBLIC gfec::runtime)
      endif()
      target_compile_features(${target} PUBLIC cxx_std_17)
    endif()
  else()
    add_custom_target(${target} ALL DEPENDS ${outputs})
  endif()
  set_property(TARGET ${target} PROPERTY GFEC_OUTPUTS ${outputs})
endfunction()

# gfec_add_chart_tests(): register scenario test files with CTest (docs/testing-charts.md).
#
#   gfec_add_chart_tests(FILES <file.test>...
#                        [PREFIX <name>]                 # test names: <prefix><file name>; default gfec_test.
#                        [INCLUDE_DIRECTORIES <dir>...]  # -I: where imports are looked for
#                        [OPTIONS <gfec test flag>...])  # e.g. --reference-only, -j 4
#
# Each file becomes one CTest test running `gfec test <file>`: it passes when every test in the
# file passes on the reference interpreter and on the generated C engine (built with the C
# compiler in $CC, else `cc`). Call enable_testing() (or include(CTest)) first.
function(gfec_add_chart_tests)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "PREFIX" "FILES;INCLUDE_DIRECTORIES;OPTIONS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gfec_add_chart_tests: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_FILES)
    message(FATAL_ERROR "gfec_add_chart_tests: no FILES given")
  endif()
  _gfec_compiler(compiler gfec_add_chart_tests)
  set(prefix "gfec_test.")
  if(DEFINED ARG_PREFIX)
    set(prefix "${ARG_PREFIX}")
  endif()
  set(flags "")
  foreach(dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND flags -I "${dir}")
  endforeach()
  foreach(file IN LISTS ARG_FILES)
    get_filename_component(path "${file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${file}" NAME_WE)
    add_test(NAME "${prefix}${name}"
             COMMAND ${compiler} test ${flags} ${ARG_OPTIONS} "${path}"
             WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  endforeach()
endfunction()

cmake_policy(POP)
