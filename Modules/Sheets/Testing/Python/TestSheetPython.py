"""Drive vtkPlumeSheetMapper from Python (Debian's /usr/bin/python3, ``import vtk;
import plume``): a small asymmetric smoke sheet with per-point density and RGB
absorption, rendered offscreen; the read-back transmittance must match
vtkPlumeSheetReference (the double-precision CPU reference) within the issue's
goal, RMS <= 1 % and max <= 5 % of the reference's dynamic range."""
import math
import sys

import vtk  # Debian's VTK 9.1 wrappers
import plume
from plume_test_window import offscreen_window, read_rgba

W, H = 64, 48

# Two triangles of a tilted quad plus a third one off to the side (asymmetric).
points = vtk.vtkPoints()
for p in [(-0.9, -0.6, 0.0), (0.7, -0.5, 0.15), (0.8, 0.6, -0.1), (-0.6, 0.7, 0.05), (0.2, -0.9, 0.3)]:
    points.InsertNextPoint(p)
cells = vtk.vtkCellArray()
for tri in [(0, 1, 2), (0, 2, 3), (0, 4, 1)]:
    cells.InsertNextCell(3, tri)
mesh = vtk.vtkPolyData()
mesh.SetPoints(points)
mesh.SetPolys(cells)
density = vtk.vtkDoubleArray()
density.SetName("density")
for d in (0.4, 1.0, 0.7, 0.2, 1.3):
    density.InsertNextValue(d)
absorption = vtk.vtkDoubleArray()
absorption.SetName("absorption")
absorption.SetNumberOfComponents(3)
for rgb in [(0.3, 0.8, 1.4), (1.2, 0.6, 0.2), (0.7, 1.0, 0.5), (1.0, 1.0, 1.0), (0.5, 0.2, 1.1)]:
    absorption.InsertNextTuple3(*rgb)
mesh.GetPointData().AddArray(density)
mesh.GetPointData().AddArray(absorption)

mapper = plume.vtkPlumeSheetMapper()
mapper.SetInputData(mesh)
mapper.SetDensityArrayName("density")
mapper.SetDensityScale(1.2)
mapper.SetAbsorptionArrayName("absorption")
mapper.SetBlurRadius(0.12)
mapper.SetThickness(0.08)
actor = vtk.vtkActor()
actor.SetMapper(mapper)

renderer = vtk.vtkRenderer()
renderer.SetBackground(1, 1, 1)
renderer.AddActor(actor)
window = offscreen_window(renderer, W, H)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.8, 1.1, 4.5)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(35)
renderer.ResetCameraClippingRange()


actor.SetVisibility(False)
base = read_rgba(window)
depth = vtk.vtkFloatArray()
window.GetZbufferData(0, 0, W - 1, H - 1, depth)
actor.SetVisibility(True)
image = read_rgba(window)
assert mapper.GetTriangleCount() == 3, mapper.GetTriangleCount()

reference = plume.vtkPlumeSheetReference()
reference.SetInputData(mesh)
reference.SetDensityArrayName("density")
reference.SetDensityScale(1.2)
reference.SetAbsorptionArrayName("absorption")
reference.SetBlurRadius(0.12)
reference.SetThickness(0.08)
assert reference.Compute(renderer, [depth.GetValue(i) for i in range(W * H)])
T = reference.GetTransmittance()
assert len(T) == W * H * 3, len(T)

lo, hi = min(T), max(T)
span = hi - lo
sq, worst = 0.0, 0.0
for i in range(W * H):
    for c in range(3):
        got = image[4 * i + c]
        assert math.isfinite(got), "NaN/Inf pixel"
        e = abs(got - base[4 * i + c] * T[3 * i + c])
        sq += e * e
        worst = max(worst, e)
rms = math.sqrt(sq / (W * H * 3)) / span
mx = worst / span
print(f"T range {span:.3f}  RMS {rms:.4f}  max {mx:.4f} of the range")
assert span > 0.3, "the sheet barely darkens the frame"
# channels darken differently (RGB absorption reached the shader)
assert max(abs(image[4 * i] - image[4 * i + 2]) for i in range(W * H)) > 0.1, "no per-channel absorption"
assert rms <= 0.01 and mx <= 0.05, f"rendered transmittance differs from the reference (RMS {rms}, max {mx})"

# a camera move re-renders without uploading the triangles again
uploads = mapper.GetUploadCount()
camera.Azimuth(10)
window.Render()
assert mapper.GetUploadCount() == uploads, "camera move re-uploaded the triangles"
print("OK")
sys.exit(0)
