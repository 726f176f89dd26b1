"""Run inside the ParaView GUI (paraview --script=...) by test_gui.sh: loads the plugin, shows a
generated hexahedral mesh with "Volume (Hexahedral Ray Cast)" and writes what the GUI lists to
$UV_GUI_OUTPUT/gui_entries.txt once the view has rendered. $UV_PLUGIN is the plugin's .so, or the
name of an installed plugin, which ParaView then finds in its own plugin list."""
import os

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

out = os.environ["UV_GUI_OUTPUT"]
plugin = os.environ["UV_PLUGIN"]
if os.sep in plugin:
    LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405
else:
    LoadDistributedPlugin(plugin, remote=False, ns=globals())  # noqa: F405
mesh = AnalyticMesh(Resolution=[10, 10, 10], Distortion="Twist")  # noqa: F405
SetActiveSource(mesh)  # noqa: F405
display = Show(mesh)  # noqa: F405
display.Representation = "Volume (Hexahedral Ray Cast)"
ColorBy(display, ("POINTS", "MarschnerLobb"))  # noqa: F405
lut = GetColorTransferFunction("MarschnerLobb")  # noqa: F405
lut.ApplyPreset("Cool to Warm", True)
opacity = GetOpacityTransferFunction("MarschnerLobb")  # noqa: F405
opacity.Points = [0.0, 0.0, 0.5, 0.0, 0.3, 0.05, 0.5, 0.0, 1.0, 0.6, 0.5, 0.0]
display.ScalarOpacityUnitDistance = 0.4
display.Isovalues = [0.7]
display.IsosurfaceOpacity = 0.8
display.SetScalarBarVisibility(GetActiveView(), True)  # noqa: F405
view = GetActiveView()  # noqa: F405
view.OrientationAxesVisibility = 1
ResetCamera()  # noqa: F405
view.CameraPosition = [3.5, -5.0, 3.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
Render()  # noqa: F405

lines = ["representation: " + t for t in display.Representation.Available]
for name in ("HexahedraToTetrahedra", "VertexGradient"):
    prototype = servermanager.ProxyManager().SMProxyManager.GetPrototypeProxy("filters", name)
    menu = prototype.GetHints().FindNestedElementByName("ShowInMenu") if prototype else None
    lines.append(f"filter: {name} in {menu.GetAttribute('category') if menu else None}")
with open(os.path.join(out, "gui_entries.txt"), "w") as f:
    f.write("\n".join(lines) + "\n")
