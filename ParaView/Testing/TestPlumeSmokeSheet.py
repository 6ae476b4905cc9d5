"""pvbatch: the plugin's 'sheet' scene (plume_scenes.py) on carotid.vtk renders
as the baseline Baseline/PlumeSmokeSheet.png (within 2 levels on 99.5 % of the
pixels) and draws on at least 2 % of the image."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plume_pvtest as T
import plume_scenes

T.load_plugin()
v = T.view()
rep = plume_scenes.sheet(T.carotid(), v)
image = T.render_image(v)
drawn = T.not_blank(image, v.Background)
print("drawn on %.1f %% of the pixels" % (100 * drawn))
T.finish(drawn > 0.02 and T.check_baseline(image, "PlumeSmokeSheet"))
