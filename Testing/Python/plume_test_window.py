"""Shared by Plume's Python tests: an offscreen window without multisampling
(identical pixels run to run, as the C++ tests' windows) and its float
read-back."""
import vtk


def offscreen_window(renderer, width, height):
    """An offscreen, non-multisampled width x height window showing `renderer`."""
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    return window


def read_rgba(window):
    """Render and return the frame as a flat list of float RGBA (bottom row first)."""
    window.Render()
    width, height = window.GetSize()
    rgba = vtk.vtkFloatArray()
    window.GetRGBAPixelData(0, 0, width - 1, height - 1, 0, rgba)
    return [rgba.GetValue(i) for i in range(rgba.GetNumberOfValues())]
