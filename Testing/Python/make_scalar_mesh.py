"""Writes the quick look's scalar density blob (plume_density.vti) as an
unstructured grid of hexahedra with the same point scalars and no vectors:
a CFD-like mesh holding one scalar, which the quick look shows as a volume.
usage: make_scalar_mesh.py IN.vti OUT.vtu"""
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridWriter

reader = vtkXMLImageDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
image = reader.GetOutput()
nx, ny, nz = image.GetDimensions()
mesh = vtkUnstructuredGrid()

points = vtkPoints()
points.SetNumberOfPoints(image.GetNumberOfPoints())
for p in range(image.GetNumberOfPoints()):
    points.SetPoint(p, image.GetPoint(p))
mesh.SetPoints(points)
mesh.Allocate((nx - 1) * (ny - 1) * (nz - 1))
index = lambda i, j, k: i + nx * (j + ny * k)
for k in range(nz - 1):
    for j in range(ny - 1):
        for i in range(nx - 1):
            mesh.InsertNextCell(VTK_HEXAHEDRON, 8, [
                index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k), index(i, j + 1, k),
                index(i, j, k + 1), index(i + 1, j, k + 1), index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)])
mesh.GetPointData().ShallowCopy(image.GetPointData())
assert mesh.GetPointData().GetVectors() is None
writer = vtkXMLUnstructuredGridWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputData(mesh)
assert writer.Write() == 1
print(f"{sys.argv[2]}: {mesh.GetNumberOfCells()} hexahedra, {mesh.GetNumberOfPoints()} points")
