"""The plugin's representations from pvbatch / pvpython (and mpiexec -np N pvbatch): select one
("preintegrated": "Volume (Pre-integrated Tetrahedra)", "hexahedral": "Volume (Hexahedral Ray
Cast)", "barycentric": "Volume (Barycentric Shells)") on image data, check it is offered on unstructured, structured and multiblock data, drive it
with the colour map, opacity editor and the mapper's own properties, render, write the image and
compare it with the baseline: vtkImageDifference's thresholded error at most <threshold>, and at
most <fraction> of the pixels more than 2 levels off in some channel (the 2-rank run composites two
halves with IceT).

    pvbatch test_plugin_representation.py <plugin> <preintegrated|hexahedral|barycentric> <output.png> \
        [<baseline.png> <threshold> <fraction>]

With UV_SERVER=host:port in the environment (pvpython only) it first connects to that pvserver and
loads the plugin on both sides: the server renders, the client receives the image.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from pvscene import new_view  # beside this script

plugin, mapper, output = sys.argv[1], sys.argv[2], sys.argv[3]
baseline = sys.argv[4] if len(sys.argv) > 4 else None
threshold = float(sys.argv[5]) if len(sys.argv) > 5 else 10.0
fraction = float(sys.argv[6]) if len(sys.argv) > 6 else 0.0
# Each representation: its menu entry and the panel's settings the test drives.
ENTRY, SETTINGS = {
    "preintegrated": ("Volume (Pre-integrated Tetrahedra)",
                      {"Isovalues": [200.0], "IsosurfaceOpacity": 0.8, "IntegrationMode": "Partial pre-integration",
                       "TetrahedraOpacityThreshold": 0.999, "TetrahedraRenderMode": "Ray casting"}),
    "hexahedral": ("Volume (Hexahedral Ray Cast)",
                   {"Isovalues": [200.0], "IsosurfaceOpacity": 0.8,
                    "HexahedralIntegrationMode": "Accurate", "OpacityThreshold": 0.99}),
    "barycentric": ("Volume (Barycentric Shells)",
                    {"Isovalues": [200.0], "IsosurfaceOpacity": 0.8, "RenderMode": "Shells",
                     "AutomaticSamplesAcross": 256, "ShellOpacityThreshold": 0.99}),
}[mapper]
server = os.environ.get("UV_SERVER")
if server:
    host, port = server.split(":")
    Connect(host, int(port))  # noqa: F405
    LoadPlugin(plugin, remote=True, ns=globals())
    print(f"connected to {server}, server ranks: {servermanager.ActiveConnection.GetNumberOfDataPartitions()}")
LoadPlugin(plugin, remote=False, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
print(f"ranks: {ranks}")

view = new_view(300, (0.1, 0.1, 0.12))

# Image data (a parallel source: each rank gets its piece), as ParaView users meet it.
wavelet = Wavelet(WholeExtent=[-12, 12, -12, 12, -12, 12])  # noqa: F405
display = Show(wavelet, view)  # noqa: F405
assert ENTRY in display.Representation.Available, display.Representation.Available
display.Representation = ENTRY
ColorBy(display, ("POINTS", "RTData"))  # noqa: F405
lut = GetColorTransferFunction("RTData")  # noqa: F405
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(37.0, 277.0)
opacity = GetOpacityTransferFunction("RTData")  # noqa: F405
opacity.Points = [37.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0, 277.0, 0.6, 0.5, 0.0]
display.ScalarOpacityUnitDistance = 3.0
for name, value in SETTINGS.items():
    setattr(display, name, value)

# The same entry on an unstructured grid (generated hexahedra).
mesh = AnalyticMesh(Resolution=[6, 6, 6], Distortion="Twist")  # noqa: F405
mesh_display = Show(mesh, view)  # noqa: F405
assert ENTRY in mesh_display.Representation.Available, mesh_display.Representation.Available
Hide(mesh, view)  # noqa: F405

view.CameraPosition = [60.0, -45.0, 35.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
Render(view)  # noqa: F405
SaveScreenshot(output, view, ImageResolution=[300, 300])  # noqa: F405

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from baselines import nearest_baseline, read_png  # noqa: E402  (the Python tests' helper, on ParaView's VTK)


def pixel_differences(first, second):
    """Between two images' pixels (colour channels): how many differ by more than 2 levels, the
    largest difference, and the RMSE in levels."""
    channels = min(first.GetNumberOfComponents(), second.GetNumberOfComponents(), 3)
    off, worst, squares = 0, 0, 0.0
    for i in range(first.GetNumberOfTuples()):
        a, b = first.GetTuple(i), second.GetTuple(i)
        d = [abs(a[c] - b[c]) for c in range(channels)]
        worst = max(worst, max(d))
        off += 1 if max(d) > 2 else 0
        squares += sum(x * x for x in d) / channels
    return off, worst, (squares / first.GetNumberOfTuples()) ** 0.5


if baseline:
    error, baseline = nearest_baseline(output, baseline)
    images = [read_png(path).GetOutput().GetPointData().GetScalars() for path in (output, baseline)]
    off, worst, _ = pixel_differences(images[0], images[1])
    share = off / images[0].GetNumberOfTuples()
    print(f"image difference against {baseline}: thresholded {error:.3f} (at most {threshold}), "
          f"{100 * share:.2f}% of pixels more than 2 levels off (at most {100 * fraction:.2f}%), largest {worst:.0f}")
    assert error <= threshold, error
    assert share <= fraction, share
# ImageSampleDistance 2, a setting of every entry: the volume drawn at half the view's width and
# height, stretched over it. Near the full image (edges blur), but not it: the setting reached the
# mapper.


def screenshot_pixels(path):
    SaveScreenshot(path, view, ImageResolution=[300, 300])  # noqa: F405
    return read_png(path).GetOutput().GetPointData().GetScalars()


stem = os.path.splitext(output)[0]
full = screenshot_pixels(stem + "_sample_distance_1.png")
display.ImageSampleDistance = 2.0
Render(view)  # noqa: F405
stretched = screenshot_pixels(stem + "_sample_distance_2.png")
display.ImageSampleDistance = 1.0
changed, _, levels = pixel_differences(full, stretched)
print(f"image sample distance 2: RMSE {levels:.2f} levels against distance 1, {changed} pixels more than 2 off")
assert changed > 0, "ImageSampleDistance did not reach the mapper"
assert levels < 8.0, levels
# The entry is offered on a structured grid (a transformed image) and on multiblock data too (after
# the image: showing them may rescale the shared colour map).
for label, source in (("structured grid", Transform(Input=wavelet)),  # noqa: F405
                      ("multiblock", GroupDatasets(Input=[mesh, mesh]))):  # noqa: F405
    other = Show(source, view)  # noqa: F405
    assert ENTRY in other.Representation.Available, (label, other.Representation.Available)
    Hide(source, view)  # noqa: F405
print("plugin representation OK")
