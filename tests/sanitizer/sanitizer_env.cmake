# Test environment for the MOTIONGP_SANITIZE=ON build (docs/testing.md, "Sanitizers"), so that a
# plain `ctest --test-dir build-asan` runs with the right sanitizer options. Included by
# tests/CMakeLists.txt; the lists are empty when the option is off.
#   MOTIONGP_SANITIZER_ENV     every test: leaks detected, UB fatal with a stack trace, and the
#                              runtime's __tls_get_addr interceptor off (see below).
#   MOTIONGP_SANITIZER_GL_ENV  the `gl` tests: the same plus LeakSanitizer suppressions for leaks
#                              inside Mesa/EGL/llvmpipe only (tests/sanitizer/lsan_gl.supp).
set(MOTIONGP_SANITIZER_ENV "")
set(MOTIONGP_SANITIZER_GL_ENV "")
# intercept_tls_get_addr=0: the sanitizer runtimes up to LLVM 16 and GCC 13 guess that a dynamic TLS
# block whose address is 16 bytes past a 4 KiB boundary carries a pre-2.25 glibc header, and read
# its start and size from the 16 bytes before it. Since glibc 2.25 no such header exists: when
# a block of Mesa's dynamic TLS (llvmpipe's threads) lands there by chance, LeakSanitizer's tracer
# scans a garbage range at exit and dies ("Tracer caught signal 11"), failing a test that passed.
# Without the interceptor nothing is lost to leak checking: the dynamic linker allocates those
# blocks, and LeakSanitizer counts what the linker allocated as reachable and scans it
# (use_ld_allocations, on by default) (docs/testing.md, "Sanitizers").
if(MOTIONGP_SANITIZE)
  set(MOTIONGP_SANITIZER_ENV
    "ASAN_OPTIONS=intercept_tls_get_addr=0:detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  set(MOTIONGP_SANITIZER_GL_ENV ${MOTIONGP_SANITIZER_ENV}
    "LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/tests/sanitizer/lsan_gl.supp:print_suppressions=0")
endif()

# motiongp_discovered_tests_environment(LIST_VAR ENV...): sets ENVIRONMENT (the whole list) on every
# test that doctest_discover_tests named in LIST_VAR (its TEST_LIST, `<target>_TESTS` by default).
# Those tests only exist at ctest time, and doctest_discover_tests' PROPERTIES flattens lists (an
# ENVIRONMENT of several entries cannot pass through it), so this adds a ctest include file that
# runs after the discovered tests' own. Call it after doctest_discover_tests in the same directory.
function(motiongp_discovered_tests_environment list_var)
  set(env "${ARGN}")
  set(file "${CMAKE_CURRENT_BINARY_DIR}/${list_var}_environment.cmake")
  file(WRITE "${file}"
    "if(NOT \"\${${list_var}}\" STREQUAL \"\")\n"
    "  set_tests_properties(\${${list_var}} PROPERTIES ENVIRONMENT [==[${env}]==])\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${file}")
endfunction()
