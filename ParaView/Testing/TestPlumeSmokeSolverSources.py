"""pvbatch: the smoke solver's point sources through the plugin.

"Plume Smoke Solver" (vtkPlumeSmokeSolver as a ParaView source) takes a
point set on its SourcePoints input (port 2). Three points with per-point
arrays rate (0.5, 1, 2 mass/s), radius and temperature, in a closed box with
ConserveMass on (advection then keeps the total; only the sources change it):
after k steps of TimeStep dt the smoke's mass, sum(density) x cell volume,
must be k dt sum(rate) (relative 1e-4; float output), at two times (5 and 10
steps: it grows linearly), and without the points the box stays empty.
Also: the source advertises its time steps (TimestepValues) and the
SourceRate constant applies to points without a rate array.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np

import plume_pvtest as T
from paraview import simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
import vtk

T.load_plugin()

H = 0.05
DT = 0.05
RATES = [0.5, 1.0, 2.0]
points = vtk.vtkPoints()
for p in [(0.2, 0.3, 0.2), (0.5, 0.5, 0.3), (0.35, 0.2, 0.5)]:
    points.InsertNextPoint(p)
cloud = vtk.vtkPolyData()
cloud.SetPoints(points)
for name, values in [("rate", RATES), ("radius", [0.0, 0.05, 0.1]), ("temperature", [1.0, 2.0, 1.0])]:
    array = numpy_to_vtk(np.array(values, dtype=np.float64), deep=1)
    array.SetName(name)
    cloud.GetPointData().AddArray(array)
producer = simple.PVTrivialProducer()
producer.GetClientSideObject().SetOutput(cloud)


def solver(sources):
    # paraview.simple connects the active source to a new proxy's first input
    # (here port 0, Obstacles): none is active
    simple.SetActiveSource(None)
    s = simple.PlumeSmokeSolver(SourcePoints=sources) if sources else simple.PlumeSmokeSolver()
    s.Dimensions = [16, 16, 20]
    s.Spacing = [H, H, H]
    s.TimeStep = DT
    s.NumberOfTimeSteps = 10
    s.ConserveMass = 1
    return s


def mass(s, steps):
    s.UpdatePipeline(steps * DT)
    image = s.GetClientSideObject().GetOutputDataObject(0)
    density = vtk_to_numpy(image.GetPointData().GetArray("density")).astype(np.float64)
    return float(density.sum()) * H ** 3


ok = True
with_sources = solver(producer)
with_sources.UpdatePipelineInformation()
times = list(with_sources.TimestepValues)
print("time steps advertised: %d, last %g" % (len(times), times[-1]))
ok = ok and len(times) == 11 and abs(times[-1] - 10 * DT) < 1e-12
for steps in (5, 10):
    got = mass(with_sources, steps)
    expected = steps * DT * sum(RATES)
    error = abs(got - expected) / expected
    print("%2d steps: smoke mass %.6f, expected %.6f (relative error %.2e)" % (steps, got, expected, error))
    ok = ok and error < 1e-4

# the rate array renamed away: each point injects SourceRate. Source
# parameters apply from the next step: back to step 0 (a restart), then on.
with_sources.SourceRateArrayName = "no-such-array"
with_sources.SourceRate = 0.25
start = mass(with_sources, 0)
print("step 0: mass %.3g" % start)
ok = ok and start == 0.0
got = mass(with_sources, 10)
expected = 10 * DT * 3 * 0.25
print("SourceRate 0.25 for all three points: mass %.6f, expected %.6f" % (got, expected))
ok = ok and abs(got - expected) / expected < 1e-4

empty = mass(solver(None), 10)
print("without source points: mass %.3g" % empty)
ok = ok and empty == 0.0
T.finish(ok)
