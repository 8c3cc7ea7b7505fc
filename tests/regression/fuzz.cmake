# Fuzz smoke run (docs/architecture.md, "Fuzzing" under the tests): the libFuzzer harnesses of
# tests/fuzz/ are built with clang as a project of their own (ExternalProject,
# build-dir/fuzz) and each runs 2000 executions from the seed corpus, after
# replaying the past findings (tests/fuzz/regressions/); fuzz_gmsh replays only (below). Needs clang and the
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
         COMMAND bash ${PROJECT_SOURCE_DIR}/tests/fuzz/run_fuzz.sh --build ${COULOMB_FUZZ_BUILD} --runs 2000 deck exodus)
# The run_fuzz.sh corpus grows in the build folder from run to run; a test
# of its own so that a finding is a failing test with the harness named.
set_tests_properties(Fuzz.smoke PROPERTIES TIMEOUT 600 PROCESSORS 1 LABELS "regression;fuzz")
# fuzz_gmsh only replays (--runs 0: the past findings of tests/fuzz/regressions/gmsh/
# and the corpus, seeded with gmsh's own files of every format), no mutation:
# gmsh's own .msh reader (Debian's libgmsh 4.8.4, which readGmsh calls) crashes
# on damaged files within about a thousand mutations, e.g. a 54-byte file with an
# unterminated physical name (tests/fuzz/gmsh_crashes/physical_name_unterminated.msh, which the gmsh program
# itself segfaults on). Those are gmsh's bugs, not ours; run_fuzz.sh ... gmsh
# by hand still fuzzes it (docs/architecture.md, "Reading gmsh meshes").
add_test(NAME Fuzz.gmsh_replay
         COMMAND bash ${PROJECT_SOURCE_DIR}/tests/fuzz/run_fuzz.sh --build ${COULOMB_FUZZ_BUILD} --runs 0 gmsh)
set_tests_properties(Fuzz.gmsh_replay PROPERTIES TIMEOUT 600 PROCESSORS 1 LABELS "regression;fuzz")
