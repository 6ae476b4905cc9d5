"""pvbatch: more than one image piece on one process. carotid.vtk cut into two
slabs (Extract Subset, sharing the plane i = 37) and grouped into one
multiblock, shown as "Plume Volume", renders as the whole image shown the
same way (within one 8-bit level on >= 99.5 % of the pixels): the
representation merges pieces of one grid that tile a box (vtkPlumeImageInput).
Drawing the first piece only, as before, loses half the vessels."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plume_pvtest as T
import plume_scenes
from paraview import simple

T.load_plugin()
source = T.carotid()
v = T.view()
whole_rep = plume_scenes.volume(source, v)
whole = T.render_image(v)
simple.Hide(source, v)  # one view for both: every new view is a new X window

left = simple.ExtractSubset(Input=source, VOI=[0, 37, 0, 48, 0, 44])
right = simple.ExtractSubset(Input=source, VOI=[37, 75, 0, 48, 0, 44])
group = simple.GroupDatasets(Input=[left, right])
rep = plume_scenes.volume(group, v)
pieces = T.render_image(v)
from PIL import Image

Image.fromarray(pieces).save(os.path.join(T.OUT, "PlumeVolumePieces.png"))
ok, share, worst = T.compare(pieces, whole, levels=1, fraction=0.995)
print("two pieces vs the whole image: %.3f %% of pixels within 1 level (max %d)" % (100 * share, worst))
T.finish(ok and T.not_blank(pieces, v.Background) > 0.02)
