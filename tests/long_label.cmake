# Run after each doctest executable is built (tests/CMakeLists.txt, arksph_test_executable): lists
# its test cases of doctest suite "long" (TEST_CASE("..." * doctest::test_suite("long"))) and writes
# CTEST_FILE, which adds the ctest label "long" to each of them beside the executable's own label.
# It also refuses a test case name with a ';', which doctest's discovery (doctestAddTests.cmake)
# would split into two ctest tests that each run no test case and pass.
#   cmake -D TEST_EXECUTABLE=... -D CTEST_FILE=... -P long_label.cmake
cmake_minimum_required(VERSION 3.25)

# The names printed by `TEST_EXECUTABLE ARGS --list-test-cases`, one a line, into the variable OUT
# (a string, not a list: a name may hold a ';').
function(list_test_cases out)
  execute_process(
    COMMAND "${TEST_EXECUTABLE}" ${ARGN} --list-test-cases
    OUTPUT_VARIABLE output
    RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "listing the test cases of ${TEST_EXECUTABLE} failed (${result}):\n${output}")
  endif()
  set(names "")
  while(NOT output STREQUAL "")  # line by line (a CMake list would split a name at its ';')
    string(FIND "${output}" "\n" end)
    if(end EQUAL -1)
      set(line "${output}")
      set(output "")
    else()
      string(SUBSTRING "${output}" 0 ${end} line)
      math(EXPR end "${end} + 1")
      string(SUBSTRING "${output}" ${end} -1 output)
    endif()
    # doctest's own lines: the rules and "[doctest] ..." (as doctestAddTests.cmake skips them)
    if(NOT line STREQUAL "" AND NOT line MATCHES "^=+$" AND NOT line MATCHES "^\\[doctest\\] ")
      string(APPEND names "${line}\n")
    endif()
  endwhile()
  string(STRIP "${names}" names)
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

list_test_cases(all)
string(REGEX MATCH "[^\n]*;[^\n]*" bad "${all}")
if(NOT bad STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE}: the test case \"${bad}\" has a ';' in its name, which ctest "
                      "would split into two tests that run nothing: use another character")
endif()

list_test_cases(long --test-suite=long)
string(REPLACE "\n" "]==] PROPERTIES LABELS long)\nset_tests_properties([==[" script "${long}")
if(script STREQUAL "")
  file(WRITE "${CTEST_FILE}" "")
else()
  file(WRITE "${CTEST_FILE}" "set_tests_properties([==[${script}]==] PROPERTIES LABELS long)\n")
endif()
