"""pvpython client + pvserver (scripts/test-paraview.sh starts the server,
`mpirun -np 2 pvserver`, through ParaView/Testing/plume_client_server.sh and
passes its port in PLUME_PV_SERVER_PORT): the client connects over localhost,
loads the plugin on both sides (the XML on the client, the classes on the
server), and renders the volume, smoke-sheet and velocity-line scenes of the
MPI test (and the filter's) with the data spread over the server's ranks. Each
image equals the
serial pvbatch reference written by TestPlumeMPI.serial (<name>-serial.png,
same reader, same scene) within one 8-bit level on >= 99.5 % of the pixels,
the bar of TestPlumeMPI. Asserted too: the server has the expected number of
ranks and every rank holds part of the data (the 'Process Id Scalars' filter's
range on the server's output).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from PIL import Image

import plume_pvtest as T
import plume_scenes
from paraview import simple
from paraview import servermanager as sm

port = int(os.environ["PLUME_PV_SERVER_PORT"])
expected_ranks = int(os.environ.get("PLUME_PV_SERVER_RANKS", "2"))
# The server may still be starting: Connect retries for up to 60 s.
connection = simple.Connect("127.0.0.1", port, timeout=60)  # the root has no /etc/hosts: no "localhost"
if connection is None:
    print("could not connect to pvserver on port %d" % port)
    T.finish(False)
ranks = connection.GetNumberOfDataPartitions()
print("connected to pvserver on port %d: %d rank(s)" % (port, ranks), flush=True)
failures = []
if ranks != expected_ranks:
    print("server has %d ranks, expected %d" % (ranks, expected_ranks))
    failures.append("ranks")

# Both sides: the client needs the proxies' XML, the server the classes.
simple.LoadPlugin(os.environ["PLUME_PLUGIN"], remote=False)
simple.LoadPlugin(os.environ["PLUME_PLUGIN"], remote=True)

for name, build in (("PlumeVolume", plume_scenes.volume), ("PlumeSmokeSheet", plume_scenes.sheet),
                    ("PlumeVelocityLines", plume_scenes.lines),
                    ("PlumeGaussianSplat", plume_scenes.splat_points)):
    serial_path = os.path.join(T.OUT, name + "-serial.png")
    if not os.path.exists(serial_path):
        print("%s: no serial image %s (TestPlumeMPI.serial writes it)" % (name, serial_path))
        failures.append(name)
        continue
    v = T.view()
    source = T.carotid_xml()  # read on the server: each rank a slab
    ids = simple.ProcessIdScalars(Input=source)
    ids.UpdatePipeline()
    info = ids.PointData["ProcessId"]
    rng = info.GetRange() if info is not None else (0, 0)
    rep = build(source, v)
    image = T.render_image(v)
    Image.fromarray(image).save(os.path.join(T.OUT, name + "-cs.png"))
    serial = np.asarray(Image.open(serial_path).convert("RGB"))
    ok, share, worst = T.compare(image, serial, levels=1, fraction=0.995)
    diff = np.abs(image.astype(np.int32) - serial.astype(np.int32)).max(axis=2)
    Image.fromarray(np.clip(diff * 16, 0, 255).astype(np.uint8)).save(os.path.join(T.OUT, name + "-cs-diff.png"))
    print("%s: ranks holding data %d..%d; %.3f %% of pixels within 1 level of serial (max %d)" %
          (name, rng[0], rng[1], 100 * share, worst))
    if int(rng[1]) != expected_ranks - 1:
        print("%s: the data is not spread over the %d ranks" % (name, expected_ranks))
        ok = False
    if not ok:
        failures.append(name)
    simple.Delete(rep)
    simple.Delete(ids)
    simple.Delete(v)
    del v
simple.Disconnect()
T.finish(not failures)
