"""The scene of each representation test, shared by the serial tests and the
2-rank MPI test (which renders the same scenes with the data distributed).

Each function builds its pipeline from `source` (a reader of carotid.vtk's
image data; in the MPI test a parallel reader that gives each rank a slab),
shows it in `v` and returns the representation.
"""
from paraview import simple


def volume(source, v):
    rep = simple.Show(source, v)
    rep.Representation = "Plume Volume"
    simple.ColorBy(rep, ("POINTS", "scalars"))
    lut = simple.GetColorTransferFunction("scalars")
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(0.0, 580.0)
    pwf = simple.GetOpacityTransferFunction("scalars")
    pwf.Points = [0.0, 0.0, 0.5, 0.0, 100.0, 0.0, 0.5, 0.0, 580.0, 0.6, 0.5, 0.0]
    pwf.RescaleTransferFunction(0.0, 580.0)
    rep.PlumeVolumeOpacityUnitDistance = 2.0
    return rep


def volume_default(source, v):
    """Plume Volume as the first Apply leaves it: no colour array chosen, so
    the representation's default look over the active scalars' range."""
    rep = simple.Show(source, v)
    rep.Representation = "Plume Volume"
    simple.ColorBy(rep, ("POINTS", None))
    return rep


def sheet(source, v, redistribute=False):
    contour = simple.Contour(Input=source, ContourBy=["POINTS", "scalars"], Isosurfaces=[190.0])
    src = contour
    if redistribute:
        red = simple.RedistributeDataSet(Input=contour)
        src = simple.ExtractSurface(Input=red)
    rep = simple.Show(src, v)
    rep.Representation = "Plume Smoke Sheet"
    simple.ColorBy(rep, ("POINTS", None))
    rep.PlumeSheetDensity = 0.15
    rep.PlumeSheetBlurRadius = 0.6
    rep.PlumeSheetThickness = 0.6
    rep.PlumeSheetSmokeColor = [0.95, 0.92, 0.85]
    return rep


def lines(source, v):
    rep = lines_auto(source, v)
    rep.PlumeLinesScaleMode = "fixed"
    rep.PlumeLinesScale = 0.3
    return rep


def lines_auto(source, v):
    """The lines with the glyph scale left at its default (automatic: two
    grid cells at the 99th percentile of the speeds, over all ranks)."""
    rep = simple.Show(source, v)
    rep.Representation = "Plume Velocity Lines"
    simple.ColorBy(rep, ("POINTS", "vectors", "Magnitude"))
    lut = simple.GetColorTransferFunction("vectors")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, 12.0)
    # Every node of the lattice: the same roots however the grid is split.
    rep.PlumeLinesRootMode = "lattice"
    rep.PlumeLinesLatticeStride = 1
    # Opaque lines: ranks are composited by depth, which cannot blend a
    # translucent root over another rank's lines behind it.
    rep.PlumeLinesRootAlpha = 1.0
    rep.PlumeLinesMinimumSpeed = 1.5  # no specks from the still air around the vessels
    return rep


def lines_screen(source, v):
    """The lines with roots and scale at their defaults (screen-adaptive
    roots, automatic scale), as a first Apply leaves them but opaque and
    without the still air's specks: the stride (and with it the automatic
    length) comes from the whole image's footprint and moving nodes, and the
    roots from its lattice, whatever part of it a rank holds."""
    rep = lines_auto(source, v)
    rep.PlumeLinesRootMode = "screen"
    return rep


def splat(source, v):
    # Seeds at the common carotid's inflow (z = 1, where |v| > 8).
    seeds = simple.PointSource(Center=[113.0, 104.0, 2.0], Radius=3.0, NumberOfPoints=80)
    tracer = simple.StreamTracerWithCustomSource(Input=source, SeedSource=seeds)
    tracer.Vectors = ["POINTS", "vectors"]
    tracer.MaximumStreamlineLength = 100.0
    splatter = simple.PlumeGaussianSplat(Input=tracer, Lines=tracer)
    splatter.Mode = "density"  #: the lines' lengths and the points
    splatter.Radius = 1.0
    splatter.Dimensions = [72, 48, 44]
    rep = simple.Show(splatter, v)
    rep.Representation = "Plume Volume"
    simple.ColorBy(rep, ("POINTS", "density"))
    lut = simple.GetColorTransferFunction("density")
    lut.ApplyPreset("Inferno (matplotlib)", True)
    simple.GetOpacityTransferFunction("density")
    rep.RescaleTransferFunctionToDataRange(True, False)
    return rep


def splat_points(source, v):
    """The filter on a point set that splits over ranks without duplicates:
    the centres of the cells inside the vessels (every cell lies on exactly
    one rank, where image slabs share their boundary points). Density of the
    centres, shown as a volume."""
    inside = simple.Threshold(Input=source, Scalars=["POINTS", "scalars"])
    inside.LowerThreshold = 190.0
    inside.UpperThreshold = 1000.0
    centres = simple.CellCenters(Input=inside)
    splatter = simple.PlumeGaussianSplat(Input=centres)
    splatter.Mode = "density"
    splatter.Radius = 1.5
    splatter.Dimensions = [72, 48, 44]
    rep = simple.Show(splatter, v)
    rep.Representation = "Plume Volume"
    simple.ColorBy(rep, ("POINTS", "density"))
    lut = simple.GetColorTransferFunction("density")
    lut.ApplyPreset("Inferno (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, 0.5)
    pwf = simple.GetOpacityTransferFunction("density")
    pwf.Points = [0.0, 0.0, 0.5, 0.0, 0.5, 0.4, 0.5, 0.0]
    pwf.RescaleTransferFunction(0.0, 0.5)
    rep.PlumeVolumeOpacityUnitDistance = 2.0
    return rep
