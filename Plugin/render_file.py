"""Render any file ParaView reads with the plugin's volume representations, in one command.

    PYTHONPATH=/opt/unstructuredvolume/paraview-python/usr/lib/python3/dist-packages \\
      pvbatch Plugin/render_file.py MESH [--array NAME] [--views N | --time-steps] [--compare] ...

The Representation entry follows the data's 3D cell types unless --representation names one:
"Volume (Hexahedral Ray Cast)" where every 3D cell is a hexahedron, voxel, wedge, pyramid or
tetrahedron (and not all are tetrahedra), or the data is structured or image data; "Volume
(Pre-integrated Tetrahedra)" for tetrahedral meshes and for prisms, polyhedra and higher-order cells,
which that entry splits. Writes PREFIX_0000.png, PREFIX_0001.png, ... and one line per frame.
Run `pvbatch Plugin/render_file.py --help` for every option.
"""
import argparse
import math
import os
import sys
import time

ENTRIES = {
    "hexahedral": "Volume (Hexahedral Ray Cast)",
    "tetrahedra": "Volume (Pre-integrated Tetrahedra)",
    "shells": "Volume (Barycentric Shells)",
}
PARAVIEW_VOLUME = "Volume"
# Linear 3D cells the hexahedral ray caster walks without a split (VTK cell type ids).
VTK_TETRA, VTK_VOXEL, VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID = 10, 11, 12, 13, 14
RAY_CAST_CELLS = {VTK_TETRA, VTK_VOXEL, VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID}
# Grids whose cells are all one type, known from their extent without fetching the data.
GRID_CELL_TYPES = {"vtkImageData": VTK_VOXEL, "vtkUniformGrid": VTK_VOXEL, "vtkRectilinearGrid": VTK_VOXEL,
                   "vtkStructuredGrid": VTK_HEXAHEDRON}
PLUGIN_NAME = "UnstructuredVolume"
BACKGROUND = [0.1, 0.1, 0.12]
# The opacity ramp's top at --opacity 1, reached over a tenth of the data's diagonal: a moderate
# haze through which the far side of the mesh stays visible. A thin slab (a 2D case extruded one
# cell) gets its thickness as the distance instead, or it would hardly show.
OPACITY_AT_TOP = 0.5
UNIT_DISTANCE_SHARE_OF_DIAGONAL = 0.1


class UserError(Exception):
    """A problem with the command line or the file: reported in one line, without a traceback."""


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="pvbatch Plugin/render_file.py",
        description="Volume-render a file ParaView reads with the UnstructuredVolume plugin and write PNGs.")
    parser.add_argument("mesh", help="the file (any format ParaView reads; a PLOT3D grid with --q)")
    parser.add_argument("--q", metavar="QFILE", help="PLOT3D solution file: read MESH as its PLOT3D grid "
                                                    "(default for MESH.xyz: MESH.q where it exists)")
    parser.add_argument("--array", help="the array to colour by (default: the first point array with a "
                                        "range, else the first cell array with one)")
    parser.add_argument("--association", choices=("points", "cells"),
                        help="where --array lives (default: points if it is a point array, else cells)")
    parser.add_argument("--representation", choices=sorted(ENTRIES),
                        help="the plugin's entry to use (default: chosen from the cell types)")
    parser.add_argument("--preset", help="ParaView colour-map preset, e.g. \"Viridis (matplotlib)\" (\"Viridis\" from 6.0) "
                                         "(default: ParaView's default map)")
    parser.add_argument("--opacity", type=float, default=1.0,
                        help="scales the opacity ramp (default 1: 0 at the array's minimum to %g at its maximum)"
                        % OPACITY_AT_TOP)
    frames = parser.add_mutually_exclusive_group()
    frames.add_argument("--views", type=int, default=1, metavar="N", help="an orbit of N views around the data")
    frames.add_argument("--time-steps", action="store_true", help="one frame per time step of the file")
    parser.add_argument("--size", type=int, nargs=2, default=[512, 512], metavar=("W", "H"),
                        help="each view's size in pixels (default 512 512)")
    parser.add_argument("--compare", action="store_true",
                        help="ParaView's own Volume representation beside the plugin's (PNG twice as wide)")
    parser.add_argument("--output", default="render", metavar="PREFIX",
                        help="writes PREFIX_0000.png, ... (default: render)")
    parser.add_argument("--plugin", default=PLUGIN_NAME,
                        help="the plugin's .so, or the name of an installed plugin (default: "
                             f"{PLUGIN_NAME}, as `cmake --install` registers it with ParaView)")
    arguments = parser.parse_args(argv)
    if arguments.views < 1:
        parser.error("--views must be at least 1")
    if min(arguments.size) < 1:
        parser.error("--size must be positive")
    if arguments.opacity <= 0:
        parser.error("--opacity must be positive")
    if arguments.association and not arguments.array:
        parser.error("--association needs --array")
    return arguments


def open_file(simple, arguments):
    """The reader for the file, its multiblock output merged into one dataset."""
    if not os.path.isfile(arguments.mesh):
        raise UserError(f"no such file: {arguments.mesh}")
    solution = arguments.q
    beside = os.path.splitext(arguments.mesh)[0] + ".q"
    if solution is None and arguments.mesh.lower().endswith(".xyz") and os.path.exists(beside):
        solution = beside  # a PLOT3D grid's usual companion: its field
    if solution:
        if not os.path.exists(solution):
            raise UserError(f"no such file: {solution}")
        reader = simple.PLOT3DReader(FileName=arguments.mesh, QFileName=[solution])
    else:
        try:
            reader = simple.OpenDataFile(arguments.mesh)
        except RuntimeError:  # paraview.simple's way of saying that no reader takes the file
            reader = None
        if reader is None:
            raise UserError(f"ParaView has no reader for {arguments.mesh}")
    reader.UpdatePipeline()
    information = reader.GetDataInformation().DataInformation
    if information.GetCompositeDataSetType() >= 0:
        # Readers such as Exodus, OpenFOAM and PLOT3D give blocks; one dataset has one set of cell
        # types and arrays to choose from.
        merged = simple.MergeBlocks(Input=reader)
        merged.UpdatePipeline()
        return reader, merged
    return reader, reader


def three_dimensional_cell_types(servermanager, source):
    """The distinct VTK types of the source's 3D cells (a set of ids)."""
    from vtkmodules.vtkCommonDataModel import vtkCellTypes, vtkGenericCell

    information = source.GetDataInformation().DataInformation
    grid_cell_type = GRID_CELL_TYPES.get(information.GetDataSetTypeAsString())
    if grid_cell_type is not None:
        extent = information.GetExtent()
        flat = any(extent[2 * d + 1] <= extent[2 * d] for d in range(3))
        return set() if flat else {grid_cell_type}
    data = servermanager.Fetch(source)
    if hasattr(data, "GetDistinctCellTypesArray"):
        distinct = data.GetDistinctCellTypesArray()
        present = [int(distinct.GetValue(i)) for i in range(distinct.GetNumberOfTuples())]
    else:  # polygonal data and the like: no 3D cells, but ask anyway
        types = vtkCellTypes()
        data.GetCellTypes(types)
        present = [types.GetCellType(i) for i in range(types.GetNumberOfTypes())]
    cell = vtkGenericCell()
    found = set()
    for cell_type in present:
        cell.SetCellType(cell_type)
        if cell.GetCellDimension() == 3:
            found.add(cell_type)
    return found


def choose_entry(cell_types):
    """The plugin's entry for these 3D cell types: the ray caster takes linear cells without a split;
    an all-tetrahedra mesh and cells that need a split (prisms, polyhedra, higher order) go to the
    tetrahedra entry."""
    if cell_types == {VTK_TETRA} or not cell_types <= RAY_CAST_CELLS:
        return ENTRIES["tetrahedra"]
    return ENTRIES["hexahedral"]


def cell_type_names(cell_types):
    try:  # VTK 9.6 moves the query to vtkCellTypeUtilities and deprecates vtkCellTypes'
        from vtkmodules.vtkCommonDataModel import vtkCellTypeUtilities as names
    except ImportError:
        from vtkmodules.vtkCommonDataModel import vtkCellTypes as names
    return ", ".join(sorted(names.GetClassNameFromTypeId(t).replace("vtk", "") for t in cell_types))


def array_range(information, name):
    """The range of an array (its magnitude's when it has several components), or None."""
    array = information.GetArrayInformation(name)
    if array is None:
        return None
    return array.GetComponentRange(-1 if array.GetNumberOfComponents() > 1 else 0)


def choose_array(source, arguments):
    """(association, name, range) of the array to colour by."""
    information = source.GetDataInformation()
    point_data, cell_data = information.GetPointDataInformation(), information.GetCellDataInformation()
    if arguments.array:
        places = {"points": [("POINTS", point_data)], "cells": [("CELLS", cell_data)]}.get(
            arguments.association, [("POINTS", point_data), ("CELLS", cell_data)])
        for association, data in places:
            found = array_range(data, arguments.array)
            if found is not None:
                return association, arguments.array, found
        available = [f"{data.GetArrayInformation(i).GetName()} ({association.lower()})"
                     for association, data in (("POINTS", point_data), ("CELLS", cell_data))
                     for i in range(data.GetNumberOfArrays())]
        where = f" among the {arguments.association[:-1]} arrays" if arguments.association else ""
        raise UserError(f"no array named '{arguments.array}'{where}; the file has: "
                        + (", ".join(available) or "no arrays"))
    for association, data in (("POINTS", point_data), ("CELLS", cell_data)):
        for i in range(data.GetNumberOfArrays()):
            name = data.GetArrayInformation(i).GetName()
            if name.startswith("vtk"):  # VTK's bookkeeping (ghost levels, original ids), not a field
                continue
            found = array_range(data, name)
            if found[1] > found[0]:
                return association, name, found
    raise UserError(f"{arguments.mesh} has no point or cell array with a range to colour by")


def create_view(simple, size, scene):
    view = simple.CreateView("RenderView")
    scene.append(view)
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = BACKGROUND
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # older ParaView: the background is the view's own
        pass
    return view


def show_volume(simple, source, view, entry, association, name, scene):
    display = simple.Show(source, view)
    scene.append(display)
    if entry not in display.Representation.Available:
        raise UserError(f"the plugin offers no '{entry}' for this data (available: "
                        + ", ".join(display.Representation.Available) + ")")
    display.Representation = entry
    simple.ColorBy(display, (association, name))
    return display


def set_colour_map(simple, name, low, high, arguments, unit_distance, displays):
    """The preset over [low, high], and opacity rising linearly from 0 to a moderate maximum."""
    lut = simple.GetColorTransferFunction(name)
    if arguments.preset:
        lut.ApplyPreset(arguments.preset, True)
    if high <= low:  # a constant array: a range around its value, so the ramp has a slope
        low, high = low - 0.5, high + 0.5
    lut.RescaleTransferFunction(low, high)
    opacity = simple.GetOpacityTransferFunction(name)
    top = min(1.0, OPACITY_AT_TOP * arguments.opacity)
    opacity.Points = [low, 0.0, 0.5, 0.0, high, top, 0.5, 0.0]
    # Keep the range fixed over frames and time steps instead of following each step's data.
    lut.AutomaticRescaleRangeMode = "Never"
    for display in displays:
        display.LookupTable = lut
        display.ScalarOpacityFunction = opacity
        display.ScalarOpacityUnitDistance = unit_distance


def opacity_unit_distance(source):
    bounds = source.GetDataInformation().GetBounds()
    sides = [bounds[2 * d + 1] - bounds[2 * d] for d in range(3)]
    diagonal = math.sqrt(sum(side * side for side in sides))
    thinnest = min([side for side in sides if side > 0] or [1.0])
    return min(UNIT_DISTANCE_SHARE_OF_DIAGONAL * diagonal, thinnest) if diagonal > 0 else 1.0


def place_camera(view):
    """An oblique view of the whole data, from which the orbit turns about the view-up axis. (The
    view's own reset, not paraview.simple's, which renders: the first frame's time then holds the
    preparation.)"""
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Elevation(25.0)
    camera.Azimuth(35.0)
    camera.OrthogonalizeViewUp()
    view.ResetCamera()


def label(simple, view, text, scene):
    caption = simple.Text(Text=text)
    shown = simple.Show(caption, view)
    scene.extend([caption, shown])
    shown.WindowLocation = "Upper Left Corner"
    shown.FontSize = max(6, min(14, view.ViewSize[0] // 20))  # the entry's name about fits the view's width
    return caption


def copy_camera(source_view, target_view):
    for name in ("CameraPosition", "CameraFocalPoint", "CameraViewUp", "CameraViewAngle", "CameraParallelScale"):
        setattr(target_view, name, getattr(source_view, name))


def frame_times(arguments, reader):
    """One entry per frame: the time to show (None where the file has no time), and the orbit angle."""
    values = getattr(reader, "TimestepValues", [])
    try:
        steps = list(values)
    except TypeError:  # ParaView gives a lone time step as a number
        steps = [values]
    if arguments.time_steps:
        if not steps:
            raise UserError(f"{arguments.mesh} has no time steps")
        return [(t, 0.0) for t in steps]
    first = steps[0] if steps else None
    return [(first, 360.0 * i / arguments.views) for i in range(arguments.views)]


def preset_name(presets, name):
    """The name of the preset `name` asks for in this ParaView. ParaView 6 dropped the parenthesised
    origin from some names ("Viridis (matplotlib)" is "Viridis"), so a name that differs only by it
    is taken too, either way round."""
    if presets.HasPreset(name):
        return name
    def bare(text):
        return text.split(" (")[0].strip().lower()
    for index in range(presets.GetNumberOfPresets()):
        candidate = presets.GetPresetName(index)
        if bare(candidate) == bare(name):
            return candidate
    # (ApplyPreset reports success even for an unknown name.)
    raise UserError(f"no colour-map preset named '{name}'")


def load_plugin(simple, plugin):
    """A path loads that .so; a name loads the plugin ParaView lists under it (installed)."""
    if os.sep not in plugin:
        try:
            simple.LoadDistributedPlugin(plugin, remote=False, ns={})
        except RuntimeError:
            raise UserError(f"ParaView lists no plugin named {plugin} (run `cmake --install` of the "
                            "plugin build, or pass --plugin with the path of its .so)") from None
        return
    if not os.path.exists(plugin):
        raise UserError(f"no plugin at {plugin} (build it, or pass --plugin)")
    simple.LoadPlugin(plugin, remote=False, ns={})


def render(arguments):
    from paraview import servermanager
    from paraview import simple

    if arguments.preset:
        arguments.preset = preset_name(servermanager.vtkSMTransferFunctionPresets.GetInstance(), arguments.preset)
    load_plugin(simple, arguments.plugin)
    reader, source = open_file(simple, arguments)
    frames = frame_times(arguments, reader)
    if frames[0][0] is not None:
        source.UpdatePipeline(frames[0][0])
    cell_types = three_dimensional_cell_types(servermanager, source)
    if not cell_types:
        raise UserError(f"{arguments.mesh} has no 3D cells to volume-render")
    entry = ENTRIES[arguments.representation] if arguments.representation else choose_entry(cell_types)
    association, name, (low, high) = choose_array(source, arguments)
    if arguments.time_steps and len(frames) > 1:
        low, high = range_over_time(source, association, name, [t for t, _ in frames], (low, high))
    print(f"representation: {entry} (3D cells: {cell_type_names(cell_types)}); colouring by "
          f"{association.lower()} array '{name}' over [{low:g}, {high:g}]", flush=True)
    os.makedirs(os.path.dirname(os.path.abspath(arguments.output)), exist_ok=True)

    scene = []  # every proxy made here, deleted before exit (else Mesa's GLX aborts pvbatch's exit)
    try:
        view = create_view(simple, arguments.size, scene)
        views = [view]
        displays = [show_volume(simple, source, view, entry, association, name, scene)]
        layout = None
        if arguments.compare:
            paraview_view = create_view(simple, arguments.size, scene)
            views.append(paraview_view)
            displays.append(show_volume(simple, source, paraview_view, PARAVIEW_VOLUME, association, name, scene))
            label(simple, view, entry, scene)
            label(simple, paraview_view, "ParaView's " + PARAVIEW_VOLUME, scene)
            layout = side_by_side(simple, view, paraview_view)
        set_colour_map(simple, name, low, high, arguments, opacity_unit_distance(source), displays)
        place_camera(view)
        write_frames(simple, arguments, frames, entry, views, layout)
    finally:
        for proxy in reversed(scene):
            simple.Delete(proxy)


def side_by_side(simple, left, right):
    layout = simple.CreateLayout("render_file")
    layout.SplitHorizontal(0, 0.5)
    simple.AssignViewToLayout(view=left, layout=layout, hint=1)
    simple.AssignViewToLayout(view=right, layout=layout, hint=2)
    return layout


def write_frames(simple, arguments, frames, entry, views, layout):
    """One PNG per frame (both views in one with a layout), and a progress line for each."""
    camera = views[0].GetActiveCamera()
    previous_angle = 0.0
    for index, (time_value, angle) in enumerate(frames):
        start = time.time()
        camera.Azimuth(angle - previous_angle)
        previous_angle = angle
        for shown in views:
            if time_value is not None:
                shown.ViewTime = time_value
            if shown is not views[0]:
                copy_camera(views[0], shown)
        path = f"{arguments.output}_{index:04d}.png"
        if layout is not None:
            simple.SaveScreenshot(path, layout, SaveAllViews=1,
                                  ImageResolution=[2 * arguments.size[0], arguments.size[1]])
        else:
            simple.SaveScreenshot(path, views[0], ImageResolution=list(arguments.size))
        when = f", time {time_value:g}" if arguments.time_steps else ""
        drawn = entry + (f" and {PARAVIEW_VOLUME}" if layout is not None else "")
        print(f"frame {index + 1}/{len(frames)}{when}: {path} ({drawn}), {time.time() - start:.2f} s", flush=True)


def range_over_time(source, association, name, times, first_range):
    """The array's range over every time step, so that the frames share one colour scale."""
    low, high = first_range
    for t in times:
        source.UpdatePipeline(t)
        information = source.GetDataInformation()
        data = information.GetPointDataInformation() if association == "POINTS" else information.GetCellDataInformation()
        found = array_range(data, name)
        if found is not None:
            low, high = min(low, found[0]), max(high, found[1])
    return low, high


def main(argv):
    arguments = parse_arguments(argv)
    try:
        render(arguments)
    except UserError as error:
        print(f"render_file: error: {error}", file=sys.stderr, flush=True)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
