"""Writes the quick look's scalar density blob (plume_density.vti) as an
unstructured grid (vtkAppendFilter: its 20 007 cells as voxels) with the same
point scalars and no vectors: a CFD-like mesh of 3D cells holding one scalar,
which the quick look shows as a volume.
usage: make_scalar_mesh.py IN.vti OUT.vtu"""
import sys

from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridWriter

reader = vtkXMLImageDataReader()
reader.SetFileName(sys.argv[1])
mesh = vtkAppendFilter()
mesh.SetInputConnection(reader.GetOutputPort())
mesh.Update()
grid = mesh.GetOutput()
assert grid.GetPointData().GetVectors() is None
writer = vtkXMLUnstructuredGridWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputData(grid)
assert writer.Write() == 1
print(f"{sys.argv[2]}: {grid.GetNumberOfCells()} cells, {grid.GetNumberOfPoints()} points")
