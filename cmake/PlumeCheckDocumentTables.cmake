# ctest -P script: every table `plume params TYPE` prints must stand verbatim
# in the document (so the documentation cannot drift from the parameter
# tables the renderers declare).
# -DPLUME=<plume executable> -DDOCUMENT=<markdown file> -DTYPES=<type;type>
file(READ "${DOCUMENT}" document)
foreach (type IN LISTS TYPES)
  execute_process(COMMAND "${PLUME}" params "${type}" OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "plume params ${type} failed (${rc})")
  endif ()
  # the table without the generated heading line
  string(FIND "${out}" "| key |" at)
  string(SUBSTRING "${out}" ${at} -1 table)
  string(STRIP "${table}" table)
  string(FIND "${document}" "${table}" found)
  if (found EQUAL -1)
    message(FATAL_ERROR "${DOCUMENT} does not hold the table of '${type}' as `plume params ${type}` prints it:\n${table}")
  endif ()
  message(STATUS "${type}: table found in ${DOCUMENT}")
endforeach ()
