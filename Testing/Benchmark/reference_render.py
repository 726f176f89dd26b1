#!/usr/bin/env python3
"""Renders a mesh with the exact CPU reference renderer: a float RGBA .vti and a PNG.

    PYTHONPATH=build/vtk/lib/python3/dist-packages /usr/bin/python3 Testing/Benchmark/reference_render.py \\
        Data/marschner_lobb_twisted_hex.vtu --scalar MarschnerLobb --size 256 --output out/reference

Reads .vtu, .vtk (legacy unstructured grid) and .vts files. The transfer function is a preset over
the scalar's range (--transfer ramp|spikes), the camera one view of the benchmark's orbit
(--view k of --views n), perspective unless --parallel.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchmark  # noqa: E402

from unstructuredvolume import vtkUnstructuredVolumeReferenceRenderer  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendFilter  # noqa: E402
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader  # noqa: E402
from vtkmodules.vtkIOXML import (vtkXMLImageDataWriter, vtkXMLStructuredGridReader,  # noqa: E402
                                 vtkXMLUnstructuredGridReader)


def read(path):
    if path.endswith(".vtu"):
        reader = vtkXMLUnstructuredGridReader()
    elif path.endswith(".vts"):
        reader = vtkXMLStructuredGridReader()
    else:
        reader = vtkUnstructuredGridReader()
    reader.SetFileName(path)
    to_grid = vtkAppendFilter()
    to_grid.SetInputConnection(reader.GetOutputPort())
    to_grid.Update()
    return to_grid.GetOutput()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input")
    parser.add_argument("--scalar", default=None, help="point array (default: the active scalars)")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--transfer", choices=("ramp", "spikes"), default="ramp")
    parser.add_argument("--unit", type=float, default=0.05, help="opacity unit distance / mesh diagonal")
    parser.add_argument("--view", type=int, default=0)
    parser.add_argument("--views", type=int, default=8)
    parser.add_argument("--parallel", action="store_true")
    parser.add_argument("--tolerance", type=float, default=1e-7)
    parser.add_argument("--output", default="reference", help="path prefix of the .vti and .png written")
    args = parser.parse_args()

    mesh = read(args.input)
    if mesh.GetNumberOfCells() == 0:
        sys.exit(f"no cells in {args.input}")
    maker = benchmark.smooth_ramp if args.transfer == "ramp" else benchmark.spikes
    prop, _, _ = benchmark.volume_property(mesh, args.scalar, maker, args.unit)
    camera = benchmark.orbit(mesh, args.views)[args.view % args.views]
    if args.parallel:
        camera.ParallelProjectionOn()
        camera.SetParallelScale(0.6 * mesh.GetLength())
    renderer = vtkUnstructuredVolumeReferenceRenderer()
    renderer.SetInputData(mesh)
    if args.scalar:
        renderer.SetScalarArrayName(args.scalar)
    renderer.SetVolumeProperty(prop)
    renderer.SetCamera(camera)
    renderer.SetImageSize(args.size, args.size)
    renderer.SetTolerance(args.tolerance)
    start = time.perf_counter()
    if not renderer.Render():
        sys.exit("the reference renderer failed (see the error above)")
    print(f"rendered {mesh.GetNumberOfCells()} cells at {args.size} px in {time.perf_counter() - start:.2f} s")
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(renderer.GetOutput())
    writer.SetFileName(args.output + ".vti")
    writer.Write()
    vtkUnstructuredVolumeReferenceRenderer.WritePNG(renderer.GetOutput(), args.output + ".png", 0.1, 0.1, 0.12)
    print("wrote", args.output + ".vti", "and", args.output + ".png")


if __name__ == "__main__":
    main()
