# plume simulate with "backend": "gpu": the series is written, a step of it
# renders, and its last step equals (to float tolerance) the same scene run
# on the CPU backend's Jacobi path with the GPU's fixed iteration count (the
# scene made here from the GPU one by swapping those keys, so the two cannot
# drift apart).
#   cmake -DPLUME=... -DPYTHON=... -DSCENE_DIR=... -DCOMPARE=... -DWORK_DIR=... -P SimulateGPUTest.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/plumeRunInWorkDir.cmake")
file(READ "${SCENE_DIR}/plume_gpu.json" gpu_scene)
string(REPLACE "\"backend\": \"gpu\"" "\"backend\": \"cpu\", \"pressure_solver\": \"jacobi\", \"pressure_tolerance\": 0"
  cpu_scene "${gpu_scene}")
if (cpu_scene STREQUAL gpu_scene)
  message(FATAL_ERROR "plume_gpu.json has no \"backend\": \"gpu\" to swap")
endif ()
file(WRITE "${WORK_DIR}/plume_cpu.json" "${cpu_scene}")
run("${PLUME}" simulate "${SCENE_DIR}/plume_gpu.json" -o gpu.pvd --every 4)
if (NOT out MATCHES "wrote gpu\\.pvd \\(2 time steps of dataset 'smoke', steps 0\\.\\.8")
  message(FATAL_ERROR "unexpected summary: ${out}")
endif ()
run("${PLUME}" simulate plume_cpu.json -o cpu.pvd --every 4)
run("${PYTHON}" "${COMPARE}" gpu/smoke_000008.vti cpu/smoke_000008.vti 2e-5)
message(STATUS "${out}")
# a step of the GPU series renders
file(WRITE "${WORK_DIR}/render_gpu.json"
  "{ \"size\": [96, 96], \"datasets\": { \"series\": { \"path\": \"gpu.pvd\", \"time_step\": 1 } },
     \"representations\": [{ \"type\": \"volume\", \"dataset\": \"series\", \"array\": \"density\", \"range\": [0, 1] }] }")
run("${PLUME}" render render_gpu.json -o gpu_step8.png)
if (NOT EXISTS "${WORK_DIR}/gpu_step8.png")
  message(FATAL_ERROR "plume render wrote no gpu_step8.png")
endif ()
message(STATUS "simulate on the GPU backend: series written, equal to the CPU's, rendered")
