# plume simulate with sources given as points (scene key source_points: a
# .vtp of two inlets with rate, radius and velocity arrays, no "sources"
# sphere): the written series holds smoke, which only the points can have put there.
#   cmake -DPLUME=... -DSCENE_DIR=... -DWORK_DIR=... -P SimulatePointSourcesTest.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/plumeRunInWorkDir.cmake")
run("${PLUME}" simulate "${SCENE_DIR}/point_sources.json" -o points.pvd --every 10)
if (NOT out MATCHES "wrote points\\.pvd \\(2 time steps of dataset 'smoke', steps 0\\.\\.20")
  message(FATAL_ERROR "unexpected summary: ${out}")
endif ()
run("${PLUME}" info points.pvd --time-step 1)
if (NOT out MATCHES "density +float +1 +\\[0, [0-9.e+-]+\\]" OR out MATCHES "density +float +1 +\\[0, 0\\]")
  message(FATAL_ERROR "no smoke from the source points:\n${out}")
endif ()
message(STATUS "${out}")
