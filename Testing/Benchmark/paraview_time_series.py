"""What a time step costs each ParaView entry against a static frame (a command, not a test).

    PYTHONPATH=/opt/unstructuredvolume/paraview-python/usr/lib/python3/dist-packages \\
      pvbatch paraview_time_series.py <plugin> <preintegrated|hexahedral|barycentric> [--extent 50] [--steps 4]
    mpiexec -np 2 pvbatch paraview_time_series.py ...   (each rank its piece)

A time series as a reader or a simulation delivers it: every step a deep copy of the mesh (every
array a new object), the cells the same, either the values changing (a travelling wave added to the
wavelet) or the points moving (a swirl of 2% of the extent). The hexahedral entry gets the wavelet as
(2E)^3 unstructured hexahedra (E = 50: 1 M), the tetrahedral entries the wavelet tetrahedralised at
E = 29 (1.2 M tetrahedra). The camera stays put. Producing a step's data is timed apart ("data");
"step" is the frame after it: ParaView's representation update, delivery and the mapper's refresh
and drawing. Prints the first frame (Show and Render), the median static frame (rendered again, nothing
changed), the median step of each kind, its ratio to the static frame, and what the mapper redid.
"""
import argparse
import re
import statistics
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("mapper", choices=["preintegrated", "hexahedral", "barycentric"])
parser.add_argument("--extent", type=int, default=None, help="default 50 (hexahedral) or 29 (tetrahedral)")
parser.add_argument("--steps", type=int, default=4)
parser.add_argument("--size", type=int, default=384)
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())  # noqa: F405
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
entry = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
         "barycentric": "Volume (Barycentric Shells)"}[args.mapper]
tetrahedral = args.mapper != "hexahedral"
# Not a one-letter name: the programmable filter runs its script in this module's namespace.
EXTENT = args.extent or (29 if tetrahedral else 50)

INFORMATION = f"""
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
info = self.GetOutputInformation(0)
info.Remove(pipeline.TIME_STEPS())
for step in range({args.steps + 1}):
    info.Append(pipeline.TIME_STEPS(), float(step))
info.Set(pipeline.TIME_RANGE(), [0.0, float({args.steps})], 2)
"""
STEP = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
info = self.GetOutputInformation(0)
t = info.Get(pipeline.UPDATE_TIME_STEP()) if info.Has(pipeline.UPDATE_TIME_STEP()) else 0.0
source, out = self.GetInput(), self.GetOutput()
out.DeepCopy(source)
rest = vtk_to_numpy(source.GetPoints().GetData()).astype(np.float64)
extent = np.maximum(rest.max(axis=0) - rest.min(axis=0), 1e-9) if len(rest) else np.ones(3)
phase = 0.7 * (t + 1.0)
if KIND == "values":
    values = vtk_to_numpy(source.GetPointData().GetArray("RTData")).astype(np.float32)
    array = numpy_to_vtk(values + (20.0 * np.sin(2 * np.pi * rest[:, 0] / extent[0] + phase)).astype(np.float32), deep=True)
    array.SetName("RTData")
    out.GetPointData().RemoveArray("RTData")
    out.GetPointData().SetScalars(array)
else:
    moved = rest.copy()
    moved[:, 0] += 0.02 * extent[0] * np.sin(2 * np.pi * rest[:, 1] / extent[1] + phase)
    moved[:, 1] += 0.02 * extent[1] * np.cos(2 * np.pi * rest[:, 2] / extent[2] - phase)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(moved.astype(np.float32), deep=True))
    out.SetPoints(points)
"""


def seconds(function):
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def measure(kind):
    view = CreateView("RenderView")  # noqa: F405
    view.ViewSize = [args.size, args.size]
    view.OrientationAxesVisibility = 0
    wavelet = Wavelet(WholeExtent=[-EXTENT, EXTENT - 1] * 3)  # noqa: F405
    mesh = Tetrahedralize(Input=wavelet) if tetrahedral else AppendDatasets(Input=wavelet)  # noqa: F405
    series = ProgrammableFilter(Input=mesh)  # noqa: F405
    series.OutputDataSetType = "vtkUnstructuredGrid"
    series.RequestInformationScript = INFORMATION
    series.Script = f"KIND = {kind!r}\n" + STEP
    series.UpdatePipeline(0.0)
    view.ViewTime = 0.0
    display = Show(series, view)  # noqa: F405
    display.Representation = entry
    ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
    lut = GetColorTransferFunction("RTData")  # noqa: F405
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(17.0, 297.0)
    GetOpacityTransferFunction("RTData").Points = [17.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0,  # noqa: F405
                                                   297.0, 0.6, 0.5, 0.0]
    display.ScalarOpacityUnitDistance = EXTENT / 4.0
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = [3.5 * EXTENT, 2.2 * EXTENT, 2.0 * EXTENT]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    first = seconds(lambda: Render(view))  # noqa: F405
    Render(view)  # noqa: F405  (warm-up)
    static = statistics.median(seconds(lambda: view.StillRender()) for _ in range(args.steps))
    data, steps = [], []
    for step in range(1, args.steps + 1):
        data.append(seconds(lambda: series.UpdatePipeline(float(step))))
        view.ViewTime = float(step)
        steps.append(seconds(lambda: Render(view)))  # noqa: F405
    cells = series.GetDataInformation().GetNumberOfCells()
    # The mapper is not wrapped in ParaView's Python: its PrintSelf says what it redid.
    text = str(display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper())
    redone = "/".join(re.search(name + r": (\d+)", text).group(1)
                      for name in ("MeshBuilds", "PointRefreshes", "ValueRefreshes"))
    Delete(display)  # noqa: F405
    Delete(view)  # noqa: F405
    for proxy in (series, mesh, wavelet):
        Delete(proxy)  # noqa: F405
    return cells, first, static, statistics.median(data), statistics.median(steps), redone


print(f"{entry}, {ranks} rank(s), {args.size} px, {args.steps} steps per kind")
print(f"{'kind':8s} {'cells':>9s} {'first':>7s} {'static':>7s} {'data':>7s} {'step':>7s} {'ratio':>6s}  "
      "builds/point/value refreshes (rank 0)")
for kind in ("values", "points"):
    cells, first, static, data, step, redone = measure(kind)
    print(f"{kind:8s} {cells:9d} {first:7.3f} {static:7.3f} {data:7.3f} {step:7.3f} {step / static:6.2f}  {redone}",
          flush=True)
