"""The installed Python package, as a user gets it: /usr/bin/python3 with no PYTHONPATH imports
`unstructuredvolume` from VTK's own Python folder (not the build tree), and its classes work: a
generated mesh is split and drawn by each mapper.
Usage: python3 installed_package.py <VTK's Python folder> <build folder>"""
import os
import sys

site_folder, build_folder = (os.path.realpath(p) for p in sys.argv[1:3])
assert "PYTHONPATH" not in os.environ, "the installed package is tested without PYTHONPATH"

import vtkmodules  # noqa: E402
import unstructuredvolume  # noqa: E402
from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper,  # noqa: E402
                                vtkHexahedralRayCastMapper, vtkHexahedraToTetrahedra,
                                vtkPreIntegratedTetrahedraMapper)
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,  # noqa: E402
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

package = os.path.realpath(os.path.dirname(unstructuredvolume.__file__))
assert package == os.path.join(site_folder, "unstructuredvolume"), f"imported {package}"
assert os.path.dirname(os.path.dirname(os.path.realpath(vtkmodules.__file__))) == site_folder, "VTK's Python is elsewhere"
print("imported:", package)

# Every header installed goes to our own include folder: a header at the top (the Python wrapping's
# generated Python.h once did) shadows a system one for whatever is built next.
with open(os.path.join(build_folder, "install_manifest.txt")) as manifest:
    headers = [line.strip() for line in manifest if "/include/" in line]
stray = [path for path in headers if "/include/unstructuredvolume/" not in path]
assert headers and not stray, f"headers installed outside include/unstructuredvolume: {stray}"

source = vtkAnalyticMeshSource()
source.SetResolution(6, 6, 6)
split = vtkHexahedraToTetrahedra()
split.SetInputConnection(source.GetOutputPort())
split.Update()
assert split.GetOutput().GetNumberOfCells() > 0, "the split made no tetrahedra"

colors = vtkColorTransferFunction()
colors.AddRGBPoint(0.0, 0.2, 0.3, 1.0)
colors.AddRGBPoint(1.0, 1.0, 0.6, 0.2)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(0.0, 0.2)
opacity.AddPoint(1.0, 0.8)
for mapper_class, data in ((vtkHexahedralRayCastMapper, source), (vtkPreIntegratedTetrahedraMapper, split),
                           (vtkBarycentricShellMapper, split)):
    mapper = mapper_class()
    mapper.SetInputConnection(data.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(vtkVolumeProperty())
    volume.GetProperty().SetColor(colors)
    volume.GetProperty().SetScalarOpacity(opacity)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(64, 64)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    lit = int((pixels[:, :3].max(axis=1) > 8).sum())
    print(f"{mapper_class.__name__}: {lit} of {len(pixels)} pixels lit")
    assert lit > len(pixels) // 5, f"{mapper_class.__name__} drew {lit} pixels"
    window.Finalize()
print("installed package OK")
