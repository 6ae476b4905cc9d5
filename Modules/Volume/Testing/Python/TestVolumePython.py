"""Drive vtkPlumeVolumeMapper from Debian's /usr/bin/python3 next to VTK:
render a small analytic smoke volume offscreen and compare the read-back
float image with vtkPlumeVolumeReference (the independent CPU raycaster),
RMS asserted; a reference computed with twice the opacity unit distance must
fail the same bound (the comparison discriminates); a texture-memory budget
below the volume's size draws nothing and reports one error naming both."""
import math
import sys

import vtk  # Debian's VTK 9.1 wrappers
import plume
from plume_test_window import offscreen_window, read_rgba

N, W, H = 32, 120, 100


def smoke(n):
    """Two Gaussian puffs, asymmetric, values in [0, ~1]."""
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1))
    values = vtk.vtkFloatArray()
    values.SetName("density")
    values.SetNumberOfTuples(n * n * n)
    puffs = ((0.35, 0.4, 0.45, 0.18), (0.68, 0.6, 0.5, 0.12))
    i = 0
    for k in range(n):
        z = k / (n - 1)
        for j in range(n):
            y = j / (n - 1)
            for l in range(n):
                x = l / (n - 1)
                v = sum(math.exp(-((x - a) ** 2 + (y - b) ** 2 + (z - c) ** 2) / (2 * s * s))
                        for a, b, c, s in puffs)
                values.SetValue(i, min(v, 1.0))
                i += 1
    image.GetPointData().SetScalars(values)
    return image


def configure(prop, unit_distance):
    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(0.0, 0.1, 0.2, 0.8)
    color.AddRGBPoint(0.5, 0.9, 0.9, 0.8)
    color.AddRGBPoint(1.0, 1.0, 0.5, 0.1)
    opacity = vtk.vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(0.05, 0.0)
    opacity.AddPoint(1.0, 0.8)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    prop.SetInterpolationTypeToLinear()


image = smoke(N)
mapper = plume.vtkPlumeVolumeMapper()
mapper.SetInputData(image)
mapper.SetSampleDistance(0.5)
volume = vtk.vtkVolume()
volume.SetMapper(mapper)
configure(volume.GetProperty(), 0.05)

renderer = vtk.vtkRenderer()
renderer.SetBackground(0, 0, 0)
renderer.AddVolume(volume)
window = offscreen_window(renderer, W, H)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.3, -0.4, 1.0)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 1, 0)
renderer.ResetCamera()
rendered = read_rgba(window)
assert all(math.isfinite(v) for v in rendered), "non-finite pixel"


def compare(unit_distance):
    """RMS (RGB) and covered pixels of the rendered image vs the reference."""
    ref_volume = vtk.vtkVolume()
    configure(ref_volume.GetProperty(), unit_distance)
    reference = plume.vtkPlumeVolumeReference()
    reference.SetInputData(image)
    reference.SetVolume(ref_volume)
    reference.SetRenderer(renderer)
    reference.SetMode(plume.vtkPlumeVolumeReference.COMPOSITE)
    reference.SetStep(0.25)
    assert reference.Compute(W, H), reference.GetLastError()
    expected = reference.GetImage()  # premultiplied: over a black background it is the pixel
    assert len(expected) == 4 * W * H
    total = sum((rendered[p + c] - expected[p + c]) ** 2 for p in range(0, 4 * W * H, 4) for c in range(3))
    covered = sum(1 for p in range(3, 4 * W * H, 4) if expected[p] > 1.0 / 255)
    return math.sqrt(total / (3 * W * H)), covered


rms, covered = compare(0.05)
print(f"rendered vs reference: RMS {rms:.5f} (<= 0.005), covered {covered} px (>= 2000)")
assert covered >= 2000, "the reference volume covers too few pixels"
assert rms <= 0.005, f"RMS {rms} vs the reference"
wrong, _ = compare(0.1)
print(f"vs a reference with twice the unit distance: RMS {wrong:.5f} (must be > 0.005)")
assert wrong > 0.005, "the comparison does not tell a wrong opacity from the right one"

# texture-memory budget: 32^3 floats are 0.125 MB
errors = []
mapper.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
mapper.SetTextureMemoryBudgetMB(0.1)
pixels = read_rgba(window)
lit = sum(1 for i in range(0, 4 * W * H, 4) if max(pixels[i:i + 3]) > 2 / 255)
print(f"budget 0.1 MB: {len(errors)} error(s), {lit} px drawn")
assert len(errors) == 1 and lit == 0, "a volume over the budget must be refused, not drawn"
print("OK")
sys.exit(0)
