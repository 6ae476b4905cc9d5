"""Plume: volumetric flow visualization for VTK.

``import plume`` next to ``import vtk`` (Debian's /usr/bin/python3): the
classes of every Plume module are available at the package level, e.g.
``plume.vtkPlumeVelocityGlyphMapper()``.
"""
# VTK's own wrapped modules must be importable first: Plume's wrappers depend on them.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .PlumeData import *  # noqa: F401,F403
from .PlumeRendering import *  # noqa: F401,F403
