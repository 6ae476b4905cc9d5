"""Compares two smoke-solver .vti files written by `plume simulate` (the GPU
backend's against the CPU backend's Jacobi path, same settings): every
output array agrees to TOLERANCE relative to the CPU field's largest
magnitude, the flow is not trivial (smoke and motion), so two empty
fields cannot pass, and the two are not bit-identical (the GPU computes in
float), so two CPU runs cannot pass. Reads with VTK's XML reader and compares in Python: no
code shared with either backend.
    compare_smoke_vti.py GPU.vti CPU.vti TOLERANCE"""
import sys

import vtk  # Debian's VTK 9.1 wrappers

gpu_path, cpu_path, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])


def read(path):
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit(f"{path}: no points")
    return image.GetPointData()


gpu, cpu = read(gpu_path), read(cpu_path)
worst = 0.0
for name in ("velocity", "density", "temperature", "pressure"):
    a, b = gpu.GetArray(name), cpu.GetArray(name)
    if a is None or b is None:
        sys.exit(f"array '{name}' missing (gpu: {a is not None}, cpu: {b is not None})")
    if a.GetNumberOfTuples() != b.GetNumberOfTuples() or a.GetNumberOfComponents() != b.GetNumberOfComponents():
        sys.exit(f"'{name}': shapes differ")
    diff = scale = 0.0
    for t in range(b.GetNumberOfTuples()):
        for c in range(b.GetNumberOfComponents()):
            x, y = a.GetComponent(t, c), b.GetComponent(t, c)
            diff = max(diff, abs(x - y))
            scale = max(scale, abs(y))
    relative = diff / scale if scale > 0 else diff
    print(f"{name}: max |gpu - cpu| {diff:.3g} of max |cpu| {scale:.3g}: relative {relative:.3g}")
    if name == "density" and scale < 0.1:
        sys.exit(f"no smoke: max density {scale}")
    if name == "velocity" and scale < 0.05:
        sys.exit(f"no motion: max speed component {scale}")
    worst = max(worst, relative)
print(f"largest relative difference {worst:.3g} (tolerance {tolerance:g})")
if worst == 0:
    sys.exit("the two series are bit-identical: the GPU (float) backend did not run")
if not worst <= tolerance:
    sys.exit(f"the GPU series differs from the CPU series by {worst:.3g} > {tolerance:g}")
