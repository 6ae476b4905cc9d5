# plume_add_python_test(NAME SCRIPT): run SCRIPT with Debian's /usr/bin/python3
# (the interpreter that imports Debian's vtk) next to the built `plume`
# package, the shared test helpers (Testing/Python) and the data folder.
function (plume_add_python_test name script)
  add_test(NAME ${name} COMMAND /usr/bin/python3 "${script}")
  set_tests_properties(${name} PROPERTIES ENVIRONMENT
    "PYTHONPATH=${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/python3/dist-packages:${PROJECT_SOURCE_DIR}/Testing/Python;LD_LIBRARY_PATH=${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR};PLUME_DATA_DIR=${PLUME_DATA_DIR}")
endfunction ()
