"""pvbatch: a vtkOverlappingAMR source shown as "Plume Volume".

ParaView shows overlapping AMR with its AMRRepresentation; the plugin adds
"Plume Volume" (and "Plume Velocity Lines") to it. The source is ParaView's
AMR Gaussian Pulse Source (two levels, refinement ratio 2, the pulse as a
cell array "Gaussian-Pulse", pulse moved off-centre so the scene is not
symmetric). The representation resamples the levels onto one image at the
finest spacing (vtkPlumeImageInput): with cell data, at the centres of the
finest lattice's cells, each taking the value of the finest level's cell
holding it. The picture must equal that of an independent reference: the
same lattice built here with numpy from the AMR blocks (each block's cells
repeated by its refinement factor, finer levels written over coarser ones)
and shown as one plain image of point data, within one 8-bit level on
>= 99.5 % of the pixels. The numpy lattice is also checked against VTK's own
resampler (vtkResampleToImage probing the AMR at the same cell centres).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from PIL import Image

import plume_pvtest as T
from paraview import simple

T.load_plugin()
amr = simple.AMRGaussianPulseSource()
# the source's blocks: level 0 over [-2, 0.5] x [-2, 0.5] x [0, 2.5]
# (spacing 0.5), two level-1 blocks (spacing 0.25) with a coarse gap
# between them at -1 < x < -0.5; the pulse straddles all three
amr.XPulseOrigin = -0.7
amr.YPulseOrigin = -0.9
amr.ZPulseOrigin = 1.1
amr.XPulseWidth = 0.8
amr.YPulseWidth = 0.6
amr.ZPulseWidth = 0.9
amr.PulseAmplitude = 1.0
amr.UpdatePipeline()
v = T.view()
NAME = "Gaussian-Pulse"

# --- the reference lattice, built from the blocks with numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
import vtk

data = amr.GetClientSideObject().GetOutputDataObject(0)
assert data.IsA("vtkOverlappingAMR"), data.GetClassName()
blocks = []
for level in range(data.GetNumberOfLevels()):
    for index in range(data.GetNumberOfDataSets(level)):
        block = data.GetDataSet(level, index)
        if block is not None and block.GetNumberOfCells() > 0:
            blocks.append((level, block))
levels = sorted(set(level for level, _ in blocks))
assert len(levels) >= 2, "the source should give at least two levels, got %s" % levels
print("AMR: %d blocks on levels %s" % (len(blocks), levels))
for level, block in blocks:
    print("  level %d: origin %s, spacing %g, %s points" %
          (level, block.GetOrigin(), block.GetSpacing()[0], block.GetDimensions()))
bounds = [0.0] * 6
data.GetBounds(bounds)
h = min(block.GetSpacing()[0] for _, block in blocks)
lo = np.array(bounds[0::2])
cells = np.rint((np.array(bounds[1::2]) - lo) / h).astype(int)  # x, y, z
low = min(block.GetCellData().GetArray(NAME).GetRange()[0] for _, block in blocks)
lattice = np.full(cells[::-1], low, dtype=np.float64)  # z, y, x
for level, block in sorted(blocks, key=lambda b: b[0]):  # coarse first, finer written over it
    r = int(round(block.GetSpacing()[0] / h))
    start = np.rint((np.array(block.GetOrigin()) - lo) / h).astype(int)
    n = np.array(block.GetDimensions()) - 1  # cells along x, y, z
    values = vtk_to_numpy(block.GetCellData().GetArray(NAME)).astype(np.float64).reshape(n[::-1])
    fine = values.repeat(r, axis=0).repeat(r, axis=1).repeat(r, axis=2)
    lattice[start[2]:start[2] + r * n[2], start[1]:start[1] + r * n[1], start[0]:start[0] + r * n[0]] = fine
print("bounds %s, finest spacing %g, lattice %s cells" % (bounds, h, list(cells)))

image = vtk.vtkImageData()
image.SetOrigin(*(lo + 0.5 * h))
image.SetSpacing(h, h, h)
image.SetDimensions(*cells)
array = numpy_to_vtk(lattice.astype(np.float32).reshape(-1), deep=1)
array.SetName(NAME)
image.GetPointData().SetScalars(array)

# VTK's resampler at the same centres: the numpy lattice is what VTK means by
# "the finest level's value there" (blanked coarse cells are skipped)
try:
    resample = vtk.vtkResampleToImage()
except AttributeError:
    from vtkmodules.vtkFiltersCore import vtkResampleToImage

    resample = vtkResampleToImage()
resample.SetInputDataObject(data)
resample.UseInputBoundsOff()
resample.SetSamplingBounds(image.GetBounds())
resample.SetSamplingDimensions(*cells)
resample.Update()
probed = vtk_to_numpy(resample.GetOutput().GetPointData().GetArray(NAME)).astype(np.float64)
valid = vtk_to_numpy(resample.GetOutput().GetPointData().GetArray("vtkValidPointMask")) != 0
gap = float(np.abs(probed[valid] - lattice.reshape(-1)[valid]).max())
print("numpy lattice vs vtkResampleToImage: %d of %d samples valid, max difference %.3g" %
      (int(valid.sum()), valid.size, gap))
assert valid.mean() > 0.99 and gap < 1e-6, "the numpy reference disagrees with vtkResampleToImage"


def style(rep, association):
    simple.ColorBy(rep, (association, NAME))
    lut = simple.GetColorTransferFunction(NAME)
    lut.ApplyPreset("Inferno (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, 1.0)
    pwf = simple.GetOpacityTransferFunction(NAME)
    pwf.Points = [0.0, 0.0, 0.5, 0.0, 0.05, 0.0, 0.5, 0.0, 1.0, 0.9, 0.5, 0.0]
    pwf.RescaleTransferFunction(0.0, 1.0)
    rep.PlumeVolumeOpacityUnitDistance = 0.3


def render():
    center = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    v.CameraFocalPoint = center
    v.CameraPosition = [center[0] + 4.0, center[1] - 6.0, center[2] + 3.0]
    v.CameraViewUp = [0, 0, 1]
    v.CameraViewAngle = 30
    v.SMProxy.ResetCamera(list(bounds))
    simple.Render(v)
    path = os.path.join(T.OUT, "_capture.png")
    simple.SaveScreenshot(path, v, ImageResolution=T.SIZE)
    return np.asarray(Image.open(path).convert("RGB"))


producer = simple.PVTrivialProducer()
producer.GetClientSideObject().SetOutput(image)
ref_rep = simple.Show(producer, v)
ref_rep.Representation = "Plume Volume"
style(ref_rep, "POINTS")
expected = render()
simple.Hide(producer, v)  # one view for both: every new view is a new X window

rep = simple.Show(amr, v)
offered = rep.GetProperty("Representation").Available
print("representations offered for the AMR source:", offered)
if "Plume Volume" not in offered:
    print("ParaView does not offer Plume Volume for vtkOverlappingAMR")
    T.finish(False)
rep.Representation = "Plume Volume"
style(rep, "CELLS")
got = render()
Image.fromarray(expected).save(os.path.join(T.OUT, "PlumeVolumeAMR-reference.png"))
Image.fromarray(got).save(os.path.join(T.OUT, "PlumeVolumeAMR.png"))
ok, share, worst = T.compare(got, expected, levels=1, fraction=0.995)
print("AMR as Plume Volume vs the numpy lattice: %.3f %% of pixels within 1 level (max %d)" % (100 * share, worst))
drawn = T.not_blank(got, v.Background)
print("drawn on %.1f %% of the image" % (100 * drawn))
lines_offered = "Plume Velocity Lines" in offered
print("Plume Velocity Lines offered:", lines_offered)
T.finish(ok and drawn > 0.02 and lines_offered)
