"""pvbatch: "Plume Volume" next to opaque ParaView geometry.

The volume scene (plume_scenes.py, carotid.vti) with an opaque plane (a
ParaView Plane source, Surface representation) through it at z = 23, the
grid plane k = 22, wide enough to hide every part of the volume below it
from the camera, which looks down on it. The volume must stop at the
plane's depth: the picture must equal an independent reference, the plane
with only the part of the volume above it (Extract Subset k >= 22) rendered
over it with the mapper's opaque depth switched off (UseOpaqueDepth = 0:
nothing of that part lies behind the plane), within one 8-bit level on
>= 99.5 % of the pixels. The control: the whole volume with the opaque depth
switched off (what a mapper that ignored the depth buffer would draw)
must fail that comparison, and the volume in front of the plane must show
(>= 2 % of the pixels differ from the plane alone). The picture is also compared with
Baseline/PlumeVolumeOpaque.png (2 levels, 99.5 %).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from PIL import Image

import plume_pvtest as T
import plume_scenes
from paraview import simple

T.load_plugin()
source = T.carotid_xml()
v = T.view()

Z = 23.0  # carotid's grid plane k = 22 (origin z = 1, spacing 1)
M = 60.0  # margin around the data's x-y bounds: every ray to the volume below the plane crosses it
x0, x1, y0, y1 = T.BOUNDS[0] - M, T.BOUNDS[1] + M, T.BOUNDS[2] - M, T.BOUNDS[3] + M
plane = simple.Plane(Origin=[x0, y0, Z], Point1=[x1, y0, Z], Point2=[x0, y1, Z])
plane_rep = simple.Show(plane, v)
plane_rep.Representation = "Surface"
plane_rep.ColorArrayName = [None, ""]
plane_rep.DiffuseColor = [0.80, 0.78, 0.70]
plane_rep.AmbientColor = [0.80, 0.78, 0.70]


def render(src, name, opaque_depth=1):
    rep = plume_scenes.volume(src, v)
    rep.PlumeVolumeUseOpaqueDepth = opaque_depth
    image = T.render_image(v)
    Image.fromarray(image).save(os.path.join(T.OUT, name + ".png"))
    simple.Hide(src, v)  # one view for every render: every new view is a new X window
    return image


plane_only = T.render_image(v)
got = render(source, "PlumeVolumeOpaque-render")
above = simple.ExtractSubset(Input=source, VOI=[0, 75, 0, 48, 22, 44])
expected = render(above, "PlumeVolumeOpaque-reference", opaque_depth=0)
ignored = render(source, "PlumeVolumeOpaque-depth-ignored", opaque_depth=0)

ok, share, worst = T.compare(got, expected, levels=1, fraction=0.995)
print("volume and plane vs the part above the plane over it: %.3f %% of pixels within 1 level (max %d)" %
      (100 * share, worst))
control, cshare, cworst = T.compare(ignored, expected, levels=1, fraction=0.995)
print("control, the depth ignored: %.3f %% of pixels within 1 level (max %d)" % (100 * cshare, cworst))
if control:
    print("FAIL: the control passes: the scene cannot tell whether the volume stops at the plane")
# the part of the volume in front of the plane shows over it
drawn = float((np.abs(got.astype(np.int32) - plane_only.astype(np.int32)).max(axis=2) > 8).mean())
print("the volume changes %.1f %% of the pixels of the plane alone" % (100 * drawn))
T.finish(ok and not control and drawn > 0.02 and T.check_baseline(got, "PlumeVolumeOpaque"))
