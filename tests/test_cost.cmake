# motiongp_tests_cost(LIST_VAR SECONDS NAME [SECONDS NAME ...]): gives the named tests (discovered
# by doctest_discover_tests into LIST_VAR) a COST, their measured time under the sanitizers (the
# slowest build; clang's, as CI compiles it).
# ctest starts a parallel run's tests in decreasing COST, which it otherwise learns from earlier
# runs; a fresh build folder (CI, a new clone) has none, so the longest test could start last and
# run alone on one core while the other idles. The names are the suite's longest tests
# (docs/architecture.md, "Build"); a name that no longer exists is ignored. Like
# motiongp_discovered_tests_environment, this adds a ctest include file that runs after the
# discovered tests' own.
function(motiongp_tests_cost list_var)
  set(file "${CMAKE_CURRENT_BINARY_DIR}/${list_var}_cost.cmake")
  file(WRITE "${file}" "")
  set(pairs ${ARGN})
  list(LENGTH pairs count)
  math(EXPR last "${count} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET pairs ${i} seconds)
    list(GET pairs ${j} name)
    # list(FIND), not if(IN_LIST): ctest reads this file without the policy that enables IN_LIST.
    file(APPEND "${file}"
      "list(FIND ${list_var} [==[${name}]==] index)\n"
      "if(NOT index EQUAL -1)\n"
      "  set_tests_properties([==[${name}]==] PROPERTIES COST ${seconds})\n"
      "endif()\n")
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${file}")
endfunction()
