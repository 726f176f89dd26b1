"""The plugin from pvbatch and pvpython: load it, find the filters in their menu, run them."""
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

# The filters are listed under the "Unstructured Volume" category of the Filters menu.
for group, name in (("filters", "HexahedraToTetrahedra"), ("filters", "VertexGradient"),
                    ("sources", "AnalyticMeshSource")):
    prototype = servermanager.ProxyManager().SMProxyManager.GetPrototypeProxy(group, name)
    assert prototype is not None, f"{group}/{name} missing after LoadPlugin"
    menu = prototype.GetHints().FindNestedElementByName("ShowInMenu")
    assert menu is not None and menu.GetAttribute("category") == "Unstructured Volume", name

source = AnalyticMesh(Resolution=[4, 3, 2], Distortion="Jitter")  # noqa: F405
split = HexahedraToTetrahedra(Input=source, SplitMode="Six tetrahedra (any mesh)")  # noqa: F405
gradient = VertexGradient(Input=split, Scalars=["POINTS", "Linear"])  # noqa: F405
gradient.UpdatePipeline()
info = gradient.GetDataInformation()
assert info.GetNumberOfCells() == 6 * 4 * 3 * 2, info.GetNumberOfCells()
for component, expected in enumerate((0.25, 0.15, 0.10)):
    low, high = gradient.PointData["Gradients"].GetRange(component)
    assert abs(low - expected) < 1e-12 and abs(high - expected) < 1e-12, (component, low, high)

five = HexahedraToTetrahedra(Input=Wavelet(WholeExtent=[0, 4, 0, 4, 0, 4]),  # noqa: F405
                             SplitMode="Five tetrahedra (structured grids)")
five.UpdatePipeline()
assert five.GetDataInformation().GetNumberOfCells() == 5 * 4 ** 3
print("plugin filters OK")
