"""Shared by the plugin's pvbatch tests (run by scripts/test-paraview.sh).

Environment: PLUME_PLUGIN (the built PlumeParaView.so), PLUME_DATA_DIR,
PLUME_TEST_OUT (rendered images go there), PLUME_BASELINES.
"""
import os
import sys
import time

import numpy as np
from PIL import Image

from paraview import simple
from paraview.modules.vtkRemotingCore import vtkProcessModule

SIZE = [400, 300]
OUT = os.environ.get("PLUME_TEST_OUT", ".")
BASELINES = os.environ.get("PLUME_BASELINES", os.path.join(os.path.dirname(__file__), "Baseline"))
DATA = os.environ.get("PLUME_DATA_DIR", "/work/shared/data")


def rank():
    return vtkProcessModule.GetProcessModule().GetPartitionId()


def ranks():
    return vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def log(*args):
    if rank() == 0:
        print(*args, flush=True)


def load_plugin():
    simple.LoadPlugin(os.environ["PLUME_PLUGIN"], remote=False)


def carotid():
    """Image data 76x49x45: point arrays 'scalars' (0-580) and 'vectors' (|v| 0-22.7)."""
    return simple.LegacyVTKReader(FileNames=[os.path.join(DATA, "classic", "carotid.vtk")])


def carotid_xml():
    """carotid.vtk converted once to .vti (inline binary) and read by the XML
    image reader: the reader that splits an image into slabs over MPI ranks,
    and the one whose velocity-line image is reproducible (from the legacy
    reader's output the lines showed specks that changed from run to run)."""
    vti = os.path.join(OUT, "carotid.vti")
    if not os.path.exists(vti):
        import vtk

        reader = vtk.vtkDataSetReader()
        reader.SetFileName(os.path.join(DATA, "classic", "carotid.vtk"))
        reader.Update()
        writer = vtk.vtkXMLImageDataWriter()
        writer.SetFileName(vti + ".part.%d" % os.getpid())
        writer.SetInputData(reader.GetOutput())
        writer.SetDataModeToBinary()  # inline: the appended forms failed to parse in 5.11
        writer.Write()
        os.replace(vti + ".part.%d" % os.getpid(), vti)  # whole or absent
    return simple.XMLImageDataReader(FileName=[vti])


def view(camera=None):
    v = simple.CreateView("RenderView")
    v.ViewSize = SIZE
    v.OrientationAxesVisibility = 0
    v.Background = [0.32, 0.34, 0.43]
    try:
        v.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return v


# carotid.vtk's bounds: every scene is framed on them, the same way on every
# rank and in serial (no reset on the first render, which would use the
# bounds of what each test shows).
BOUNDS = [100.0, 175.0, 80.0, 128.0, 1.0, 45.0]
simple._DisableFirstRenderCameraReset()


def frame(v):
    center = [(BOUNDS[2 * i] + BOUNDS[2 * i + 1]) / 2 for i in range(3)]
    v.CameraFocalPoint = center
    v.CameraPosition = [center[0] - 77.5, center[1] - 64.0, center[2] + 87.0]
    v.CameraViewUp = [0, 0, 1]
    v.CameraParallelProjection = 0
    v.CameraViewAngle = 30
    v.SMProxy.ResetCamera(BOUNDS)


def render_image(v):
    """The view's image as an HxWx3 uint8 array on rank 0 (the composite of
    all ranks); None on the other ranks (which take part in the render)."""
    frame(v)
    simple.Render(v)
    path = os.path.join(OUT, "_capture.png")
    simple.SaveScreenshot(path, v, ImageResolution=SIZE)
    if rank() != 0:
        return None
    return np.asarray(Image.open(path).convert("RGB"))


def screenshot(v, name):
    path = os.path.join(OUT, name + ".png")
    simple.SaveScreenshot(path, v, ImageResolution=SIZE)
    return np.asarray(Image.open(path).convert("RGB")), path


def compare(a, b, levels=1, fraction=0.995):
    """(ok, share of pixels within `levels` 8-bit levels in every channel, max difference)."""
    diff = np.abs(a.astype(np.int32) - b.astype(np.int32)).max(axis=2)
    share = float((diff <= levels).mean())
    return share >= fraction, share, int(diff.max())


def check_baseline(image, name, levels=2, fraction=0.995, output=None):
    """Compares with Baseline/<name>.png; writes the rendered image to the test
    output as <output or name>.png."""
    rendered = os.path.join(OUT, (output or name) + ".png")
    Image.fromarray(image).save(rendered)
    baseline = os.path.join(BASELINES, name + ".png")
    if not os.path.exists(baseline):
        print("no baseline %s (rendered: %s)" % (baseline, rendered))
        return False
    ref = np.asarray(Image.open(baseline).convert("RGB"))
    if ref.shape != image.shape:
        print("baseline %s is %s, rendered %s" % (baseline, ref.shape, image.shape))
        return False
    ok, share, worst = compare(image, ref, levels, fraction)
    print("%s: %.3f %% of pixels within %d levels of the baseline (max difference %d)" %
          (name, 100 * share, levels, worst))
    return ok


def robust_speed(image, array="vectors"):
    """The 99th percentile of the finite speeds of an image's point vectors,
    computed here (numpy), not by Plume: the element of rank
    floor(0.99 (n - 1)), each speed rounded to float as the glyph mapper
    stores it. Without nodes: None."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    vectors = image.GetPointData().GetArray(array) if image else None
    if vectors is None or vectors.GetNumberOfTuples() == 0:
        return None
    v = vtk_to_numpy(vectors).astype(np.float32).astype(np.float64)
    v = v[np.isfinite(v).all(axis=1)]
    speeds = np.sqrt(v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1] + v[:, 2] * v[:, 2]).astype(np.float32)
    k = int(np.floor(0.99 * (speeds.size - 1)))
    return float(np.partition(speeds, k)[k])


def automatic_scale(image, stride=1):
    """The glyph scale SCALE_AUTO should choose (as the plume command line
    does): two grid cells (the largest spacing) times the lattice stride at
    the robust maximum speed."""
    cell = max(abs(s) for s, d in zip(image.GetSpacing(), image.GetDimensions()) if d > 1)
    return 2.0 * cell * stride / robust_speed(image)


def not_blank(image, background, minimum=0.02):
    """Share of pixels that differ from the background (the representation drew something)."""
    bg = np.array([round(255 * c) for c in background])
    drawn = np.abs(image.astype(np.int32) - bg).max(axis=2) > 8
    return float(drawn.mean())


def finish(ok):
    if not ok:
        print("FAILED", flush=True)
        # sys.exit inside pvbatch crashes its finalization (SIGSEGV, measured):
        # leave with the status directly.
        sys.stdout.flush()
        sys.stderr.flush()
        import ctypes

        ctypes.CDLL(None).fflush(None)  # pvbatch prints through C stdio
        os._exit(1)
    print("OK", flush=True)
