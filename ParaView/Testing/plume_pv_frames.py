"""Frame times of the plugin's scenes (not a test: run by hand, serial with
pvbatch or distributed with mpirun -np 2 pvbatch --symmetric). Prints one JSON
line per scene: median seconds per frame over 8 frames, the camera turning
by 3 degrees each (every frame is a full render). Data: carotid.vti read by
the XML image reader (each rank a slab); PLUME_TEST_OUT must hold it (the
MPI test writes it).

The "Plume Gaussian Splat" filter (TestPlumeMPI's splat scene: density of
the cell centres inside the vessels) is timed apart: median seconds per
re-execution over 8 (the radius nudged by 1e-9 relative each time, so the
filter runs again and nothing upstream does; on 2 ranks this includes the
exchange of line starts, the bounds reduction and the all-reduce of the
grid), at the scene's 72x48x44 grid and at 144x96x88, and the median frame
of its volume as above."""
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plume_pvtest as T
import plume_scenes
from paraview import simple

T.load_plugin()
vti = os.path.join(T.OUT, "carotid.vti")
for name, build in (("volume", plume_scenes.volume), ("sheet", plume_scenes.sheet),
                    ("lines", plume_scenes.lines)):
    v = T.view()
    rep = build(simple.XMLImageDataReader(FileName=[vti]), v)
    T.frame(v)
    simple.Render(v)  # first frame: uploads, shader builds
    times = []
    for i in range(8):
        cam = v.GetActiveCamera()
        cam.Azimuth(3.0)
        t0 = time.perf_counter()
        simple.Render(v)
        times.append(time.perf_counter() - t0)
    times.sort()
    T.log(json.dumps({"scene": name, "ranks": T.ranks(), "median_frame_s": round(times[len(times) // 2], 4),
                      "load_average_1min": round(os.getloadavg()[0], 2)}))
    simple.Delete(rep)

for dims in ([72, 48, 44], [144, 96, 88]):
    v = T.view()
    rep = plume_scenes.splat_points(simple.XMLImageDataReader(FileName=[vti]), v)
    splatter = rep.Input
    splatter.Dimensions = dims
    T.frame(v)
    simple.Render(v)
    radius = splatter.Radius
    splats, frames = [], []
    for i in range(8):
        splatter.Radius = radius * (1 + 1e-9 * ((i % 2) + 1))
        t0 = time.perf_counter()
        splatter.UpdatePipeline()
        splats.append(time.perf_counter() - t0)
        v.GetActiveCamera().Azimuth(3.0)
        t0 = time.perf_counter()
        simple.Render(v)
        frames.append(time.perf_counter() - t0)
    splats.sort()
    frames.sort()
    T.log(json.dumps({"scene": "splat", "grid": "x".join(map(str, dims)), "ranks": T.ranks(),
                      "median_splat_s": round(splats[len(splats) // 2], 4),
                      "median_frame_s": round(frames[len(frames) // 2], 4),
                      "load_average_1min": round(os.getloadavg()[0], 2)}))
    simple.Delete(rep)
