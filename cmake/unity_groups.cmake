# Unity builds in named groups. The sources of a group compile as one translation unit, so the
# headers they include are parsed once per group and the templates they share (Boost.Multiprecision's
# operators in every precision, Eigen, nlohmann-json, the core's formulas) are instantiated and
# optimised once per group instead of once per file. Measured on the 2-core machine (GCC 12, -O2):
# claims_section2, 3_4, 5, 6_7 and 8_9 take 96 s one by one and 48 s as one unit.
#
# Groups are chosen by what their files share, and kept to about 30 s each: a touched file rebuilds
# its whole group, and the slowest group is the tail of a parallel build. `scripts/build-profile`
# shows each group's time. -DSIMPSON_UNITY_BUILD=OFF compiles every file on its own (same results).
option(SIMPSON_UNITY_BUILD "Compile each target's sources in unity groups (see cmake/unity_groups.cmake)" ON)
# How big a unit is. "groups": each named group is one unit, ALONE files compile on their own; what
# a developer wants, since a touched file rebuilds only its group. "targets": all of a target's
# sources are one unit (a file with compile options of its own still compiles alone, as CMake does
# for any unity build); what a build from scratch wants, since each template is then instantiated and
# compiled once per target instead of once per group. Measured on the 2-core machine on 2026-11-27:
# the experiments' seven groups took 338 s of CPU with GCC at -O2 and 148 s in clang's sanitizer
# build at -O0, and 148 s and 68 s as one unit; the whole Release build 1057 s of CPU, and 610 s.
# The Makefile configures "targets" for a new build directory (`make build` from a fresh clone, CI);
# a directory configured earlier keeps what it has.
set(SIMPSON_UNITY_GROUPING "groups" CACHE STRING "groups: one unit per named group; targets: one unit per target")
set_property(CACHE SIMPSON_UNITY_GROUPING PROPERTY STRINGS groups targets)
if(NOT SIMPSON_UNITY_GROUPING MATCHES "^(groups|targets)$")
  message(FATAL_ERROR "SIMPSON_UNITY_GROUPING is '${SIMPSON_UNITY_GROUPING}': groups or targets")
endif()

# simpson_grouped_sources(<target> GROUP <name> <source>... [GROUP <name> <source>...]... [ALONE <source>...] [SPLIT ...])
# Adds the sources to <target>, each GROUP compiled as one unit; ALONE sources compile on their own
# (a file that would dominate its group, or one with compile options of its own). With "targets",
# the target is one unit, or two where SPLIT starts the second: a target whose one unit would be the
# build's critical path (the experiments: 259 s alone on one core while `make verify` had nothing
# else left to compile).
function(simpson_grouped_sources target)
  set(group "")
  set(sources "")
  set(unit "all")
  foreach(arg IN LISTS ARGN)
    if(arg STREQUAL "GROUP")
      set(group "expect-name")
    elseif(arg STREQUAL "ALONE")
      set(group "")
    elseif(arg STREQUAL "SPLIT")
      set(unit "second")
    elseif(group STREQUAL "expect-name")
      set(group "${arg}")
    else()
      list(APPEND sources "${arg}")
      if(SIMPSON_UNITY_BUILD AND SIMPSON_UNITY_GROUPING STREQUAL "targets")
        set_source_files_properties("${arg}" PROPERTIES UNITY_GROUP "${unit}")
      elseif(SIMPSON_UNITY_BUILD AND NOT group STREQUAL "")
        set_source_files_properties("${arg}" PROPERTIES UNITY_GROUP "${group}")
      endif()
    endif()
  endforeach()
  target_sources(${target} PRIVATE ${sources})
  if(SIMPSON_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  endif()
endfunction()
