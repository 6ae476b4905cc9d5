# For the command-line test scripts (cmake -P): run(COMMAND ARGS...) runs a
# command in WORK_DIR, stops the test with its output if it fails, and leaves
# its standard output in `out`.
function (run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK_DIR}"
    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' failed (${result}):\n${out}\n${err}")
  endif ()
  set(out "${out}" PARENT_SCOPE)
endfunction ()
