"""Frame time of the plugin's representations on 1 and N MPI ranks (a command, not a test).

    pvbatch paraview_ranks.py <plugin> <preintegrated|hexahedral|barycentric> [--extent 40] [--frames 8] [--size 512]
    mpiexec -np 2 pvbatch paraview_ranks.py <plugin> <preintegrated|hexahedral|barycentric> ...

Renders the wavelet (extent [-E, E]^3, so (2E)^3 cells) with the representation, an orbit of
frames after one warm-up frame (which includes the preparation and, on several ranks, the
redistribution), and prints the first frame's time and the median and range of the others. Each
frame is a full still render: every rank renders its piece, IceT composites them.
"""
import argparse
import math
import statistics
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("mapper", choices=["preintegrated", "hexahedral", "barycentric"])
parser.add_argument("--extent", type=int, default=40)
parser.add_argument("--frames", type=int, default=8)
parser.add_argument("--size", type=int, default=512)
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
entry = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
         "barycentric": "Volume (Barycentric Shells)"}[args.mapper]

view = CreateView("RenderView")  # noqa: F405
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
e = args.extent
wavelet = Wavelet(WholeExtent=[-e, e, -e, e, -e, e])  # noqa: F405
display = Show(wavelet, view)  # noqa: F405
display.Representation = entry
ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
GetColorTransferFunction("RTData").RescaleTransferFunction(37.0, 277.0)  # noqa: F405
GetOpacityTransferFunction("RTData").Points = [37.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0,  # noqa: F405
                                               277.0, 0.6, 0.5, 0.0]
display.ScalarOpacityUnitDistance = e / 4.0
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0

times = []
for k in range(args.frames + 1):
    angle = 6.283185 * k / (args.frames + 1)
    view.CameraPosition = [4.5 * e * math.cos(angle), 4.5 * e * math.sin(angle), 2.0 * e]
    start = time.perf_counter()
    Render(view)  # noqa: F405
    times.append(time.perf_counter() - start)
rest = times[1:]
print(f"{entry}, {ranks} rank(s), {(2 * e) ** 3} cells, {args.size} px: first frame {times[0]:.3f} s, "
      f"median {statistics.median(rest):.3f} s [{min(rest):.3f}-{max(rest):.3f}] over {len(rest)} frames")
