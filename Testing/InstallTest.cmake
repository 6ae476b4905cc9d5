# Install Plume into a fresh prefix, build Examples/FindPlume against it with
# find_package(Plume), and run the example.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P InstallTest.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
foreach (step IN ITEMS install configure build run plume python)
  if (step STREQUAL "install")
    set(cmd "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  elseif (step STREQUAL "configure")
    set(cmd "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/FindPlume" -B "${WORK_DIR}/build" -G Ninja
      "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release)
  elseif (step STREQUAL "build")
    set(cmd "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
  elseif (step STREQUAL "run")
    set(cmd "${WORK_DIR}/build/glyphs_example")
  elseif (step STREQUAL "plume")
    # the installed command line starts from its prefix alone (RPATH; no LD_LIBRARY_PATH)
    set(cmd "${WORK_DIR}/prefix/bin/plume" params sheet)
  else ()
    set(cmd env "PYTHONPATH=${WORK_DIR}/prefix/lib/python3/dist-packages" /usr/bin/python3 -c
      "import vtk, plume; print(plume.vtkPlumeSheetMapper().GetDensity())")
  endif ()
  execute_process(COMMAND ${cmd} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "install test step '${step}' failed (${result}):\n${out}\n${err}")
  endif ()
  message(STATUS "${step}: ok")
endforeach ()
