"""What the ParaView tests and benchmarks share (pvbatch, after LoadPlugin): the entries' menu names,
a view with a fixed background, the wavelet scene of the interaction test and benchmark (VTK's
wavelet shown through one of the plugin's entries, coloured and made transparent by RTData, seen
from 20 degrees above), the window's pixels as last rendered, PNG images compared pixel by pixel,
and what an entry's PrintSelf says (its classes are not wrapped in ParaView's Python).
"""
import re

from paraview import simple
from paraview.vtk.vtkRenderingCore import vtkWindowToImageFilter

ENTRIES = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
           "barycentric": "Volume (Barycentric Shells)"}


def new_view(size, background=(0.1, 0.1, 0.12)):
    """A render view of size x size pixels, no orientation axes, on a fixed background (not the
    colour palette's, where this ParaView has one), so that images compare across versions."""
    view = simple.CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    view.Background = list(background)
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def show_wavelet(entry, half_extent, size, tetrahedralize=None):
    """A new view of the wavelet on (2 half_extent)^3 cells, drawn by `entry`: as its own cells, or
    through `tetrahedralize` (the plugin's HexahedraToTetrahedra, which LoadPlugin put in the
    caller's namespace). Returns the view and the display."""
    wavelet = simple.Wavelet(WholeExtent=[-half_extent, half_extent - 1] * 3)
    data = tetrahedralize(Input=wavelet) if tetrahedralize else wavelet
    view = simple.CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    display = simple.Show(data, view)
    display.Representation = entry
    simple.ColorBy(display, ("POINTS", "RTData"))
    simple.GetColorTransferFunction("RTData").RescaleTransferFunction(37.0, 277.0)
    simple.GetOpacityTransferFunction("RTData").RescaleTransferFunction(37.0, 277.0)
    view.ResetCamera()
    view.GetActiveCamera().Elevation(20)
    view.GetActiveCamera().Azimuth(30)
    return view, display


def window_rgb(view):
    """The view's RGB as last rendered (not rendered again): a list of byte triples, and the image."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    image = grab.GetOutput()
    pixels = image.GetPointData().GetScalars()
    return [pixels.GetTuple3(i) for i in range(pixels.GetNumberOfTuples())], image


def rgb_rmse(a, b):
    """RMSE over two windows' RGB byte triples, in [0, 1]."""
    total = sum((x - y) ** 2 for p, q in zip(a, b) for x, y in zip(p, q))
    return (total / (3.0 * len(a))) ** 0.5 / 255.0


def png_rgb(path):
    """A PNG file's RGB as a numpy array of integers, a row per pixel."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(np.int32)


def pixels_off(first, second):
    """Between two png_rgb arrays: the share of pixels more than 2 levels off in some channel, and
    the largest difference."""
    import numpy as np
    difference = np.abs(first - second).max(axis=1)
    return float(np.mean(difference > 2)), int(difference.max())


def printed(vtk_object, name):
    """The value `vtk_object`'s PrintSelf gives for `name`, as text."""
    return re.search(re.escape(name) + r": ([^\n]*)", str(vtk_object)).group(1).strip()
