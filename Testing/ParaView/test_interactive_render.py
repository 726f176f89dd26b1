"""One entry's interactive renders in ParaView (view.InteractiveRender, what the GUI does while the
camera moves). With the data above the view's LOD threshold, the entry draws its own image, marked as
an interactive frame by its mapper and within INTERACTIVE_RMSE of the still render (ParaView's LOD,
the mesh's opaque surface, is far further off: UseOwnLevelOfDetail off must give it back). Below the
threshold the interactive render is the full image, the window bitwise the still render's; and the
still render after interaction is bitwise the one before.

    pvbatch test_interactive_render.py <plugin> <preintegrated|hexahedral|barycentric>
"""
import re
import sys

from paraview.simple import *  # noqa: F401,F403
from pvscene import rgb_rmse as rmse, show_wavelet, window_rgb  # beside this script

plugin, mapper = sys.argv[1], sys.argv[2]
ENTRY, TETRAHEDRAL = {"preintegrated": ("Volume (Pre-integrated Tetrahedra)", True),
                      "hexahedral": ("Volume (Hexahedral Ray Cast)", False),
                      "barycentric": ("Volume (Barycentric Shells)", True)}[mapper]
# The entry's interactive window against its still window, RGB in [0, 1]: a reduced image stretched
# over the view blurs edges and detail; ParaView's LOD surface (no volume at all) is far beyond it.
INTERACTIVE_RMSE = 0.05
LOD_SURFACE_RMSE = 0.15  # the least ParaView's LOD must be off, for the test to tell the two apart
LoadPlugin(plugin, remote=False, ns=globals())  # noqa: F405

view, display = show_wavelet(ENTRY, 12, 256, HexahedraToTetrahedra if TETRAHEDRAL else None)  # noqa: F405
proxy = view.SMProxy


def window():
    """The view's RGB bytes as last rendered (not rendered again)."""
    return window_rgb(view)[0]


def interactive_frame():
    """What the entry's mapper says of the last frame it drew (its PrintSelf: the mapper is not
    wrapped in ParaView's Python): drawn as interactive, and its image sample distance."""
    text = str(display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper())
    return (int(re.search(r"InteractiveFrame: (\d)", text).group(1)) == 1,
            float(re.search(r"UsedImageSampleDistance: ([0-9.e+-]+)", text).group(1)))


proxy.StillRender()
still = window()
assert any(p != still[0] for p in still), "the still render drew nothing"

# Above the LOD threshold: the entry's own image.
view.LODThreshold = 0.0
for _ in range(3):
    proxy.InteractiveRender()
own = window()
drawn_as_interactive, distance = interactive_frame()
error = rmse(own, still)
print(f"own level of detail: interactive {drawn_as_interactive}, distance {distance:.3g}, RMSE {error:.4f}")
assert drawn_as_interactive, "the entry's mapper did not draw the interactive frame"
assert error < INTERACTIVE_RMSE, error

# ParaView's own LOD, for the record: the surface, far off.
display.UseOwnLevelOfDetail = 0
proxy.StillRender()
proxy.InteractiveRender()
surface_error = rmse(window(), still)
print(f"ParaView's level of detail: RMSE {surface_error:.4f}")
assert surface_error > LOD_SURFACE_RMSE, surface_error
display.UseOwnLevelOfDetail = 1

# Below the threshold: the full image while interacting, and the still render unchanged after.
view.LODThreshold = 1e9
proxy.StillRender()
proxy.InteractiveRender()
assert not interactive_frame()[0], "an interactive render below the LOD threshold was reduced"
assert window() == still, "an interactive render below the LOD threshold differs from the still render"
proxy.StillRender()
assert window() == still, "the still render after interaction differs"
print("interactive render OK")
