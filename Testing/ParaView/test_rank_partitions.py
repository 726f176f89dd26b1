"""Ranks' pieces kept or redistributed (KeepRankPartitions), on 2 MPI ranks:

    mpiexec -np 2 pvbatch test_rank_partitions.py <plugin> <preintegrated|hexahedral|barycentric> <output-dir>

One mesh (the wavelet's voxels as an unstructured grid), dealt to the ranks three ways by a
programmable source: in z-slabs (a partition: the entry keeps the pieces where they are), cell by
cell in turn (every piece spans the whole mesh: ParaView redistributes), and all to rank 0 (far from
balanced: ParaView redistributes); and the slabs again with KeepRankPartitions off. The four images
must agree: at most 1% of the pixels more than 2 levels off in some channel (IceT composites the
pieces in a different order each way, and the pieces' seams fall elsewhere). Then the z-slabs beside
a copy dealt in x-slabs: the second entry must not keep its pieces (each rank's box around both
would overlap the other's), and the image must agree with both redistributed. Last, a value-only
time step of the slabs keeps them kept. The entry's choice is read from the representation's PrintSelf.
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from pvscene import ENTRIES, new_view, pixels_off, png_rgb, printed  # beside this script

# Not names the programmable source uses: its script runs in this module's namespace.
plugin, mapper, OUTPUT_DIR = sys.argv[1], sys.argv[2], sys.argv[3]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
assert ranks == 2, f"run on 2 ranks, not {ranks}"
os.makedirs(OUTPUT_DIR, exist_ok=True)
ENTRY = ENTRIES[mapper]

INFORMATION = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm, vtkStreamingDemandDrivenPipeline as pipeline
info = self.GetOutputInformation(0)
info.Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
info.Remove(pipeline.TIME_STEPS())
for step in (0.0, 1.0):
    info.Append(pipeline.TIME_STEPS(), step)
info.Set(pipeline.TIME_RANGE(), [0.0, 1.0], 2)
"""
# Every rank builds the whole mesh and keeps its share of the cells.
SOURCE = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
from vtkmodules.vtkFiltersCore import vtkAppendFilter
try:
    from vtkmodules.vtkFiltersCore import vtkExtractCells  # VTK 9.2 and later
except ImportError:
    from vtkmodules.vtkFiltersExtraction import vtkExtractCells
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
info = self.GetOutputInformation(0)
piece = info.Get(pipeline.UPDATE_PIECE_NUMBER())
pieces = info.Get(pipeline.UPDATE_NUMBER_OF_PIECES())
t = info.Get(pipeline.UPDATE_TIME_STEP()) if info.Has(pipeline.UPDATE_TIME_STEP()) else 0.0
wavelet = vtkRTAnalyticSource()
wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
grid = vtkAppendFilter()
grid.SetInputConnection(wavelet.GetOutputPort())
grid.Update()
whole = grid.GetOutput()
count = whole.GetNumberOfCells()
if DEAL == "slabs":
    mine = np.array_split(np.arange(count), pieces)[piece]  # cells run x fastest, z slowest
elif DEAL == "xslabs":
    cells = np.arange(count)
    mine = cells[(cells % 20) * pieces // 20 == piece]  # 20 cells along x
elif DEAL == "turns":
    mine = np.arange(piece, count, pieces)
else:
    mine = np.arange(count) if piece == 0 else np.arange(0)
ids = vtkIdList()
for cell in mine:
    ids.InsertNextId(int(cell))
extract = vtkExtractCells()
extract.SetInputData(whole)
extract.SetCellList(ids)
extract.Update()
out = self.GetOutput()
out.ShallowCopy(extract.GetOutput())
if SHIFT and out.GetNumberOfPoints():
    moved = vtk_to_numpy(out.GetPoints().GetData()).copy()
    moved[:, 0] += SHIFT
    out.GetPoints().SetData(numpy_to_vtk(moved, deep=True))
values = vtk_to_numpy(out.GetPointData().GetArray("RTData")).astype(np.float32) + np.float32(15.0 * t)
array = numpy_to_vtk(values, deep=True)
array.SetName("RTData")
out.GetPointData().RemoveArray("RTData")
out.GetPointData().SetScalars(array)
"""

view = new_view(240, (0.1, 0.1, 0.12))
view.CameraViewAngle = 30.0
view.ViewTime = 0.0


def show(deal, shift, keep):
    source = ProgrammableSource(OutputDataSetType="vtkUnstructuredGrid")  # noqa: F405
    source.ScriptRequestInformation = INFORMATION
    source.Script = f"DEAL, SHIFT = {deal!r}, {shift!r}\n" + SOURCE
    display = Show(source, view)  # noqa: F405
    display.Representation = ENTRY
    ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
    lut = GetColorTransferFunction("RTData")  # noqa: F405
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(37.0, 292.0)
    GetOpacityTransferFunction("RTData").Points = [37.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0,  # noqa: F405
                                                   292.0, 0.6, 0.5, 0.0]
    display.ScalarOpacityUnitDistance = 3.0
    display.KeepRankPartitions = 1 if keep else 0
    return source, display


def render(deals, keep=True, time=0.0):
    """The deals' meshes side by side (the second 25 along x), rendered; the image's name, each
    entry's choice and the pixels."""
    view.ViewTime = time
    shown = [show(deal, 25.0 * k, keep) for k, deal in enumerate(deals)]
    Render(view)  # noqa: F405  (ParaView resets the camera on a view's first render: before ours)
    centre = 12.5 * (len(deals) - 1)
    distance = 1.0 + 0.45 * (len(deals) - 1)
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [centre, 0.0, 0.0]
    view.CameraPosition = [centre + 55.0 * distance, -40.0 * distance, 30.0 * distance]
    Render(view)  # noqa: F405
    if time > 0.0:
        view.ViewTime = 0.0
        Render(view)  # noqa: F405
        view.ViewTime = time
        Render(view)  # noqa: F405
    name = f"{'+'.join(deals)}{'' if keep else '_redistributed'}{'_step' if time else ''}"
    path = os.path.join(OUTPUT_DIR, f"{mapper}_{name}.png")
    SaveScreenshot(path, view, ImageResolution=[240, 240])  # noqa: F405
    choices = [printed(display.GetClientSideObject().GetActiveRepresentation(), "RankPartition")
               for _, display in shown]
    pixels = png_rgb(path)
    for source, display in shown:
        Delete(display)  # noqa: F405
        Delete(source)  # noqa: F405
    return name, choices, pixels


def check(results, expected):
    """Every image within 1% of the first's, every entry's choice the expected one."""
    first = results[0][2]
    covered = float(np.mean(np.abs(first - first[0]).max(axis=1) > 2))
    print(f"{ENTRY}: the volumes cover {100 * covered:.1f}% of the image")
    assert covered > 0.2, covered
    for name, choices, pixels in results:
        share = pixels_off(pixels, first)[0]
        print(f"{name}: {', '.join(choices)}; {100 * share:.2f}% of pixels more than 2 levels off {results[0][0]}")
        assert choices == expected[name], (name, choices)
        assert share <= 0.01, (name, share)
    return first


kept = check([render(["slabs"]), render(["turns"]), render(["rank0"]), render(["slabs"], keep=False)],
             {"slabs": ["pieces kept"], "turns": ["redistributed"], "rank0": ["redistributed"],
              "slabs_redistributed": ["redistributed"]})
# Two meshes split along different axes: each a partition, but the view would order each rank by the
# box around both of its pieces, and those boxes overlap. The second entry lets ParaView move its cells
# to the first's boxes.
check([render(["slabs", "xslabs"]), render(["slabs", "xslabs"], keep=False)],
      {"slabs+xslabs": ["pieces kept", "redistributed"],
       "slabs+xslabs_redistributed": ["redistributed", "redistributed"]})
# A value-only step (a programmable source's later time): the slabs stay kept, and the image moves.
name, choices, stepped = render(["slabs"], time=1.0)
share = pixels_off(stepped, kept)[0]
print(f"{name}: {', '.join(choices)}; {100 * share:.2f}% of pixels changed by the step")
assert choices == ["pieces kept"], choices
assert share > 0.01, share
print("rank partitions OK")
