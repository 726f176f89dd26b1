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
changed), the median step of each kind, its ratio to the static frame, what the mapper redid, the
entry's choice of rank partition and each rank's resident memory after the steps. paraview_ranks.py
runs it on 1, 2 and 4 ranks (--json, --image) for the rank-scaling table.
"""
import argparse
import builtins
import json
import os
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ParaView"))
from pvscene import ENTRIES, pixels_off, png_rgb, printed  # noqa: E402  (shared with the ParaView tests)

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("mapper", choices=["preintegrated", "hexahedral", "barycentric"])
parser.add_argument("--extent", type=int, default=None, help="default 50 (hexahedral) or 29 (tetrahedral)")
parser.add_argument("--steps", type=int, default=4)
parser.add_argument("--size", type=int, default=384)
parser.add_argument("--kinds", default="values,points", help="comma-separated: values, points")
parser.add_argument("--keep-partitions", type=int, choices=[0, 1], default=1,
                    help="the entries' KeepRankPartitions (0: ParaView redistributes every change)")
parser.add_argument("--image", help="write the last step's image here (PNG)")
parser.add_argument("--compare-to", help="with --image: the image to compare it with (one rank's)")
parser.add_argument("--json", help="append one JSON line per kind here")
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())  # noqa: F405
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
entry = ENTRIES[args.mapper]
tetrahedral = args.mapper != "hexahedral"
# Not a one-letter name: the programmable filter runs its script in this module's namespace, where it
# also leaves numpy_interface's algorithms (max, min, sum: MPI reductions that hang when only this
# rank calls them; builtins.max below).
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


def resident_megabytes():
    """Each rank's resident memory now (ParaView's memory inspector's source), in MB."""
    from paraview.modules.vtkRemotingCore import vtkPVMemoryUseInformation
    information = vtkPVMemoryUseInformation()
    servermanager.ActiveConnection.Session.GatherInformation(0x01, information, 0)  # the data server
    return [information.GetProcMemoryUse(i) / 1024.0 for i in range(information.GetSize())]


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
    display.KeepRankPartitions = args.keep_partitions
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
    if args.image:
        SaveScreenshot(args.image, view, ImageResolution=[args.size, args.size])  # noqa: F405
    compared = pixels_off(png_rgb(args.image), png_rgb(args.compare_to)) if args.image and args.compare_to else None
    memory = resident_megabytes()
    # The mapper and representation are not wrapped in ParaView's Python: their PrintSelf says what
    # the mapper redid and which partition the entry chose.
    representation = display.GetClientSideObject().GetActiveRepresentation()
    mapper = representation.GetActiveVolumeMapper()
    redone = "/".join(printed(mapper, name) for name in ("MeshBuilds", "PointRefreshes", "ValueRefreshes"))
    partition = printed(representation, "RankPartition")
    Delete(display)  # noqa: F405
    Delete(view)  # noqa: F405
    for proxy in (series, mesh, wavelet):
        Delete(proxy)  # noqa: F405
    return dict(kind=kind, cells=cells, first=first, static=static, data=statistics.median(data),
                step=statistics.median(steps), redone=redone, partition=partition, memory_mb=memory,
                image_off=compared[0] if compared else None, image_worst=compared[1] if compared else None)


print(f"{entry}, {ranks} rank(s), {args.size} px, {args.steps} steps per kind")
print(f"{'kind':8s} {'cells':>9s} {'first':>7s} {'static':>7s} {'data':>7s} {'step':>7s} {'ratio':>6s}  "
      "builds/point/value refreshes (rank 0), partition, largest rank's memory")
for kind in args.kinds.split(","):
    row = measure(kind)
    print(f"{kind:8s} {row['cells']:9d} {row['first']:7.3f} {row['static']:7.3f} {row['data']:7.3f} "
          f"{row['step']:7.3f} {row['step'] / row['static']:6.2f}  {row['redone']}, {row['partition']}, "
          f"{builtins.max(row['memory_mb']):.0f} MB", flush=True)
    if args.json:
        row.update(entry=entry, mapper=args.mapper, ranks=ranks, size=args.size, steps=args.steps,
                   keep_partitions=args.keep_partitions)
        with open(args.json, "a", encoding="utf-8") as stream:
            stream.write(json.dumps(row) + "\n")
