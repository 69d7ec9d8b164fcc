# Registers each Catch2 test case of one test program as one CTest test, whatever characters its
# name holds (CTest includes this when the program is newer than its last listing;
# tests/CMakeLists.txt).
#
# Catch2's own catch_discover_tests keeps the names in a CMake list, which splits a name at ';'
# into two tests that match no case, and Catch2 passes a run that matched nothing. Here a ';' is
# held as another character while the names are a list, every test runs its case with -w NoTests
# (a run in which no case ran fails), and scripts/check-test-count checks that each case is run by
# exactly one test.
#
# Inputs (set by the includer): TEST_EXECUTABLE, TEST_PREFIX, TEST_WORKING_DIR, CTEST_FILE.

execute_process(
  COMMAND "${TEST_EXECUTABLE}" --list-test-names-only
  OUTPUT_VARIABLE listing
  RESULT_VARIABLE result)
# Catch2 exits with the number of cases it listed; a crash gives a message instead.
if(NOT result MATCHES "^[0-9]+$")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --list-test-names-only failed: ${result}")
endif()

# The unit separator (ASCII 31) is in no test name: it stands for ';' while the names are a list.
string(ASCII 31 semicolon)
string(REPLACE ";" "${semicolon}" listing "${listing}")
string(REPLACE "\n" ";" names "${listing}")

set(script "")
foreach(name IN LISTS names)
  if(name STREQUAL "")
    continue()
  endif()
  # Catch2 reads \ , [ ] " ~ as its filter's syntax: a backslash before each makes it a plain
  # character. Bracket arguments ([==[...]==]) keep ';' and every other character as written.
  # A name that still selects another case, such as one ending in '*' (a wildcard to Catch2), is
  # what scripts/check-test-count reports.
  string(REGEX REPLACE "([][\\\\,\"~])" "\\\\\\1" filter "${name}")
  string(REPLACE "${semicolon}" ";" filter "${filter}")
  string(REPLACE "${semicolon}" ";" name "${name}")
  string(APPEND script
    "add_test([==[${TEST_PREFIX}${name}]==] [==[${TEST_EXECUTABLE}]==] [==[${filter}]==] -w NoTests)\n"
    "set_tests_properties([==[${TEST_PREFIX}${name}]==] PROPERTIES "
    "WORKING_DIRECTORY [==[${TEST_WORKING_DIR}]==])\n")
endforeach()
file(WRITE "${CTEST_FILE}" "${script}")
