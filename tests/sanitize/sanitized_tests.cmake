# Included at the end of every CMakeLists.txt that adds tests (CMake sets
# test properties only in the directory that added the test).
# A sanitizer report fails the test even where a non-zero exit is expected
# (signals, bad input); sanitized runs are slower, so time limits triple.
if(COULOMB_SANITIZE)
  get_property(directory_tests DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} PROPERTY TESTS)
  foreach(test ${directory_tests})
    get_test_property(${test} TIMEOUT timeout)
    if(timeout)
      math(EXPR timeout "${timeout} * 3")
      set_tests_properties(${test} PROPERTIES TIMEOUT ${timeout})
    endif()
    set_tests_properties(${test} PROPERTIES
      FAIL_REGULAR_EXPRESSION "ERROR: AddressSanitizer;ERROR: LeakSanitizer;runtime error:")
  endforeach()
endif()
