"""Colouring by a cell array and by a vector's magnitude or component in each of the plugin's entries
(pvbatch), the way a ParaView user does it: ColorBy(display, ("CELLS", name)) and
ColorBy(display, ("POINTS", name, "Magnitude")).

    pvbatch test_plugin_arrays.py <plugin> <preintegrated|hexahedral|barycentric>

Checks, on the wavelet as an unstructured grid of 12^3 hexahedra:
- a vector (0.6 s, 0.8 s, 0) of the scalar s coloured by "Magnitude" gives the image of s, and by
  its "Y" component, with the colour map and opacity scaled by 0.8, the same image again (no pixel
  more than 3 levels off);
- the cell array (the point scalar averaged to the cells) renders without an error, covers what the
  point scalar covers and differs from it (it is constant in each cell); a constant cell array
  renders as the same constant point array does (no pixel more than 2 levels off);
- where ../shared/data is present, the OpenFOAM cavity's cell pressure "p" renders, and so do the
  triquadratic hexahedra (a cell array) and the quadratic cylinder (point data, tetrahedral entries).
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from pvscene import new_view  # beside this script
from vtkmodules.vtkCommonCore import vtkOutputWindow

plugin, mapper = sys.argv[1], sys.argv[2]
ENTRY = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
         "barycentric": "Volume (Barycentric Shells)"}[mapper]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
SIZE = 160


class ErrorCounter:
    """Counts the error and warning text VTK prints (ParaView routes it through vtkOutputWindow)."""

    def __init__(self):
        self.window = vtkOutputWindow.GetInstance()
        self.errors = 0
        self.window.AddObserver("ErrorEvent", self.count)

    def count(self, *args):
        self.errors += 1


view = new_view(SIZE, (0.0, 0.0, 0.0))
view.CameraPosition = [40.0, -30.0, 25.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0

wavelet = Wavelet(WholeExtent=[-6, 6, -6, 6, -6, 6])  # noqa: F405
grid = AppendDatasets(Input=wavelet)  # noqa: F405  (an unstructured grid of hexahedra)
vector = Calculator(Input=grid, ResultArrayName="vector", Function="0.6*RTData*iHat + 0.8*RTData*jHat")  # noqa: F405
averaged = PointDatatoCellData(Input=vector)  # noqa: F405
averaged.PassPointData = 1
# The same constant as a point and as a cell array: the two routes must give the same image.
flat_points = Calculator(Input=averaged, ResultArrayName="flat_points", Function="200")  # noqa: F405
cells = Calculator(Input=flat_points, AttributeType="Cell Data", ResultArrayName="flat_cells", Function="200")  # noqa: F405
LOW, HIGH = 37.0, 277.0


def colour_map(name, factor):
    lut = GetColorTransferFunction(name)  # noqa: F405
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(factor * LOW, factor * HIGH)
    opacity = GetOpacityTransferFunction(name)  # noqa: F405
    opacity.Points = [factor * LOW, 0.0, 0.5, 0.0, factor * 150.0, 0.05, 0.5, 0.0, factor * HIGH, 0.6, 0.5, 0.0]
    return lut, opacity


def render(association, name, factor=1.0, component=None):
    """The entry's image coloured by the array (a component name: "Magnitude", "X", "Y", ...)."""
    display = Show(cells, view)  # noqa: F405
    display.Representation = ENTRY
    ColorBy(display, (association, name) if component is None else (association, name, component))  # noqa: F405
    lut, opacity = colour_map(name, factor)
    display.Isovalues = []  # the volume alone (an isovalue of a cell scalar is not drawn)
    display.LookupTable = lut
    display.ScalarOpacityFunction = opacity
    display.ScalarOpacityUnitDistance = 3.0
    Render(view)  # noqa: F405
    path = os.path.join(os.environ.get("UV_TEST_OUTPUT", "/tmp"), f"arrays_{mapper}_{association}_{name}_{component}.png")
    SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])  # noqa: F405
    Hide(cells, view)  # noqa: F405
    return read_png(path)


def read_png(path):
    """A screenshot's pixels as RGB tuples."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    return [scalars.GetTuple3(i) for i in range(scalars.GetNumberOfTuples())]


def largest_difference(a, b):
    return max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))


def covered(image):
    return sum(1 for p in image if max(p) > 8)


errors = ErrorCounter()
scalar = render("POINTS", "RTData")
magnitude = render("POINTS", "vector", 1.0, "Magnitude")
component = render("POINTS", "vector", 0.8, "Y")
cell = render("CELLS", "RTData")
flat_cells, flat_points = render("CELLS", "flat_cells"), render("POINTS", "flat_points")
print(f"{ENTRY}: covered pixels, point scalar {covered(scalar)}, cell scalar {covered(cell)}; largest "
      f"difference to the point scalar: magnitude {largest_difference(scalar, magnitude):.0f}, component "
      f"{largest_difference(scalar, component):.0f}, cell scalar {largest_difference(scalar, cell):.0f}; "
      f"constant as cells against points: {largest_difference(flat_cells, flat_points):.0f}")
assert covered(scalar) > 1000
assert largest_difference(scalar, magnitude) <= 3
assert largest_difference(scalar, component) <= 3
assert abs(covered(cell) - covered(scalar)) < 0.1 * covered(scalar)
assert largest_difference(scalar, cell) > 2  # constant in each cell: not the point scalar's image
assert covered(flat_cells) > 1000
assert largest_difference(flat_cells, flat_points) <= 2

cavity = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data",
                      "openfoam_cavity", "cavity", "case.foam")
if os.path.exists(cavity):
    reader = OpenFOAMReader(FileName=cavity)  # noqa: F405
    reader.Createcelltopointfiltereddata = 0  # the data per cell, as OpenFOAM writes it
    reader.UpdatePipeline(max(reader.TimestepValues))
    foam = Show(reader, view)  # noqa: F405
    foam.Representation = ENTRY
    ColorBy(foam, ("CELLS", "p"))  # noqa: F405
    foam.RescaleTransferFunctionToDataRange(True)
    foam.Isovalues = []
    ResetCamera(view)  # noqa: F405
    Render(view)  # noqa: F405
    path = os.path.join(os.environ.get("UV_TEST_OUTPUT", "/tmp"), f"arrays_{mapper}_cavity_p.png")
    SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])  # noqa: F405
    print(f"OpenFOAM cavity coloured by cell p: {path}")
else:
    print("../shared/data absent: the OpenFOAM cavity is skipped")


def show_higher_order(name, association, array):
    """A higher-order mesh of ../shared/data/quadratic in the entry (subdivided on the way in);
    returns its covered pixel count, or None when the file is absent."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data",
                        "quadratic", name)
    if not os.path.exists(path):
        return None
    source = OpenDataFile(path)  # noqa: F405
    if association == "CELLS":  # a smooth field averaged to the cells (the file's own is constant)
        smooth = Calculator(Input=source, ResultArrayName=array, Function="coordsX + 2*coordsY + 3")  # noqa: F405
        source = PointDatatoCellData(Input=smooth)  # noqa: F405
    display = Show(source, view)  # noqa: F405
    display.Representation = ENTRY
    ColorBy(display, (association, array))  # noqa: F405
    display.RescaleTransferFunctionToDataRange(True)
    low, high = source.GetDataInformation().DataInformation.GetArrayInformation(
        array, 0 if association == "POINTS" else 1).GetComponentRange(0)
    GetOpacityTransferFunction(array).Points = [low, 0.1, 0.5, 0.0, high, 0.8, 0.5, 0.0]  # noqa: F405
    bounds = source.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * d + 1] - bounds[2 * d]) ** 2 for d in range(3)) ** 0.5
    display.ScalarOpacityUnitDistance = 0.2 * diagonal
    display.Isovalues = []
    ResetCamera(view)  # noqa: F405
    Render(view)  # noqa: F405
    shot = os.path.join(os.environ.get("UV_TEST_OUTPUT", "/tmp"), f"arrays_{mapper}_{name}.png")
    SaveScreenshot(shot, view, ImageResolution=[SIZE, SIZE])  # noqa: F405
    Hide(source, view)  # noqa: F405
    return covered(read_png(shot))


# Higher-order cells: the triquadratic hexahedra (every entry; the hexahedral one subdivides them into
# linear hexahedra) by a cell array, the quadratic cylinder's tetrahedra by a point array.
higher_order = [("TriQuadraticHexahedron.vtu", "CELLS", "smooth")]
if mapper != "hexahedral":
    higher_order.append(("CylinderQuadratic.vtk", "POINTS", "velocity_norm"))
for name, association, array in higher_order:
    drawn = show_higher_order(name, association, array)
    print(f"{name} coloured by {array}: " + ("absent, skipped" if drawn is None else f"{drawn} covered pixels"))
    assert drawn is None or drawn > 200
assert errors.errors == 0, f"{errors.errors} errors"
print("plugin arrays OK")
