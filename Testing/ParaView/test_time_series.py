"""An animation played through one entry, as a user plays a reader's time steps: each step's image
must be that step rendered from scratch (a new reader of that step alone, a new view), and the entry
must redo only what changed: one build of its mesh for the whole animation, a refresh of the values or
of the points for each step that changed them.

    pvbatch test_time_series.py <plugin> <preintegrated|hexahedral|barycentric>

Two series: a generated one (6 .vtu files of 1,000 unstructured hexahedra: the values change over
the first three steps, then the points move while the values stay) and, where ../shared/data is
present, the OpenFOAM cavity's six steps of cell pressure (a static mesh whose reader makes new arrays
every step).
"""
import math
import os
import re
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

plugin, mapper = sys.argv[1], sys.argv[2]
ENTRY = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
         "barycentric": "Volume (Barycentric Shells)"}[mapper]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
SIZE = 128
# A step played and the same step from scratch run the same code on the same data: only rounding of
# an 8-bit screenshot may differ.
LEVELS = 2


def generated_series(folder):
    """File names of the generated steps: values change for steps 1-2, points for steps 3-5."""
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-5, 5, -5, 5, -5, 5)
    append = vtkAppendFilter()
    append.SetInputConnection(source.GetOutputPort())
    append.Update()
    base = append.GetOutput()
    names = []
    for step in range(6):
        grid = vtkUnstructuredGrid()
        grid.DeepCopy(base)
        phase = 0.8 * min(step, 2)
        values = vtkFloatArray()
        values.SetName("field")
        points = vtkPoints()
        for p in range(grid.GetNumberOfPoints()):
            x, y, z = base.GetPoint(p)
            values.InsertNextValue(base.GetPointData().GetArray("RTData").GetValue(p) +
                                   40.0 * math.sin(0.5 * x + phase) * math.cos(0.4 * y))
            shift = 0.3 * max(step - 2, 0)
            points.InsertNextPoint(x + shift * math.sin(0.6 * y), y + shift * math.cos(0.5 * z), z)
        grid.GetPointData().AddArray(values)
        grid.SetPoints(points)
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(grid)
        names.append(os.path.join(folder, f"series_{step}.vtu"))
        writer.SetFileName(names[-1])
        writer.Write()
    return names


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    return [scalars.GetTuple3(i) for i in range(scalars.GetNumberOfTuples())]


def screenshot(view, folder, name):
    path = os.path.join(folder, name + ".png")
    SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])  # noqa: F405
    return read_png(path)


def largest_difference(a, b):
    return max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))


def covered(image):
    return sum(1 for p in image if max(p) > 8)


def new_view(camera):
    view = CreateRenderView()  # noqa: F405
    view.ViewSize = [SIZE, SIZE]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0, 0, 0]
    if camera:
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp, view.CameraViewAngle = camera
    return view


def show(source, view, association, array, value_range, unit_distance):
    display = Show(source, view)  # noqa: F405
    display.Representation = ENTRY
    ColorBy(display, (association, array))  # noqa: F405
    lut = GetColorTransferFunction(array)  # noqa: F405
    lut.AutomaticRescaleRangeMode = "Never"  # the same map for every step and for the steps from scratch
    lut.RescaleTransferFunction(*value_range)
    opacity = GetOpacityTransferFunction(array)  # noqa: F405
    opacity.RescaleTransferFunction(*value_range)
    display.ScalarOpacityUnitDistance = unit_distance
    return display


def mapper_counts(display):
    """The entry's mapper's MeshBuilds, PointRefreshes, ValueRefreshes (from its PrintSelf: the
    mapper is not wrapped in ParaView's Python)."""
    text = str(display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper())
    return tuple(int(re.search(name + r": (\d+)", text).group(1))
                 for name in ("MeshBuilds", "PointRefreshes", "ValueRefreshes"))


def play(name, make_reader, files, association, array, expected_counts, folder):
    """Plays every step of `make_reader(files)` and compares each with the step from scratch;
    `expected_counts(steps)`: the mapper's builds, point and value refreshes after them."""
    reader = make_reader(files)
    steps = list(reader.TimestepValues)
    assert len(steps) >= 5, steps
    ranges = []
    for time in steps:  # one map for the whole animation
        reader.UpdatePipeline(time)
        arrays = reader.PointData if association == "POINTS" else reader.CellData
        ranges.append(arrays[array].GetRange(0))
    value_range = (min(r[0] for r in ranges), max(r[1] for r in ranges))
    bounds = reader.GetDataInformation().GetBounds()
    unit_distance = 0.3 * math.dist(bounds[0::2], bounds[1::2])
    scene = GetAnimationScene()  # noqa: F405
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = steps[0]  # so that the first frame shows the first step
    view = new_view(None)
    display = show(reader, view, association, array, value_range, unit_distance)
    ResetCamera(view)  # noqa: F405
    camera = (list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp), view.CameraViewAngle)
    worst, drawn = 0, 0
    for index, time in enumerate(steps):
        scene.AnimationTime = time
        Render(view)  # noqa: F405
        played = screenshot(view, folder, f"{name}_played_{index}")
        single = make_reader([files[index]] if len(files) > 1 else files, time)
        alone = new_view(camera)
        show(single, alone, association, array, value_range, unit_distance)
        Render(alone)  # noqa: F405
        fresh = screenshot(alone, folder, f"{name}_fresh_{index}")
        Delete(alone)  # noqa: F405
        Delete(single)  # noqa: F405
        difference = largest_difference(played, fresh)
        worst = max(worst, difference)
        print(f"  {name} step {index} (t = {time:g}): covered {covered(played)} pixels, largest difference "
              f"to the step from scratch {difference:.0f} levels")
        drawn += 1 if covered(fresh) > 0.05 * SIZE * SIZE else 0
        assert difference <= LEVELS, f"{name} step {index} differs from the step rendered from scratch"
    assert drawn >= len(steps) - 1, "the steps draw almost nothing"  # the cavity starts at rest (p = 0)
    counts = mapper_counts(display)
    print(f"{ENTRY}, {name}: mesh builds, point refreshes, value refreshes = {counts}; largest difference "
          f"{worst:.0f} levels")
    expected_counts = expected_counts(len(steps))
    assert counts == expected_counts, f"expected {expected_counts}"
    Delete(view)  # noqa: F405
    Delete(reader)  # noqa: F405


def xml_reader(files, time=None):
    reader = XMLUnstructuredGridReader(FileName=files)  # noqa: F405
    if time is not None:
        reader.UpdatePipeline()
    return reader


def foam_reader(files, time=None):
    reader = OpenFOAMReader(FileName=files[0])  # noqa: F405
    reader.Createcelltopointfiltereddata = 0  # the data per cell, as OpenFOAM writes it
    if time is not None:  # only that step: the "from scratch" render
        reader.UpdatePipeline(time)
        return ForceTime(Input=reader, ForcedTime=time, IgnorePipelineTime=1)  # noqa: F405
    return reader


with tempfile.TemporaryDirectory() as folder:
    files = generated_series(folder)
    # One build; steps 1-2 new values, steps 3-5 new points.
    play("generated", xml_reader, files, "POINTS", "field", lambda steps: (1, 3, 2), folder)
    cavity = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data",
                          "openfoam_cavity", "cavity", "case.foam")
    if os.path.exists(cavity):
        # One build; the pressure changes at every step after the first, the mesh never (ParaView's
        # reader leaves out the initial time, so the steps are 0.5 to 2.5).
        play("cavity", foam_reader, [cavity], "CELLS", "p", lambda steps: (1, 0, steps - 1), folder)
    else:
        print("../shared/data absent: the OpenFOAM cavity is skipped")
print("time series OK")
