"""ParaView's interactive render of each entry: ParaView's level of detail against the entry's own
reduced image, in frame time and in error (a command, not a test).

    PYTHONPATH=/opt/unstructuredvolume/paraview-python/usr/lib/python3/dist-packages \\
      pvbatch paraview_interaction.py <plugin> [--size 512] [--frames 6] [--output INTERACTION.md] [--images DIR]

The scene: VTK's wavelet on 64^3 points, as 1.25 M tetrahedra for the tetrahedral entries (the
plugin's Hexahedra To Tetrahedra) and as its 250 k cells for the hexahedral one, coloured and made
transparent by RTData, seen from 20 degrees above. For each entry:
- still: the median still frame (view.StillRender) and its image, the reference of this table: each
  entry's still frame is exact-grade (the accuracy tests bound it against the exact reference);
- LOD: interactive renders (view.InteractiveRender) with the data above the LOD threshold, so that
  ParaView draws what its level of detail gives (vtkPVLODVolume's LOD mapper)
  (the representation's UseOwnLevelOfDetail off);
- own: the same interactive renders with UseOwnLevelOfDetail on (the default): the entry draws its own
  image, reduced to the time ParaView allows an interactive frame (AutoAdjustSampleDistances);
- full: interactive renders below the LOD threshold, where every entry draws its full image.
Each interactive row: the median frame of `frames` after two to settle, and the RMSE over the window's
RGB (8-bit, as shown) against the still frame. Writes INTERACTION.md beside this script (how and where it
ran, and the table) and each entry's four images to --images.
"""
import argparse
import os
import platform
import statistics
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.vtkIOImage import vtkPNGWriter

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ParaView"))
from pvscene import rgb_rmse, show_wavelet, window_rgb  # noqa: E402  (the scene the interaction test uses)

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--frames", type=int, default=6)
parser.add_argument("--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "INTERACTION.md"))
parser.add_argument("--images", default=os.path.join("out", "paraview_interaction"))
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())  # noqa: F405

ENTRIES = (("Volume (Pre-integrated Tetrahedra)", True), ("Volume (Barycentric Shells)", True),
           ("Volume (Hexahedral Ray Cast)", False))


def write_png(image, path):
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def frames(view, render, count):
    """`render` twice to settle, then `count` times, each after a small turn; the median seconds."""
    camera = view.GetActiveCamera()
    times = []
    for k in range(count + 2):
        camera.Azimuth(1.0 if k % 2 else -1.0)  # back and forth: the view stays put on the whole
        start = time.perf_counter()
        render()
        times.append(time.perf_counter() - start)
    return statistics.median(times[2:])


def measure(entry, tetrahedral, folder):
    view, display = show_wavelet(entry, 32, args.size, HexahedraToTetrahedra if tetrahedral else None)  # noqa: F405
    proxy = view.SMProxy
    still_time = frames(view, proxy.StillRender, args.frames)
    proxy.StillRender()
    still, image = window_rgb(view)
    stem = entry.split("(")[1].rstrip(")").replace(" ", "_").lower()
    write_png(image, os.path.join(folder, f"{stem}_still.png"))
    rows = [(entry, "still", still_time, 0.0)]
    for label, threshold, own in (("ParaView's LOD", 0.0, 0), ("own reduced image", 0.0, 1),
                                  ("full image (below the LOD threshold)", 1e9, 1)):
        view.LODThreshold = threshold
        display.UseOwnLevelOfDetail = own
        proxy.StillRender()  # a changed representation delivers its data in a still render
        seconds = frames(view, proxy.InteractiveRender, args.frames)
        proxy.InteractiveRender()
        pixels, image = window_rgb(view)
        write_png(image, os.path.join(folder, f"{stem}_{('lod', 'own', 'full')[own + (threshold > 0)]}.png"))
        rows.append((entry, label, seconds, rgb_rmse(pixels, still)))
    Delete(display)  # noqa: F405
    Delete(view)  # noqa: F405
    return rows


def header(started, view_strings):
    """How and where the run was made."""
    from paraview import servermanager
    version = "ParaView " + servermanager.vtkSMProxyManager.GetParaViewSourceVersion().split()[-1]
    return [
        "# ParaView: interactive renders of each entry",
        "",
        "Written by `Testing/Benchmark/paraview_interaction.py` from one run; do not edit by hand, run it again.",
        "",
        f"- Command: `pvbatch {' '.join(os.path.relpath(a) if os.path.exists(a) else a for a in sys.argv)}`",
        f"- Run started: {started}",
        f"- {version}; {platform.processor() or platform.machine()}, {os.cpu_count()} logical CPUs; {view_strings}",
        f"- Scene: VTK's wavelet on 64^3 points ({args.size} x {args.size} px): 1.25 M tetrahedra for the tetrahedral "
        "entries, its 250 k cells for the hexahedral one",
        "",
        "Per entry: the still frame (the reference of the errors: each entry's still frame is exact-grade), then",
        "interactive renders (view.InteractiveRender, as while the camera moves) with the data above the view's LOD",
        "threshold, drawn by ParaView's level of detail (UseOwnLevelOfDetail off: the mesh's surface) and by the",
        "entry's own reduced image (on, the default), and below the threshold (the full image). Seconds: the",
        "median frame; RMSE: over the window's RGB, in [0, 1], against the still frame.",
        "",
    ]


def opengl_strings():
    window = GetActiveViewOrCreate("RenderView").GetRenderWindow()  # noqa: F405
    window.Render()
    info = window.ReportCapabilities()
    pick = [line.split(":", 1)[1].strip() for line in info.splitlines() if line.startswith("OpenGL renderer string")]
    return f"OpenGL renderer: {pick[0]}" if pick else "OpenGL renderer: unknown"


def main():
    started = time.strftime("%Y-%m-%d %H:%M %Z")
    folder = args.images
    os.makedirs(folder, exist_ok=True)
    strings = opengl_strings()
    rows = []
    for entry, tetrahedral in ENTRIES:
        rows += measure(entry, tetrahedral, folder)
        print(*rows[-3:], sep="\n", flush=True)
    lines = ["| entry | frame | seconds | x still | RMSE against still (RGB) |", "|---|---|---:|---:|---:|"]
    for entry, label, seconds, error in rows:
        still = next(s for e, l, s, _ in rows if e == entry and l == "still")
        lines.append(f"| {entry} | {label} | {seconds:.3f} | {seconds / still:.2f} | {error:.4f} |")
    with open(args.output, "w") as out:
        out.write("\n".join(header(started, strings) + lines) + "\n")
    print("\n".join(lines))


main()
