"""pvbatch: the plugin's 'lines' scene (plume_scenes.py) on carotid.vtk
(through the XML image reader, see plume_pvtest.carotid_xml) renders
as the baseline Baseline/PlumeVelocityLines.png (within 2 levels on 99.5 % of the
pixels) and draws on at least 2 % of the image.

Then the same scene with the glyph scale left at its default ('lines_auto'):
the default must be the automatic scale, i.e. render the same image (within 1
level on 99.9 % of the pixels) as a fixed scale set to the automatic scale
computed here with numpy (two grid cells at the 99th percentile of the speeds:
plume_pvtest.automatic_scale, what the plume command line chooses), and a
different image from the fixed scale 1 (under 99 % of the pixels within 1
level). With the old default (fixed, 1) the first check fails."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from PIL import Image

import plume_pvtest as T
import plume_scenes
from paraview import simple

T.load_plugin()
v = T.view()
rep = plume_scenes.lines(T.carotid_xml(), v)
image = T.render_image(v)
drawn = T.not_blank(image, v.Background)
print("drawn on %.1f %% of the pixels" % (100 * drawn))
ok = drawn > 0.02 and T.check_baseline(image, "PlumeVelocityLines")
source = rep.Input
simple.Delete(rep)

rep = plume_scenes.lines_auto(source, v)
auto = T.render_image(v)
data = source.GetClientSideObject().GetOutputDataObject(0)
reference = T.automatic_scale(data)
print("default scale mode %s; automatic scale (numpy) %.9g: 2 cells %g at the robust speed %.9g" %
      (rep.PlumeLinesScaleMode, reference, max(data.GetSpacing()), T.robust_speed(data)))
rep.PlumeLinesScaleMode = "fixed"
rep.PlumeLinesScale = reference
fixed = T.render_image(v)
rep.PlumeLinesScale = 1.0
one = T.render_image(v)
same, share_same, worst_same = T.compare(auto, fixed, levels=1, fraction=0.999)
_, share_one, worst_one = T.compare(auto, one, levels=1)
print("default vs fixed at the automatic scale: %.3f %% of pixels within 1 level (max %d); "
      "vs fixed scale 1: %.3f %% (max %d)" % (100 * share_same, worst_same, 100 * share_one, worst_one))
print("drawn: default %.2f %%, scale 1 %.2f %% of the pixels" %
      (100 * T.not_blank(auto, v.Background), 100 * T.not_blank(one, v.Background)))
for name, img in (("PlumeVelocityLinesDefault", auto), ("PlumeVelocityLinesScale1", one)):
    Image.fromarray(img).save(os.path.join(T.OUT, name + ".png"))
if not same:
    print("FAIL: the default lines are not drawn at the automatic scale")
    ok = False
if share_one >= 0.99:
    print("FAIL: the default lines look like the fixed scale 1")
    ok = False
T.finish(ok)
