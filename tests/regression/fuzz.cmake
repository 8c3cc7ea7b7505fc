# Fuzz smoke run (docs/architecture.md, "Fuzzing" under the tests): the libFuzzer harnesses of
# tests/fuzz/ are built with clang as a project of their own (ExternalProject,
# build-dir/fuzz) and each runs 2000 executions from the seed corpus, after
# replaying the past findings (tests/fuzz/regressions/). Needs clang and the
# libFuzzer runtime (Debian: clang, libclang-rt-14-dev); without them the
# test is not defined and configure says so. The sanitized build leaves it
# out (the harnesses are sanitized already).
if(COULOMB_SANITIZE)
  return()
endif()
find_program(COULOMB_CLANGXX clang++)
find_program(COULOMB_CLANG clang)
file(GLOB COULOMB_LIBFUZZER /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a)
if(NOT COULOMB_CLANGXX OR NOT COULOMB_CLANG OR NOT COULOMB_LIBFUZZER)
  message(STATUS "Fuzz smoke test left out: clang or libFuzzer (libclang-rt-14-dev) is missing")
  return()
endif()
include(ExternalProject)
set(COULOMB_FUZZ_BUILD ${PROJECT_BINARY_DIR}/fuzz)
ExternalProject_Add(coulomb_fuzz
  SOURCE_DIR ${PROJECT_SOURCE_DIR}/tests/fuzz
  BINARY_DIR ${COULOMB_FUZZ_BUILD}
  CMAKE_ARGS -DCMAKE_CXX_COMPILER=${COULOMB_CLANGXX} -DCMAKE_C_COMPILER=${COULOMB_CLANG} -DCMAKE_BUILD_TYPE=Release
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON)
add_test(NAME Fuzz.smoke
         COMMAND bash ${PROJECT_SOURCE_DIR}/tests/fuzz/run_fuzz.sh --build ${COULOMB_FUZZ_BUILD} --runs 2000)
# The run_fuzz.sh corpus grows in the build folder from run to run; a test
# of its own so that a finding is a failing test with the harness named.
set_tests_properties(Fuzz.smoke PROPERTIES TIMEOUT 600 PROCESSORS 1 LABELS "regression;fuzz")
