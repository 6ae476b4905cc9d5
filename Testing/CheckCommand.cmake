# ctest helper: run COMMAND (a ;-list), require a non-zero exit code and that
# stderr matches EXPECT (a regex) in a single line, with no crash signature.
#   cmake -DCOMMAND="a;b;c" -DEXPECT="regex" -P CheckCommand.cmake
execute_process(COMMAND ${COMMAND}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (result EQUAL 0)
  message(FATAL_ERROR "expected failure, got exit 0\nstdout: ${out}\nstderr: ${err}")
endif ()
if (NOT result MATCHES "^[0-9]+$" OR result GREATER 100)
  message(FATAL_ERROR "abnormal exit '${result}' (crash?)\nstderr: ${err}")
endif ()
if (NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}':\n${err}")
endif ()
string(STRIP "${err}" stripped)
string(REGEX MATCHALL "\n" newlines "${stripped}")
list(LENGTH newlines lines)
if (lines GREATER 0)
  message(FATAL_ERROR "expected one error line, got:\n${err}")
endif ()
message(STATUS "exit ${result}: ${err}")
