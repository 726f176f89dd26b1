"""Plugin/render_file.py, the one-line render of a file, run as a user runs it (a pvbatch subprocess).

    pvbatch test_render_file.py <pvbatch> <plugin> <output folder>

Checks, on generated .vtu files of hexahedra, tetrahedra and a pentagonal prism written here, and, where
../shared/data exists, on the OpenFOAM cavity (every time step, a cell array) and the PLOT3D Blunt
Fin: the Representation entry the command reports, that every PNG it names exists at the size asked
(twice as wide with --compare) and covers part of the middle of each view; and that a wrong array
name, a missing file and a surface without 3D cells end with a non-zero exit and a one-line message.
"""
import math
import os
import re
import subprocess
import sys
import time

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_PENTAGONAL_PRISM, vtkUnstructuredGrid
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter, vtkImageDataToPointSet
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUnstructuredGridWriter

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Python"))
import shared_data  # noqa: E402  (finds ../shared/data beside the repository)

pvbatch, plugin, output = sys.argv[1], sys.argv[2], sys.argv[3]
COMMAND = os.path.join(HERE, "..", "..", "Plugin", "render_file.py")
HEXAHEDRAL, TETRAHEDRA = "Volume (Hexahedral Ray Cast)", "Volume (Pre-integrated Tetrahedra)"
os.makedirs(output, exist_ok=True)
failures = []


def write_meshes():
    """The wavelet (8^3 cells) as unstructured hexahedra (a structured grid's cells are hexahedra),
    the same split into tetrahedra, a pentagonal prism and a sphere's surface: four files of ours."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-4, 4, -4, 4, -4, 4)
    structured = vtkImageDataToPointSet()
    structured.SetInputConnection(wavelet.GetOutputPort())
    hexahedra = vtkAppendFilter()
    hexahedra.SetInputConnection(structured.GetOutputPort())
    tetrahedra = vtkDataSetTriangleFilter()
    tetrahedra.SetInputConnection(hexahedra.GetOutputPort())
    paths = {}
    for name, algorithm in (("hexahedra", hexahedra), ("tetrahedra", tetrahedra)):
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputConnection(algorithm.GetOutputPort())
        paths[name] = writer_path = os.path.join(output, f"render_file_{name}.vtu")
        writer.SetFileName(writer_path)
        writer.Write()
    prism = vtkUnstructuredGrid()  # one pentagonal prism: a cell the ray caster does not take
    corners = vtkPoints()
    for z in (0.0, 1.0):
        for k in range(5):
            corners.InsertNextPoint(math.cos(0.4 * math.pi * k), math.sin(0.4 * math.pi * k), z)
    prism.SetPoints(corners)
    prism.InsertNextCell(VTK_PENTAGONAL_PRISM, 10, list(range(10)))
    height = vtkDoubleArray()
    height.SetName("height")
    for i in range(10):
        height.InsertNextValue(corners.GetPoint(i)[0] + corners.GetPoint(i)[2])
    prism.GetPointData().AddArray(height)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputData(prism)
    paths["prism"] = os.path.join(output, "render_file_prism.vtu")
    writer.SetFileName(paths["prism"])
    writer.Write()
    sphere = vtkSphereSource()  # held here: an output port does not keep its algorithm alive
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(sphere.GetOutputPort())
    paths["surface"] = os.path.join(output, "render_file_surface.vtp")
    writer.SetFileName(paths["surface"])
    writer.Write()
    return paths


def run(arguments):
    """The command's exit status, output and error text, and its wall time."""
    start = time.time()
    done = subprocess.run([pvbatch, COMMAND, *arguments, "--plugin", plugin], capture_output=True, text=True,
                          timeout=120)
    return done.returncode, done.stdout, done.stderr, time.time() - start


def png(path):
    """(width, height, pixel(x, y) -> RGB) of a PNG; y counts from the bottom, as VTK does."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height = image.GetDimensions()[:2]
    scalars = image.GetPointData().GetScalars()
    return width, height, lambda x, y: scalars.GetTuple(y * width + x)[:3]


def covered_share(pixel, left, width, height):
    """Share of the middle half of a view (columns from left) that differs from its corner, the
    background: the middle, as --compare labels each view in its upper-left corner."""
    background = pixel(left, 0)
    middle = [(x, y) for x in range(left + width // 4, left + 3 * width // 4)
              for y in range(height // 4, 3 * height // 4)]
    covered = [1 for x, y in middle if any(abs(a - b) > 8 for a, b in zip(pixel(x, y), background))]
    return len(covered) / len(middle)


def check_render(case, arguments, entry, frames, size, compare=False, expect=None, orbit=False):
    """Runs the command, then checks its entry, frame count and every PNG (and, for an orbit, that
    the first two frames differ)."""
    prefix = os.path.join(output, f"render_file_{case}")
    arguments = [*arguments, "--size", str(size[0]), str(size[1]), "--output", prefix]
    if compare:
        arguments.append("--compare")
    status, out, err, seconds = run(arguments)
    print(f"{case}: exit {status} in {seconds:.1f} s\n" + out.strip(), flush=True)
    if status != 0:
        failures.append(f"{case}: exit {status}: {err.strip()[-400:]}")
        return
    if f"representation: {entry} " not in out:
        failures.append(f"{case}: expected the entry '{entry}'")
    if expect and expect not in out:
        failures.append(f"{case}: expected '{expect}' in the output")
    reported = re.findall(r"^frame (\d+)/(\d+)\b.*: (\S+\.png) \(.*\), ([0-9.]+) s$", out, re.MULTILINE)
    if len(reported) != frames or any(int(n) != frames for _, n, _, _ in reported):
        failures.append(f"{case}: {len(reported)} progress lines, expected {frames}")
    views = 2 if compare else 1
    images = []
    for index in range(frames):
        path = f"{prefix}_{index:04d}.png"
        if not os.path.exists(path):
            failures.append(f"{case}: {path} missing")
            continue
        width, height, pixel = png(path)
        images.append([pixel(x, y) for x in range(width) for y in range(height)])
        if (width, height) != (views * size[0], size[1]):
            failures.append(f"{case}: {path} is {width}x{height}, expected {views * size[0]}x{size[1]}")
            continue
        for view in range(views):
            share = covered_share(pixel, view * size[0], size[0], size[1])
            if share < 0.05:
                failures.append(f"{case}: {path} view {view + 1} covers {100 * share:.1f}% of its middle")
    if orbit and len(images) >= 2:
        moved = len([1 for a, b in zip(images[0], images[1]) if a != b]) / len(images[0])
        if moved < 0.01:
            failures.append(f"{case}: the orbit's second frame is the first one ({100 * moved:.2f}% of pixels differ)")


def check_error(case, arguments, message):
    """A user error: a non-zero exit and the one-line message, without a traceback."""
    status, out, err, seconds = run([*arguments, "--output", os.path.join(output, f"render_file_{case}")])
    print(f"{case}: exit {status} in {seconds:.1f} s: {err.strip()}", flush=True)
    if status == 0:
        failures.append(f"{case}: exit 0, expected an error")
    if message not in err:
        failures.append(f"{case}: expected '{message}' in: {err.strip()[-400:]}")
    if "Traceback" in err:
        failures.append(f"{case}: a traceback for a user error")


meshes = write_meshes()
check_render("hexahedra", [meshes["hexahedra"], "--views", "2"], HEXAHEDRAL, 2, (128, 96),
             expect="points array 'RTData'", orbit=True)
check_render("tetrahedra", [meshes["tetrahedra"], "--preset", "Viridis (matplotlib)"], TETRAHEDRA, 1, (128, 128),
             compare=True)
check_render("prism", [meshes["prism"]], TETRAHEDRA, 1, (128, 128))
check_error("bad_array", [meshes["hexahedra"], "--array", "no_such_array"],
            "render_file: error: no array named 'no_such_array'")
check_error("missing_file", [os.path.join(output, "no_such_file.vtu")], "render_file: error: no such file")
check_error("surface", [meshes["surface"]], "has no 3D cells")
check_error("bad_preset", [meshes["tetrahedra"], "--preset", "No Such Map (nowhere)"],
            "render_file: error: no colour-map preset named 'No Such Map (nowhere)'")

try:
    cavity = shared_data.path("openfoam_cavity", "cavity", "case.foam")
    steps = len([name for name in os.listdir(os.path.dirname(cavity))
                 if re.fullmatch(r"[0-9.]+", name) and float(name) > 0])  # the reader skips time 0
    check_render("cavity", [cavity, "--time-steps", "--array", "p", "--association", "cells"], HEXAHEDRAL, steps,
                 (128, 128), expect="cells array 'p'")
except FileNotFoundError as absent:
    print(f"skipped (absent: {absent})")
try:
    grid, solution = shared_data.path("bluntfin", "bluntfinxyz.bin"), shared_data.path("bluntfin", "bluntfinq.bin")
    check_render("plot3d", [grid, "--q", solution, "--array", "Density"], HEXAHEDRAL, 1, (128, 128))
except FileNotFoundError as absent:
    print(f"skipped (absent: {absent})")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("render_file OK")
