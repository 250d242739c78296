# Run after each doctest executable is built (tests/CMakeLists.txt, arksph_test_executable): every
# doctest test suite of the executable is also a ctest label. The test cases of suite S
# (TEST_CASE("..." * doctest::test_suite("S"))) get label S beside the executable's own label, through
# CTEST_FILE, which ctest reads after the discovered tests. The suites in use: "long" and
# "asan_slow" (tests/CMakeLists.txt). A test case is in one suite at most.
# It also refuses a test case name with a ';', which doctest's discovery (doctestAddTests.cmake)
# would split into two ctest tests that each run no test case and pass.
#   cmake -D TEST_EXECUTABLE=... -D CTEST_FILE=... -P suite_labels.cmake
cmake_minimum_required(VERSION 3.25)

# The names printed by `TEST_EXECUTABLE ARGS`, one a line, without doctest's own lines, into the
# variable OUT (a string, not a list: a name may hold a ';').
function(doctest_list out)
  execute_process(
    COMMAND "${TEST_EXECUTABLE}" ${ARGN}
    OUTPUT_VARIABLE output
    RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${TEST_EXECUTABLE} ${ARGN} failed (${result}):\n${output}")
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

doctest_list(all --list-test-cases)
string(REGEX MATCH "[^\n]*;[^\n]*" bad "${all}")
if(NOT bad STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE}: the test case \"${bad}\" has a ';' in its name, which ctest "
                      "would split into two tests that run nothing: use another character")
endif()

set(script "")
doctest_list(suites --list-test-suites)
string(REPLACE "\n" ";" suites "${suites}")
foreach(suite IN LISTS suites)
  if(NOT suite MATCHES "^[A-Za-z0-9_]+$")
    message(FATAL_ERROR "${TEST_EXECUTABLE}: test suite \"${suite}\" is used as a ctest label: "
                        "letters, digits and '_' only")
  endif()
  doctest_list(cases --test-suite=${suite} --list-test-cases)
  string(REPLACE "\n" "]==] PROPERTIES LABELS ${suite})\nset_tests_properties([==[" cases "${cases}")
  if(NOT cases STREQUAL "")
    string(APPEND script "set_tests_properties([==[${cases}]==] PROPERTIES LABELS ${suite})\n")
  endif()
endforeach()
file(WRITE "${CTEST_FILE}" "${script}")
