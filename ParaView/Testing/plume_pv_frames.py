"""Frame times of the plugin's scenes (not a test: run by hand, serial with
pvbatch or distributed with mpirun -np 2 pvbatch --symmetric). Prints one JSON
line per scene: median seconds per frame over 8 frames, the camera turning
by 3 degrees each (every frame is a full render). Data: carotid.vti read by
the XML image reader (each rank a slab); PLUME_TEST_OUT must hold it (the
MPI test writes it)."""
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
    T.log(json.dumps({"scene": name, "ranks": T.ranks(), "median_frame_s": round(times[len(times) // 2], 4)}))
    simple.Delete(rep)
