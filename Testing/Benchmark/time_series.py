#!/usr/bin/env python3
"""What a time step costs each mapper against a static frame (a command, not a test: timings are
never asserted).

    PYTHONPATH=build/vtk/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \\
        /usr/bin/python3 Testing/Benchmark/time_series.py [--resolution 50] [--tet-resolution 29] [--steps 4] [--size 384]

A time series as a reader delivers it: every step a new vtkUnstructuredGrid whose arrays are all new
objects (deep copies), the cells the same. Three kinds of step, on the wavelet as (2R)^3 unstructured
hexahedra (R = 50: 1 M) and, at R = 29, as their five-tetrahedra split (0.98 M):
  - values: the scalar changes (a travelling wave added), the points not;
  - points: the points move (a swirl of 2% of the extent), the scalar not;
  - both.
The camera stays put, as in an animation, so a static frame (nothing changed, rendered again) is what
a step would cost if the mapper recognised that only values or positions changed. Prints per mapper
the first frame, the median static frame, the median step of each kind and their ratios to static.
"""
import argparse
import os
import statistics
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Benchmark"))
import benchmark  # noqa: E402

from unstructuredvolume import (vtkBarycentricShellMapper, vtkHexahedraToTetrahedra,  # noqa: E402
                                vtkHexahedralRayCastMapper, vtkPreIntegratedTetrahedraMapper)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendFilter  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkVolume  # noqa: E402
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper  # noqa: E402
import numpy as np  # noqa: E402

HEXAHEDRAL_MAPPERS = [("UV HexahedralRayCast", vtkHexahedralRayCastMapper)]
TETRAHEDRAL_MAPPERS = [
    ("VTK ProjectedTetrahedra", vtkProjectedTetrahedraMapper),
    ("UV PreIntegratedTetrahedra", vtkPreIntegratedTetrahedraMapper),
    ("UV BarycentricShells", vtkBarycentricShellMapper),
    ("UV BarycentricCellProjection",
     lambda: benchmark.configured(vtkBarycentricShellMapper, RenderModeToCellProjection=None)),
]
KINDS = ("values", "points", "both")


def wavelet_grid(resolution, tetrahedra):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-resolution, resolution, -resolution, resolution, -resolution, resolution)
    conversion = vtkHexahedraToTetrahedra() if tetrahedra else vtkAppendFilter()
    if tetrahedra:
        conversion.SetSplitModeToFiveTetrahedra()
    conversion.SetInputConnection(source.GetOutputPort())
    conversion.Update()
    grid = vtkUnstructuredGrid()
    grid.ShallowCopy(conversion.GetOutput())
    return grid


def step_grid(base, kind, step):
    """`base` as a reader would deliver step `step`: every array a new object."""
    grid = vtkUnstructuredGrid()
    grid.DeepCopy(base)
    rest = vtk_to_numpy(base.GetPoints().GetData()).astype(np.float64)
    extent = rest.max(axis=0) - rest.min(axis=0)
    t = 0.7 * (step + 1)
    if kind in ("values", "both"):
        values = vtk_to_numpy(base.GetPointData().GetArray("RTData")).astype(np.float32)
        wave = 20.0 * np.sin(2 * np.pi * rest[:, 0] / extent[0] + t)
        array = numpy_to_vtk(values + wave.astype(np.float32), deep=True)
        array.SetName("RTData")
        grid.GetPointData().RemoveArray("RTData")
        grid.GetPointData().SetScalars(array)
    if kind in ("points", "both"):
        moved = rest.copy()
        moved[:, 0] += 0.02 * extent[0] * np.sin(2 * np.pi * rest[:, 1] / extent[1] + t)
        moved[:, 1] += 0.02 * extent[1] * np.cos(2 * np.pi * rest[:, 2] / extent[2] - t)
        points = vtkPoints()
        points.SetData(numpy_to_vtk(moved.astype(np.float32), deep=True))
        grid.SetPoints(points)
    return grid


def timed_render(window):
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return time.perf_counter() - start


def offscreen_volume(factory, mesh, prop, camera, size):
    """A new mapper of `factory` rendering `mesh`'s RTData in an off-screen window: (window, mapper)."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    mapper = factory()
    mapper.SetInputData(mesh)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray("RTData")
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    renderer.SetActiveCamera(camera)
    return window, mapper


def run(factory, base, prop, camera, size, steps):
    window, mapper = offscreen_volume(factory, base, prop, camera, size)
    result = {"first": timed_render(window)}
    timed_render(window)  # warm-up
    result["static"] = statistics.median(timed_render(window) for _ in range(steps))
    for kind in KINDS:
        grids = [step_grid(base, kind, k) for k in range(steps + 1)]  # made before timing
        times = []
        for k, grid in enumerate(grids):
            mapper.SetInputData(grid)
            elapsed = timed_render(window)
            if k > 0:  # the first step after a switch of kind also changes what the last kind left
                times.append(elapsed)
        result[kind] = statistics.median(times)
        mapper.SetInputData(base)
        timed_render(window)
    window.Finalize()
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=int, default=50)
    parser.add_argument("--tet-resolution", type=int, default=29)
    parser.add_argument("--steps", type=int, default=4)
    parser.add_argument("--size", type=int, default=384)
    parser.add_argument("--mapper", default=None, help="only mappers whose name contains this")
    args = parser.parse_args()
    print(f"{'mesh':12s} {'mapper':30s} {'first':>7s} {'static':>7s} " +
          " ".join(f"{k:>7s} {'ratio':>5s}" for k in KINDS))
    for tetrahedra, mappers in ((False, HEXAHEDRAL_MAPPERS), (True, TETRAHEDRAL_MAPPERS)):
        base = wavelet_grid(args.tet_resolution if tetrahedra else args.resolution, tetrahedra)
        prop, _, _ = benchmark.volume_property(base, "RTData", benchmark.smooth_ramp, 0.05)
        camera = benchmark.orbit(base, 8)[1]
        label = f"{base.GetNumberOfCells() / 1e6:.2f}M {'tets' if tetrahedra else 'hex'}"
        for name, factory in mappers:
            if args.mapper and args.mapper not in name:
                continue
            r = run(factory, base, prop, camera, args.size, args.steps)
            ratios = " ".join(f"{r[k]:7.3f} {r[k] / r['static']:5.2f}" for k in KINDS)
            print(f"{label:12s} {name:30s} {r['first']:7.3f} {r['static']:7.3f} {ratios}", flush=True)


if __name__ == "__main__":
    main()
