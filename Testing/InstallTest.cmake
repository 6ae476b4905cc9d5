# Install Plume into a fresh prefix, build Examples/FindPlume against it with
# find_package(Plume), and run the example. Then move the prefix elsewhere and
# run the installed plume (a real render) and import the installed Python
# package from there, with LD_LIBRARY_PATH unset: the RPATH ($ORIGIN-relative)
# must find Plume's libraries from any prefix.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DWITH_PYTHON=ON]
#         [-DCONSUMER_ARGS=...] -P InstallTest.cmake
# CONSUMER_ARGS (a |-separated list) configures the consumer like the libraries: in a
# sanitizer build, the same compiler and the sanitizer runtime linked first
# (an unsanitized executable loading ASan-instrumented libraries dies in the
# runtime's start-up, before any report).
string(REPLACE "|" ";" CONSUMER_ARGS "${CONSUMER_ARGS}")
file(REMOVE_RECURSE "${WORK_DIR}")
set(steps install configure build run move plume render)
if (WITH_PYTHON)
  list(APPEND steps python)
endif ()
foreach (step IN LISTS steps)
  if (step STREQUAL "install")
    set(cmd "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  elseif (step STREQUAL "configure")
    set(cmd "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/FindPlume" -B "${WORK_DIR}/build" -G Ninja
      "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release ${CONSUMER_ARGS})
  elseif (step STREQUAL "build")
    set(cmd "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
  elseif (step STREQUAL "run")
    set(cmd "${WORK_DIR}/build/glyphs_example")
  elseif (step STREQUAL "move")
    # another prefix than the one installed to: an absolute RPATH would not follow
    set(cmd "${CMAKE_COMMAND}" -E rename "${WORK_DIR}/prefix" "${WORK_DIR}/moved")
  elseif (step STREQUAL "plume")
    # the installed command line starts from its prefix alone (RPATH; no LD_LIBRARY_PATH)
    set(cmd env -u LD_LIBRARY_PATH "${WORK_DIR}/moved/bin/plume" params sheet)
  elseif (step STREQUAL "render")
    set(cmd env -u LD_LIBRARY_PATH -u DISPLAY "${WORK_DIR}/moved/bin/plume" render
      "${SOURCE_DIR}/Examples/Scenes/vortex_streamlets.json" -o "${WORK_DIR}/installed_render.png" --size 64x48)
  else ()
    set(cmd env -u LD_LIBRARY_PATH "PYTHONPATH=${WORK_DIR}/moved/lib/python3/dist-packages" /usr/bin/python3 -c
      "import vtk, plume; print(plume.vtkPlumeSheetMapper().GetDensity())")
  endif ()
  execute_process(COMMAND ${cmd} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "install test step '${step}' failed (${result}):\n${out}\n${err}")
  endif ()
  message(STATUS "${step}: ok")
endforeach ()
