"""The installed plugin, as a user gets it: run by an installed pvbatch with no PYTHONPATH and no
path to the .so, it is loaded by name from ParaView's own plugin list (paraview.conf), draws a frame
with each Representation entry, and is the copy in ParaView's plugin folder, not the build tree's.
Usage: pvbatch test_installed_plugin.py <ParaView's plugin folder> <build folder> <output folder>"""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

plugin_folder, build_folder = (os.path.realpath(p) for p in sys.argv[1:3])
output = sys.argv[3]
os.makedirs(output, exist_ok=True)
assert "PYTHONPATH" not in os.environ, "the installed plugin is tested without PYTHONPATH"

LoadDistributedPlugin("UnstructuredVolume", remote=False, ns=globals())  # noqa: F405

information = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
files = [information.GetPluginFileName(i) for i in range(information.GetNumberOfPlugins())
         if information.GetPluginName(i) == "UnstructuredVolume"]
assert len(files) == 1, f"ParaView lists UnstructuredVolume {len(files)} times: {files}"
loaded = os.path.realpath(files[0])
assert loaded.startswith(plugin_folder + os.sep), f"loaded {loaded}, not from {plugin_folder}"
assert not loaded.startswith(build_folder + os.sep), f"loaded the build tree's {loaded}"
print("loaded by name:", loaded)

for name in ("HexahedraToTetrahedra", "VertexGradient"):
    assert servermanager.ProxyManager().SMProxyManager.GetPrototypeProxy("filters", name), name

mesh = AnalyticMesh(Resolution=[8, 8, 8], Distortion="Twist")  # noqa: F405
view = CreateRenderView(ViewSize=[96, 96], Background=[0, 0, 0], OrientationAxesVisibility=0)  # noqa: F405
view.UseColorPaletteForBackground = 0
display = Show(mesh, view)  # noqa: F405
ColorBy(display, ("POINTS", "MarschnerLobb"))  # noqa: F405
GetOpacityTransferFunction("MarschnerLobb").Points = [0.0, 0.2, 0.5, 0.0, 1.0, 0.8, 0.5, 0.0]  # noqa: F405
ResetCamera(view)  # noqa: F405
for entry in ("Volume (Hexahedral Ray Cast)", "Volume (Pre-integrated Tetrahedra)", "Volume (Barycentric Shells)"):
    display.Representation = entry
    Render(view)  # noqa: F405
    path = os.path.join(output, "installed_" + entry.split("(")[1].rstrip(")").replace(" ", "_").lower() + ".png")
    SaveScreenshot(path, view, ImageResolution=[96, 96])  # noqa: F405
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    lit = int((pixels[:, :3].max(axis=1) > 8).sum())
    print(f"{entry}: {lit} of {len(pixels)} pixels lit")
    assert lit > len(pixels) // 5, f"{entry} drew {lit} pixels"
print("installed plugin OK")
