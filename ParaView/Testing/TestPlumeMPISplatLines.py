"""Flow lines cut over MPI ranks splat as the uncut lines do.

Run twice by scripts/test-paraview.sh (like TestPlumeMPI): with one rank it
writes the serial velocity grid of six whole helical polylines; under
`mpirun -np 2 pvbatch --symmetric` each rank's piece of the "Plume Gaussian
Splat" output must equal that grid over the piece's extent within 1e-5 of
its maximum (float sums in another order).

The lines' source (a Programmable Source that handles pieces) gives each of
the 2 ranks its piece of every line, the three ways ranks and partitioners
leave them:
  lines 0, 1  cut at vertex 30; both ranks hold vertex 30, unflagged ("owned
              by both": the continuation rule, line starts exchanged over ranks)
  lines 2, 3  cut at vertex 30; rank 0's copy flagged DUPLICATEPOINT
  lines 4, 5  whole on both ranks; on the rank that does not own it the cell
              is flagged DUPLICATECELL
Splatted twice, a shared vertex adds a whole splat (and the backward
difference): broken once (no exchange of line starts), 0.163 of the maximum.
The same run also checks the filter's velocity mode over ranks, which had
failed before ("no field to combine": the field is the active vectors).
"""
import builtins
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np

import plume_pvtest as T
from paraview import simple

T.load_plugin()
SERIAL = T.ranks() == 1

from paraview.modules.vtkRemotingCore import vtkProcessModule

controller = vtkProcessModule.GetProcessModule().GetGlobalController()

LINES_SCRIPT = r"""
import math
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataSetAttributes
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER()) if info.Has(sddp.UPDATE_PIECE_NUMBER()) else 0
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES()) if info.Has(sddp.UPDATE_NUMBER_OF_PIECES()) else 1
N, CUT = 60, 30
pts = vtkPoints()
pts.SetDataTypeToDouble()
cells = vtkCellArray()
pg = vtkUnsignedCharArray()
pg.SetName(vtkDataSetAttributes.GhostArrayName())
cg = vtkUnsignedCharArray()
cg.SetName(vtkDataSetAttributes.GhostArrayName())
def vertex(line, i):
    t = 0.11 * i + 1.1 * line
    return (3.0 * math.cos(t) + 0.4 * line, 3.0 * math.sin(t), 0.15 * i - 0.3 * line)
def add(line, a, b, last_flag=0, cell_flag=0):
    cells.InsertNextCell(b - a + 1)
    for i in range(a, b + 1):
        cells.InsertCellPoint(pts.InsertNextPoint(vertex(line, i)))
        pg.InsertNextValue(last_flag if i == b else 0)
    cg.InsertNextValue(cell_flag)
for line in range(6):
    if pieces == 1:
        add(line, 0, N - 1)
    elif line < 4:
        if piece == 0:
            add(line, 0, CUT, vtkDataSetAttributes.DUPLICATEPOINT if line >= 2 else 0)
        elif piece == 1:
            add(line, CUT, N - 1)
    else:
        owner = line - 4
        if piece < 2:
            add(line, 0, N - 1, 0, 0 if piece == owner else vtkDataSetAttributes.DUPLICATECELL)
out = self.GetPolyDataOutput()
out.SetPoints(pts)
out.SetLines(cells)
out.GetPointData().AddArray(pg)
out.GetCellData().AddArray(cg)
"""
INFO_SCRIPT = r"""
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""

lines = simple.ProgrammableSource(OutputDataSetType="vtkPolyData", Script=LINES_SCRIPT,
                                  ScriptRequestInformation=INFO_SCRIPT)
# no points: an empty point set as the required first input
empty = simple.ProgrammableSource(OutputDataSetType="vtkPolyData", Script="")
splatter = simple.PlumeGaussianSplat(Input=empty, Lines=lines)
splatter.Mode = "velocity"
splatter.Radius = 0.5
splatter.Dimensions = [40, 40, 44]
splatter.UpdatePipeline()

import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

held = lines.GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells()
image = splatter.GetClientSideObject().GetOutputDataObject(0)
field = vtk_to_numpy(image.GetPointData().GetArray("velocity")).astype(np.float64).reshape(-1, 3)
extent = image.GetExtent()
path = os.path.join(T.OUT, "PlumeSplatLines-serial-velocity.npz")
ok = True
if SERIAL:
    np.savez(path, velocity=field, extent=np.array(extent))
    print("serial velocity grid written (%d line cells, extent %s, max |v| %.4g)" %
          (held, list(extent), np.abs(field).max()))
else:
    ref = np.load(path)
    e = ref["extent"]
    whole = ref["velocity"].reshape(e[5] - e[4] + 1, e[3] - e[2] + 1, e[1] - e[0] + 1, 3)
    piece = whole[extent[4] - e[4]:extent[5] - e[4] + 1, extent[2] - e[2]:extent[3] - e[2] + 1,
                  extent[0] - e[0]:extent[1] - e[0] + 1].reshape(-1, 3)
    local = float(np.abs(piece - field).max() / np.abs(whole).max()) if piece.shape == field.shape else 1.0
    send = vtk.vtkDoubleArray()
    send.InsertNextValue(local)
    send.InsertNextValue(held)
    recv = vtk.vtkDoubleArray()
    controller.AllGather(send, recv)
    # builtins': the Programmable Source's script runs in this module's namespace and
    # brings numpy_interface.algorithms' max along
    worst = builtins.max(recv.GetValue(2 * i) for i in range(T.ranks()))
    cells = [int(recv.GetValue(2 * i + 1)) for i in range(T.ranks())]
    T.log("PlumeSplatLines: line cells per rank %s; each rank's piece vs the serial grid: max difference "
          "%.2e of the maximum (bound 1e-5)" % (cells, worst))
    ok = worst <= 1e-5 and builtins.min(cells) > 0
T.finish(ok)
