"""Drive vtkPlumeSmokeSolver from Python: a time request through the
pipeline runs the right number of steps, the output carries the solver's
arrays, the buoyant smoke rises and the projection leaves no divergence
(hypre's MPI is initialised and finalised by the solver itself)."""
import vtk  # Debian's VTK 9.1 wrappers
import plume

smoke = plume.vtkPlumeSmokeSolver()
smoke.SetDimensions(16, 16, 28)
smoke.SetSpacing(0.05, 0.05, 0.05)
smoke.SetTimeStep(0.05)
smoke.SetBuoyancy(4.0)
smoke.AddSource((0.375, 0.375, 0.15), 0.1, 1.0, 2.0, (0.0, 0.0, 0.0))
smoke.AddObstacleSphere((0.4, 0.35, 0.8), 0.15)
smoke.UpdateTimeStep(1.0)
assert smoke.GetCurrentStep() == 20, smoke.GetCurrentStep()
out = smoke.GetOutput()
names = [out.GetPointData().GetArrayName(i) for i in range(out.GetPointData().GetNumberOfArrays())]
for name in ("velocity", "density", "temperature", "pressure", "divergence", "obstacle"):
    assert name in names, names

pd = out.GetPointData()
density, divergence = pd.GetArray("density"), pd.GetArray("divergence")
velocity, obstacle = pd.GetArray("velocity"), pd.GetArray("obstacle")
n = out.GetNumberOfPoints()
mass = sum(density.GetValue(p) for p in range(n))
z = sum(density.GetValue(p) * out.GetPoint(p)[2] for p in range(n)) / mass
assert z > 0.3, f"smoke centroid at z = {z}, the source is at 0.15"

speed = max(abs(velocity.GetComponent(p, c)) for p in range(n) for c in range(3))
scale = speed / 0.05
max_div = max(abs(divergence.GetValue(p)) for p in range(n))
assert max_div < 1e-4 * scale, (max_div, scale)
solid = sum(obstacle.GetValue(p) for p in range(n))
assert solid > 20, solid
print(f"step {smoke.GetCurrentStep()}, centroid z {z:.3f}, max |div| {max_div:.2e} "
      f"of |u|/h {scale:.2f}, PCG {smoke.GetPressureSolver().GetLastIterations()} iterations")

# Sources given as points (input port 2) from Python: a vtkPolyData whose
# "rate" array gives each point's mass per second; with conserve_mass the
# smoke's mass after 10 steps is 10 * dt * sum(rate).
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

points = vtkPoints()
points.InsertNextPoint(0.3, 0.3, 0.2)
points.InsertNextPoint(0.5, 0.4, 0.3)
rates = vtkDoubleArray()
rates.SetName("rate")
rates.InsertNextValue(0.4)
rates.InsertNextValue(0.6)
inlets = vtkPolyData()
inlets.SetPoints(points)
inlets.GetPointData().AddArray(rates)
fed = plume.vtkPlumeSmokeSolver()
fed.SetDimensions(12, 12, 16)
fed.SetSpacing(0.05, 0.05, 0.05)
fed.SetTimeStep(0.05)
fed.SetConserveMass(True)
fed.SetSourceRadius(0.06)
fed.SetSourcePointsData(inlets)
fed.UpdateTimeStep(0.5)
fed_density = fed.GetOutput().GetPointData().GetArray("density")
fed_mass = sum(fed_density.GetValue(p) for p in range(fed.GetOutput().GetNumberOfPoints())) * 0.05 ** 3
assert abs(fed_mass - 10 * 0.05 * 1.0) < 1e-5, fed_mass  # float output arrays
print(f"point sources: mass {fed_mass:.6f} after 10 steps (expected 0.5)")
