#!/usr/bin/env python3
"""Frame time of a mesh whose points move every frame against the same mesh standing still (a
command, not a test: timings are never asserted).

    PYTHONPATH=build/vtk/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Benchmark/deforming.py [--resolution 32] [--frames 8] [--size 512]

The wavelet on (2R - 1)^3 cells split into five tetrahedra each (R = 32: the benchmark's 1.25 M),
rendered along an orbit (so every frame is a new view for every mapper), once with the points fixed
and once displaced in place by a time-varying field before each frame (points.Modified(), as a simulation or vtkWarpVector's output
does). Prints each mapper's median frame time both ways and their ratio: vtkBarycentricShellMapper
needs no preprocessing (it refreshes positions only), the others redo what depends on the points.
"""
import argparse
import os
import statistics
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Benchmark"))
import benchmark  # noqa: E402
import time_series  # noqa: E402

from unstructuredvolume import vtkBarycentricShellMapper, vtkPreIntegratedTetrahedraMapper  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper  # noqa: E402
import numpy as np  # noqa: E402

MAPPERS = [
    ("VTK ProjectedTetrahedra", vtkProjectedTetrahedraMapper),
    ("UV PreIntegratedTetrahedra", vtkPreIntegratedTetrahedraMapper),
    ("UV BarycentricShells 64", lambda: benchmark.configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=64)),
    ("UV BarycentricShells 128 (default)", vtkBarycentricShellMapper),
    ("UV BarycentricCellProjection",
     lambda: benchmark.configured(vtkBarycentricShellMapper, RenderModeToCellProjection=None)),
]


def wavelet(resolution):
    from unstructuredvolume import vtkHexahedraToTetrahedra
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-resolution, resolution - 1, -resolution, resolution - 1, -resolution, resolution - 1)
    split = vtkHexahedraToTetrahedra()
    split.SetSplitModeToFiveTetrahedra()
    split.SetInputConnection(source.GetOutputPort())
    split.Update()
    return split.GetOutput()


def run(name, factory, mesh, prop, cameras, size, deform):
    rest = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64).copy()
    points = vtkPoints()
    points.SetDataTypeToFloat()
    points.SetData(numpy_to_vtk(rest.astype(np.float32), deep=True))
    mesh.SetPoints(points)
    coordinates = vtk_to_numpy(points.GetData())
    window, _ = time_series.offscreen_volume(factory, mesh, prop, cameras[0], size)
    renderer = window.GetRenderers().GetFirstRenderer()
    window.Render()
    window.WaitForCompletion()
    extent = rest.max(axis=0) - rest.min(axis=0)
    frames = []
    for k, camera in enumerate(cameras):
        if deform:
            # A smooth swirl of up to 2% of the extent, different every frame.
            t = 0.7 * (k + 1)
            coordinates[:, 0] = rest[:, 0] + 0.02 * extent[0] * np.sin(2 * np.pi * rest[:, 1] / extent[1] + t)
            coordinates[:, 1] = rest[:, 1] + 0.02 * extent[1] * np.cos(2 * np.pi * rest[:, 2] / extent[2] - t)
            points.Modified()
        renderer.SetActiveCamera(camera)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        frames.append(time.perf_counter() - start)
    window.Finalize()
    return statistics.median(frames)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=int, default=32)
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--size", type=int, default=512)
    args = parser.parse_args()
    mesh = wavelet(args.resolution)
    prop, _, _ = benchmark.volume_property(mesh, "RTData", benchmark.smooth_ramp, 0.05)
    cameras = benchmark.orbit(mesh, args.frames)
    print(f"wavelet: {mesh.GetNumberOfCells()} tetrahedra, {args.frames} frames, {args.size} px")
    print(f"{'mapper':36s} {'static (s)':>10s} {'deforming (s)':>14s} {'ratio':>6s}")
    for name, factory in MAPPERS:
        static = run(name, factory, mesh, prop, cameras, args.size, False)
        deforming = run(name, factory, mesh, prop, cameras, args.size, True)
        print(f"{name:36s} {static:10.3f} {deforming:14.3f} {deforming / static:6.2f}", flush=True)


if __name__ == "__main__":
    main()
