"""Drive Plume from Python next to VTK: load real data with
vtkPlumeDatasetReader, draw velocity glyph lines, and check the image."""
import os
import sys

import vtk  # Debian's VTK 9.1 wrappers
import plume
from plume_test_window import offscreen_window

data_dir = os.environ["PLUME_DATA_DIR"]

reader = plume.vtkPlumeDatasetReader()
reader.SetFileName(os.path.join(data_dir, "classic", "carotid.vtk"))
reader.Update()
image = reader.GetOutputDataObject(0)
assert image.IsA("vtkImageData"), image.GetClassName()
assert image.GetDimensions() == (76, 49, 45), image.GetDimensions()

mapper = plume.vtkPlumeVelocityGlyphMapper()
mapper.SetInputData(image)
mapper.SetVectorArrayName("vectors")
mapper.SetRootMode(plume.vtkPlumeVelocityGlyphMapper.ROOTS_LATTICE)
mapper.SetLatticeStride(2)
mapper.SetScaleMode(plume.vtkPlumeVelocityGlyphMapper.SCALE_FIXED)
mapper.SetScale(0.3)
mapper.SetRootAlpha(1.0)
lut = vtk.vtkColorTransferFunction()
lut.AddRGBPoint(0, 0, 0, 1)
lut.AddRGBPoint(20, 1, 0, 0)
mapper.SetLookupTable(lut)
mapper.SetUseDataRange(False)
mapper.SetScalarRange(0, 20)
actor = vtk.vtkActor()
actor.SetMapper(mapper)

renderer = vtk.vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(0, 0, 0)
window = offscreen_window(renderer, 300, 200)
renderer.ResetCamera()
window.Render()

grab = vtk.vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
pixels = grab.GetOutput().GetPointData().GetScalars()
rgb = [pixels.GetTuple3(i) for i in range(pixels.GetNumberOfTuples())]
lit = [p for p in rgb if max(p) > 30]
print("lit pixels:", len(lit), "of", len(rgb))
assert len(lit) > 500, "glyphs were not drawn"
# Colour follows magnitude: both slow (blue-dominant) and fast (red-dominant) glyphs appear.
assert any(p[2] > p[0] for p in lit) and any(p[0] > p[2] for p in lit), "no colour variation"
assert mapper.GetUploadCount() == 1
window.Render()
assert mapper.GetUploadCount() == 1, "re-render uploaded the texture again"
print("OK")
sys.exit(0)
