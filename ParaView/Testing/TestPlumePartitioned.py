"""pvbatch: partitioned inputs (vtkPartitionedDataSet, the composite type of
ParaView 5.10+'s readers and partitioners, and vtkPartitionedDataSetCollection).

carotid (XML image reader) is cut into two slabs sharing the plane i = 37
(Extract Subset) and grouped by Group Datasets into a vtkPartitionedDataSet
of the two slabs, or a vtkPartitionedDataSetCollection of two partitioned
datasets of one slab each. ParaView must offer the Plume representations for them, and:
- "Plume Volume" and "Plume Velocity Lines" (the scenes of plume_scenes.py)
  render as the whole image does, within one 8-bit level on >= 99.5 % of the
  pixels (vtkPlumeImageInput merges the slabs into one image);
- Contour keeps the partitions (one polydata per slab), and the contour shown
  as "Plume Smoke Sheet" renders as the sheet baseline
  Baseline/PlumeSmokeSheet.png (the same scene on the whole image), within 2
  levels on >= 99.5 % (the sheet representation appends the partitions).
Drawing the first partition only loses half the vessels (checked: the
volume of the first slab alone fails the comparison).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from PIL import Image

import plume_pvtest as T
import plume_scenes
from paraview import simple


def partitioned(inputs, kind):
    """Group Datasets (ParaView 5.10+ makes any of the composite types): each
    input a partition of one vtkPartitionedDataSet, or a partitioned dataset
    of its own in a vtkPartitionedDataSetCollection."""
    group = simple.GroupDatasets(Input=inputs)
    group.OutputType = kind
    group.UpdatePipeline()
    data = group.GetClientSideObject().GetOutputDataObject(0)
    assert data.IsA(kind), "Group Datasets gave %s, not %s" % (data.GetClassName(), kind)
    return group


T.load_plugin()
source = T.carotid_xml()
halves = [simple.ExtractSubset(Input=source, VOI=[0, 37, 0, 48, 0, 44]),
          simple.ExtractSubset(Input=source, VOI=[37, 75, 0, 48, 0, 44])]
v = T.view()
ok = True


def render(scene, src, name):
    rep = scene(src, v)
    image = T.render_image(v)
    Image.fromarray(image).save(os.path.join(T.OUT, name + ".png"))
    simple.Hide(src, v)  # one view for every render: every new view is a new X window
    return rep, image


def same(got, expected, what, levels=1):
    ok, share, worst = T.compare(got, expected, levels=levels, fraction=0.995)
    drawn = T.not_blank(got, v.Background)
    print("%s: %.3f %% of pixels within %d level(s) (max %d), drawn on %.1f %%" %
          (what, 100 * share, levels, worst, 100 * drawn))
    return ok and drawn > 0.02


_, whole_volume = render(plume_scenes.volume, source, "PlumePartitioned-volume-whole")
_, whole_lines = render(plume_scenes.lines, source, "PlumePartitioned-lines-whole")
for kind in ("vtkPartitionedDataSet", "vtkPartitionedDataSetCollection"):
    slabs = partitioned(halves, kind)
    offered = simple.Show(slabs, v).GetProperty("Representation").Available
    simple.Hide(slabs, v)
    print("%s of images: representations offered %s" % (kind, offered))
    for text in ("Plume Volume", "Plume Velocity Lines"):
        if text not in offered:
            print("FAIL: %s not offered for a %s of images" % (text, kind))
            ok = False
    _, got = render(plume_scenes.volume, slabs, "PlumePartitioned-volume-" + kind)
    ok = same(got, whole_volume, "%s as Plume Volume vs the whole image" % kind) and ok
    _, got = render(plume_scenes.lines, slabs, "PlumePartitioned-lines-" + kind)
    ok = same(got, whole_lines, "%s as Plume Velocity Lines vs the whole image" % kind) and ok

# the control: one slab alone (what a first-partition-only input would draw) fails
first = partitioned(halves[:1], "vtkPartitionedDataSet")
_, got = render(plume_scenes.volume, first, "PlumePartitioned-volume-first")
if same(got, whole_volume, "control: the first slab alone vs the whole image"):
    print("FAIL: the control passes: the comparison cannot tell one slab from both")
    ok = False

# the sheet: Contour of the partitioned slabs is partitioned polydata
slabs = partitioned(halves, "vtkPartitionedDataSet")
rep = plume_scenes.sheet(slabs, v)
contour = rep.Input
contour.UpdatePipeline()
data = contour.GetClientSideObject().GetOutputDataObject(0)
print("Contour of the slabs: %s of %d partitions" % (data.GetClassName(), data.GetNumberOfPartitions()
                                                    if data.IsA("vtkPartitionedDataSet") else -1))
if not data.IsA("vtkPartitionedDataSet") or data.GetNumberOfPartitions() != 2:
    print("FAIL: the contour is not a vtkPartitionedDataSet of 2 polydata")
    ok = False
offered = rep.GetProperty("Representation").Available
if "Plume Smoke Sheet" not in offered:
    print("FAIL: Plume Smoke Sheet not offered for a vtkPartitionedDataSet of polydata: %s" % offered)
    ok = False
image = T.render_image(v)
drawn = T.not_blank(image, v.Background)
print("partitioned contour as Plume Smoke Sheet: drawn on %.1f %%" % (100 * drawn))
ok = T.check_baseline(image, "PlumeSmokeSheet", output="PlumePartitioned-sheet") and drawn > 0.02 and ok
T.finish(ok)
