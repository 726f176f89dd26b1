"""One representation's first frame on unstructured input, as a new user meets it: the wavelet
(20^3 points) made an unstructured grid of hexahedra, the same cut by a plane into a mixed mesh
(hexahedra, wedges, pyramids, tetrahedra), and the same split into tetrahedra. Each is shown on its
own, coloured by RTData with ParaView's default map, and its first frame (what Show + Render cost,
starting from ParaView's camera before its first reset) must finish within FIRST_FRAME_BOUND and
cover part of the view. "Volume (Pre-integrated Tetrahedra)" once took far longer than the bound
here on the hexahedra: every tetrahedron near the initial camera covered the whole screen.

    pvbatch test_first_frame.py <plugin> <preintegrated|hexahedral|barycentric|volume>

("volume": ParaView's own Volume representation, for comparison; not a ctest test.)
"""
import os
import sys
import tempfile
import time

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkIOImage import vtkPNGReader

FIRST_FRAME_BOUND = 40.0  # seconds; loose, as first frames on a busy shared machine vary widely
plugin, mapper = sys.argv[1], sys.argv[2]
ENTRY = {"preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray Cast)",
         "barycentric": "Volume (Barycentric Shells)", "volume": "Volume"}[mapper]
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405

wavelet = Wavelet(WholeExtent=[-9, 10, -9, 10, -9, 10])  # noqa: F405
hexahedra = ProgrammableFilter(Input=AppendDatasets(Input=wavelet))  # noqa: F405
hexahedra.OutputDataSetType = "vtkUnstructuredGrid"
hexahedra.Script = """
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON
from vtkmodules.vtkCommonCore import vtkIdList
grid, out = self.GetInput(), self.GetOutput()
out.Initialize()
out.SetPoints(grid.GetPoints())
out.GetPointData().ShallowCopy(grid.GetPointData())
out.Allocate(grid.GetNumberOfCells())
ids = vtkIdList()
for c in range(grid.GetNumberOfCells()):  # voxels in hexahedron order
    grid.GetCellPoints(c, ids)
    p = [ids.GetId(k) for k in range(8)]
    out.InsertNextCell(VTK_HEXAHEDRON, 8, [p[0], p[1], p[3], p[2], p[4], p[5], p[7], p[6]])
"""
mixed = Clip(Input=hexahedra)  # noqa: F405
mixed.ClipType = "Plane"
mixed.ClipType.Origin = [0.3, 0.2, 0.1]
mixed.ClipType.Normal = [1.0, 0.7, 0.4]
mixed.Crinkleclip = 0
tetrahedra = Tetrahedralize(Input=hexahedra)  # noqa: F405
inputs = [("hexahedra", hexahedra), ("mixed", mixed), ("tetrahedra", tetrahedra)]


def covered_share(view):
    """Share of the view's pixels that are not the black background."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "frame.png")
        SaveScreenshot(path, view)  # noqa: F405
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
    pixels = reader.GetOutput().GetPointData().GetScalars()
    # (paraview.simple's star import shadows max and sum with array functions.)
    lit = len([i for i in range(pixels.GetNumberOfTuples()) if any(c > 8 for c in pixels.GetTuple(i)[:3])])
    return lit / pixels.GetNumberOfTuples()


failures = []
for name, data in inputs:
    view = CreateView("RenderView")  # noqa: F405
    view.ViewSize = [384, 384]
    view.OrientationAxesVisibility = 0
    view.Background = [0.0, 0.0, 0.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    data.UpdatePipeline()
    cells = data.GetDataInformation().GetNumberOfCells()
    display = Show(data, view)  # noqa: F405
    assert ENTRY in display.Representation.Available, display.Representation.Available
    display.Representation = ENTRY
    ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
    start = time.time()
    Render(view)  # noqa: F405
    first = time.time() - start
    covered = covered_share(view)
    print(f"{ENTRY} on {name} ({cells} cells): first frame {first:.2f} s (bound {FIRST_FRAME_BOUND} s), "
          f"{100 * covered:.0f}% of the view covered", flush=True)
    if first > FIRST_FRAME_BOUND:
        failures.append(f"{name}: first frame {first:.1f} s")
    if covered < 0.05:
        failures.append(f"{name}: only {100 * covered:.1f}% of the view covered")
    Delete(display)  # noqa: F405
    Delete(view)  # noqa: F405
if failures:
    sys.exit("FAILED: " + "; ".join(failures))
print("first frames OK")
