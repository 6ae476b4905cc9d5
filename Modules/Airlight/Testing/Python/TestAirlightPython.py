"""Drive vtkPlumeAirlightPass from Python (Debian's /usr/bin/python3, ``import vtk;
import plume``): a point light off to the upper left in a coloured haze, nothing
drawn, so every view ray runs through the medium to infinity. The 8-bit frame
must match vtkPlumeAirlightReference.ComputeRay (double-precision adaptive
integration) on every pixel within the issue's goal, RMS <= 0.5 % and max <= 2 %
of the airlight image's range."""
import math

import vtk  # Debian's VTK 9.1 wrappers
import plume
from plume_test_window import offscreen_window, read_rgba

W, H = 48, 36

light = vtk.vtkLight()
light.SetLightTypeToSceneLight()
light.SetPositional(True)
light.SetConeAngle(180)
light.SetPosition(-1.5, 1.0, -2.0)
light.SetColor(1.0, 0.8, 0.6)

renderer = vtk.vtkRenderer()
renderer.SetBackground(0.3, 0.3, 0.3)  # extinguished: rays that hit nothing run to infinity
renderer.AddLight(light)
steps = vtk.vtkRenderStepsPass()
air = plume.vtkPlumeAirlightPass()
air.SetDelegatePass(steps)
air.SetScattering(0.3, 0.25, 0.2)
air.SetAbsorption(0.05, 0.05, 0.1)
air.SetIntensityScale(8.0)
renderer.SetPass(air)
window = offscreen_window(renderer, W, H)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.3, 0.2, 3.0)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(60)
camera.SetClippingRange(0.1, 20)
image = read_rgba(window)

reference = plume.vtkPlumeAirlightReference()
reference.SetScattering(air.GetScattering())
reference.SetAbsorption(air.GetAbsorption())
reference.SetIntensityScale(air.GetIntensityScale())
reference.SetLights(renderer)
assert reference.GetNumberOfLights() == 1

matrix = vtk.vtkMatrix4x4()
matrix.DeepCopy(camera.GetCompositeProjectionTransformMatrix(renderer.GetTiledAspectRatio(), -1, 1))
matrix.Invert()
eye = camera.GetPosition()
expected = []
for j in range(H):
    for i in range(W):
        far = matrix.MultiplyPoint(((i + 0.5) / W * 2 - 1, (j + 0.5) / H * 2 - 1, 1.0, 1.0))
        direction = [far[k] / far[3] - eye[k] for k in range(3)]
        rgb = [0.0, 0.0, 0.0]
        reference.ComputeRay(eye, direction, math.inf, rgb)
        expected.append([min(1.0, v) for v in rgb])

lo = min(min(e) for e in expected)
hi = max(max(e) for e in expected)
span = hi - lo
sq, worst = 0.0, 0.0
for p, e in enumerate(expected):
    for c in range(3):
        got = image[4 * p + c]
        assert math.isfinite(got), "NaN/Inf pixel"
        d = abs(got - e[c])
        sq += d * d
        worst = max(worst, d)
rms = math.sqrt(sq / (3 * W * H)) / span
mx = worst / span
print(f"airlight range {span:.3f}  RMS {100 * rms:.3f} %  max {100 * mx:.3f} % of the range")
assert span > 0.3, "the haze is barely lit"
assert rms <= 0.005 and mx <= 0.02, f"airlight differs from the reference (RMS {rms}, max {mx})"

# ks = ka = 0: the pass is a no-op and the background shows again
air.SetScattering(0, 0, 0)
air.SetAbsorption(0, 0, 0)
clear = read_rgba(window)
assert abs(clear[0] - 0.3) < 2 / 255, clear[:4]
