"""Plume: volumetric flow visualization for VTK.

``import plume`` next to ``import vtk`` (Debian's /usr/bin/python3): the
classes of every Plume module are available at the package level, e.g.
``plume.vtkPlumeVelocityGlyphMapper()``.
"""
import importlib as _importlib
import os as _os

# VTK's own wrapped modules must be importable first: Plume's wrappers depend on them.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def _load_modules():
    """Import every wrapped Plume module (PlumeData, PlumeGlyphs, ...) found here."""
    here = _os.path.dirname(__file__)
    names = sorted({f.split(".")[0] for f in _os.listdir(here) if f.startswith("Plume") and f.endswith(".so")})
    for name in names:
        module = _importlib.import_module("." + name, __name__)
        for key in dir(module):
            if key.startswith("vtk"):
                globals()[key] = getattr(module, key)
    return names


modules = _load_modules()
