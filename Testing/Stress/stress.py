"""Seeded stress cases: each renders one generated input through every mapper that takes it and the
reference, in a process of its own, so that a crash or a hang is reported as such.

A case draws one choice from each axis below (the seed and the case number decide). Each mapper's
float image must be finite, premultiplied within [0, 1], raise no VTK error (the mappers' GL-error
debug mode is on, so a GL error after any pass is one), and agree with the reference: RMSE within
the case's bound, and the reference's covered pixels covered. Where it fails, each pixel is taken
against the nearest of the reference's one-sided limits (NUDGE): a ray exactly in a face, through an
edge or along a silhouette has no one value.

    python3 Testing/Stress/stress.py --cases 500 --seed 7     # the long run
    python3 Testing/Stress/stress.py --case 12 --seed 7       # one case, in this process

ctest runs a small fixed set (stress.quick). Run with the VTK build's Python path and a display, as
the Python tests are."""
import argparse
import itertools
import math
import os
import random
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Python"))

MESHES = ("tetrahedra", "hexahedra", "twisted_hexahedra", "hex_dominant", "collapsed_layers", "jittered_tetrahedra",
          "slivers", "flat_tetrahedra", "inverted_tetrahedra", "inverted_hexahedra", "duplicate_points_tetrahedra",
          "duplicate_points_hexahedra", "tangled_tetrahedra", "with_2d_1d_cells")
SCALARS = ("smooth", "constant", "huge_range", "tiny_range", "some_nan", "all_nan", "some_inf", "int8", "uint16",
           "int64", "uint64", "float32", "cell_data")
PLACEMENTS = ("unit", "offset_1e6", "offset_1e9", "scale_1e-6", "scale_1e-9", "scale_1e6", "scale_1e12")
CAMERAS = ("outside", "parallel", "inside", "on_boundary_face", "on_vertex", "grazing", "near_plane_inside",
           "axis_aligned", "far_away")
FUNCTIONS = ("ramp", "spike", "all_opaque", "all_transparent", "single_node", "empty", "unit_distance_1e-9",
             "unit_distance_1e9")
SIZES = (1, 17, 48)
AXES = {"mesh": MESHES, "scalars": SCALARS, "placement": PLACEMENTS, "camera": CAMERAS, "function": FUNCTIONS,
        "size": SIZES}
TIMEOUT_S = 120

# RMSE against the reference each case must stay within: loose enough for the mappers' stated
# approximations (centroid order, shells' sampling), tight enough that a missing or doubled part of
# the volume fails.
RMSE_BOUND = 0.03
COVERED_ALPHA = 0.2  # a pixel the reference makes this opaque must be drawn by every mapper


# The contract of test_routes.SubPixelCoverage: every mapper finds the cells a ray crosses by
# rasterising projected faces, whose corners the rasteriser snaps to its sub-pixel grid (GL: at least
# 4 bits), so a pixel whose centre lies within 1/16 pixel of a projected edge is covered as the
# rasteriser decides. Up to BAND_PIXELS such pixels of a failing image are taken from the image
# itself; the rest must pass. (At one pixel, a mesh a twentieth of a pixel across puts its one pixel
# there.)
BAND = 1.0 / 16
BAND_PIXELS = 3


def projected_edges(mesh, camera, size):
    """The 3D cells' edges on screen, in pixels: ((x0, y0), (x1, y1)) each. An edge reaching the eye's
    plane (a face through the eye, seen edge-on, projects onto a line) is cut just short of it."""
    matrix = camera.GetCompositeProjectionTransformMatrix(1.0, -1, 1)
    rows = [[matrix.GetElement(i, j) for j in range(4)] for i in range(4)]
    clip = []
    for p in range(mesh.GetNumberOfPoints()):
        x = list(mesh.GetPoint(p)) + [1.0]
        clip.append([sum(r[j] * x[j] for j in range(4)) for r in rows])
    edges = set()
    for c in range(mesh.GetNumberOfCells()):
        cell = mesh.GetCell(c)
        if cell.GetCellDimension() != 3:
            continue
        for e in range(cell.GetNumberOfEdges()):
            ids = cell.GetEdge(e).GetPointIds()
            edges.add(tuple(sorted((ids.GetId(0), ids.GetId(1)))))
    def screen(v):
        return ((v[0] / v[3] + 1) * size / 2, (v[1] / v[3] + 1) * size / 2)
    result = []
    for a, b in edges:
        ca, cb = clip[a], clip[b]
        if ca[3] <= 0 and cb[3] <= 0:
            continue
        if ca[3] <= 0:
            ca, cb = cb, ca
        if cb[3] <= 0:
            cut = 1e-9 * ca[3]  # just in front of the eye's plane
            s = (ca[3] - cut) / (ca[3] - cb[3])
            cb = [u + s * (v - u) for u, v in zip(ca, cb)]
        result.append((screen(ca), screen(cb)))
    return result


def within_band(pixel, size, edges):
    """Whether the pixel's centre lies within BAND of an edge on screen."""
    cx, cy = pixel % size + 0.5, pixel // size + 0.5
    for (ax, ay), (bx, by) in edges:
        dx, dy = bx - ax, by - ay
        length2 = dx * dx + dy * dy
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((cx - ax) * dx + (cy - ay) * dy) / length2))
        if math.hypot(ax + t * dx - cx, ay + t * dy - cy) <= BAND:
            return True
    return False


def rasteriser_band(image, expected, mesh, camera, size):
    """The image's pixels off `expected` (by more than 0.05 in a channel) when they are at most
    BAND_PIXELS, all within BAND of a projected edge: `expected` with those pixels taken from the
    image, else None."""
    from fixtures import copy_image
    drawn, truth = image.GetPointData().GetScalars(), expected.GetPointData().GetScalars()
    off = [p for p in range(size * size)
           if max(abs(a - b) for a, b in zip(drawn.GetTuple4(p), truth.GetTuple4(p))) > 0.05]
    if not off or len(off) > BAND_PIXELS:
        return None
    edges = projected_edges(mesh, camera, size)
    if not all(within_band(p, size, edges) for p in off):
        return None
    result = copy_image(expected)
    for p in off:
        result.GetPointData().GetScalars().SetTuple4(p, *drawn.GetTuple4(p))
    return result


# A pixel whose ray lies exactly in a face, through an edge or a vertex, or along a silhouette has
# no one value: moved by any amount, however small, the ray falls to one side, and the mappers'
# float arithmetic and the reference's exact one may pick different sides. Where an image fails
# against the reference, each pixel is compared with the nearest of the reference and its images
# with the camera moved by NUDGE of the mesh's size right, left, up and down: one-sided limits.
NUDGE = 1e-6


def nudged_cameras(camera, distance):
    """`camera` moved by `distance` right, left, up and down (position and focal point together)."""
    from vtkmodules.vtkRenderingCore import vtkCamera
    position, focal, up = camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp()
    forward = [f - p for f, p in zip(focal, position)]
    right = [forward[1] * up[2] - forward[2] * up[1], forward[2] * up[0] - forward[0] * up[2],
             forward[0] * up[1] - forward[1] * up[0]]
    upward = [right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
              right[0] * forward[1] - right[1] * forward[0]]
    cameras = []
    for axis in (right, upward):
        length = math.sqrt(sum(a * a for a in axis)) or 1.0
        for sign in (1.0, -1.0):
            step = [sign * distance * a / length for a in axis]
            moved = vtkCamera()
            moved.DeepCopy(camera)
            moved.SetPosition(*[p + d for p, d in zip(position, step)])
            moved.SetFocalPoint(*[f + d for f, d in zip(focal, step)])
            cameras.append(moved)
    return cameras


def nearest_limits(image, references):
    """A copy of references[0] whose every pixel is the one of `references` nearest `image`'s."""
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy
    drawn = vtk_to_numpy(image.GetPointData().GetScalars())
    stack = numpy.stack([vtk_to_numpy(r.GetPointData().GetScalars()) for r in references])
    nearest = numpy.argmin(((stack - drawn[None]) ** 2).sum(axis=2), axis=0)
    chosen = stack[nearest, numpy.arange(drawn.shape[0])]
    result = vtkImageData()
    result.DeepCopy(references[0])
    array = numpy_to_vtk(numpy.ascontiguousarray(chosen, dtype=numpy.float32), deep=True)
    array.SetName(references[0].GetPointData().GetScalars().GetName())
    result.GetPointData().SetScalars(array)
    return result


def choose(seed, number):
    """The case's choice on every axis."""
    rng = random.Random(seed * 100003 + number)
    return {axis: rng.choice(choices) for axis, choices in AXES.items()}


def build_mesh(case):
    from fixtures import analytic, analytic_hexahedra, hex_dominant
    from unstructuredvolume import vtkAnalyticMeshSource
    kind = case["mesh"]
    base = kind.rsplit("_", 1)[-1]
    if kind == "tetrahedra":
        return analytic(5)
    if kind == "jittered_tetrahedra":
        return analytic(5, distortion=vtkAnalyticMeshSource.JITTER)
    if kind == "hexahedra":
        return analytic_hexahedra(5)
    if kind == "twisted_hexahedra":
        return analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.TWIST)
    if kind == "hex_dominant":
        return hex_dominant(5)
    if kind == "collapsed_layers":
        return collapse_layers(analytic_hexahedra(6))
    if kind == "flat_tetrahedra":
        return collapse_layers(analytic(6))
    if kind == "slivers":
        return delaunay_slivers()
    source = analytic(4) if base == "tetrahedra" else analytic_hexahedra(4)
    if kind.startswith("inverted"):
        return invert_every_other_cell(source)
    if kind.startswith("duplicate_points"):
        return points_of_their_own(source)
    if kind == "tangled_tetrahedra":
        return every_cell_twice(source)
    return with_lower_dimensional_cells(analytic(4))


def collapse_layers(mesh):
    """Every other layer of the grid's points moved onto the layer below: zero-thickness cells."""
    points = mesh.GetPoints()
    layers = sorted({round(points.GetPoint(i)[2], 9) for i in range(points.GetNumberOfPoints())})
    for i in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(i)
        k = layers.index(round(z, 9))
        if k % 2:
            points.SetPoint(i, x, y, layers[k - 1])
    return mesh


def field_at(x, y, z):
    return 0.5 + 0.3 * math.sin(2.0 * x) * math.cos(1.5 * y) + 0.2 * z


def delaunay_slivers():
    """vtkDelaunay3D of a regular 7^3 lattice moved by a millionth of its spacing: the lattice's
    co-spherical points make flat slivers (tetrahedra of almost no volume) all through the mesh."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkDelaunay3D
    rng = random.Random(5)
    points, values = vtkPoints(), vtkDoubleArray()
    for k in range(7):
        for j in range(7):
            for i in range(7):
                p = [-1.0 + c / 3.0 + 1e-6 * rng.uniform(-1, 1) / 3.0 for c in (i, j, k)]
                points.InsertNextPoint(*p)
                values.InsertNextValue(field_at(*p))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    cloud.GetPointData().SetScalars(values)
    delaunay = vtkDelaunay3D()
    delaunay.SetInputData(cloud)
    delaunay.Update()
    return delaunay.GetOutput()


def cells_of(mesh):
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        yield mesh.GetCellType(c), [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


def rebuilt(mesh, cells, points=None, values=None):
    """An unstructured grid of (type, ids) cells over `points` and `values` (default: the mesh's)."""
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points or mesh.GetPoints())
    grid.GetPointData().SetScalars(values or mesh.GetPointData().GetScalars())
    for kind, ids in cells:
        grid.InsertNextCell(kind, len(ids), ids)
    return grid


def invert_every_other_cell(mesh):
    """Every other cell turned inside out (negative volume) over the same space: a tetrahedron's first
    two corners swapped, a hexahedron's top and bottom faces swapped."""
    from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON
    cells = []
    for c, (kind, ids) in enumerate(cells_of(mesh)):
        if c % 2:
            ids = ids[4:] + ids[:4] if kind == VTK_HEXAHEDRON else [ids[1], ids[0]] + ids[2:]
        cells.append((kind, ids))
    return rebuilt(mesh, cells)


def points_of_their_own(mesh):
    """Every cell on copies of its points, as exporters of discontinuous fields write meshes: no two
    cells share a point id, so no face is shared by id though every interior face is by position."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    points, values = vtkPoints(), vtkDoubleArray()
    source = mesh.GetPointData().GetScalars()
    cells = []
    for kind, ids in cells_of(mesh):
        copies = []
        for i in ids:
            copies.append(points.InsertNextPoint(mesh.GetPoint(i)))
            values.InsertNextValue(source.GetValue(i))
        cells.append((kind, copies))
    return rebuilt(mesh, cells, points, values)


def every_cell_twice(mesh):
    """Each cell twice over the same points: coincident (tangled) cells whose media superpose."""
    cells = []
    for cell in cells_of(mesh):
        cells += [cell, cell]
    return rebuilt(mesh, cells)


def with_lower_dimensional_cells(mesh):
    """The tetrahedra with triangles on some of their faces, lines along some edges and vertex and
    polyvertex cells mixed in between them: only the 3D cells hold the volume."""
    from vtkmodules.vtkCommonDataModel import VTK_LINE, VTK_POLY_VERTEX, VTK_TRIANGLE, VTK_VERTEX
    cells = []
    for c, (kind, ids) in enumerate(cells_of(mesh)):
        if c % 5 == 0:
            cells.append((VTK_TRIANGLE, ids[:3]))
        if c % 7 == 0:
            cells.append((VTK_LINE, ids[1:3]))
        if c % 11 == 0:
            cells += [(VTK_VERTEX, ids[:1]), (VTK_POLY_VERTEX, ids[:3])]
        cells.append((kind, ids))
    return rebuilt(mesh, cells)


def apply_scalars(mesh, case):
    from vtkmodules.vtkCommonCore import (vtkDoubleArray, vtkFloatArray, vtkTypeInt8Array, vtkTypeInt64Array,
                                          vtkTypeUInt16Array, vtkTypeUInt64Array)
    from vtkmodules.vtkFiltersCore import vtkPointDataToCellData
    source = mesh.GetPointData().GetScalars()
    values = [source.GetValue(i) for i in range(source.GetNumberOfTuples())]
    low, high = min(values), max(values)
    unit = [(v - low) / (high - low) for v in values]
    kind = case["scalars"]
    array = {"int8": vtkTypeInt8Array, "uint16": vtkTypeUInt16Array, "int64": vtkTypeInt64Array,
             "uint64": vtkTypeUInt64Array, "float32": vtkFloatArray}.get(kind, vtkDoubleArray)()
    array.SetName("f")
    for i, u in enumerate(unit):
        if kind == "constant":
            v = 0.5
        elif kind == "huge_range":
            v = 1e30 * (2 * u - 1)
        elif kind == "tiny_range":
            v = 1.0 + 1e-12 * u
        elif kind == "some_nan":
            v = float("nan") if i % 17 == 5 else u
        elif kind == "all_nan":
            v = float("nan")
        elif kind == "some_inf":
            v = (float("inf"), float("-inf"))[i % 2] if i % 13 == 4 else u
        elif kind == "int64":  # beyond a double's integers: 2^62 steps of one
            v = 2 ** 62 - 1000 + round(2000 * u)
        elif kind == "uint64":  # the top of the unsigned range
            v = 2 ** 64 - 1 - round(1e15 * u)
        elif kind == "int8":
            v = round(-100 + 200 * u)
        elif kind == "uint16":
            v = round(60000 * u)
        else:
            v = u
        array.InsertNextValue(v)
    mesh.GetPointData().SetScalars(array)
    if kind == "cell_data":
        average = vtkPointDataToCellData()
        average.SetInputData(mesh)
        average.PassPointDataOff()
        average.Update()
        mesh = average.GetOutput()
        mesh.GetCellData().SetActiveScalars("f")
    return mesh


def place(mesh, case):
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
    kind = case["placement"]
    if kind == "unit":
        return mesh
    transform = vtkTransform()
    if kind.startswith("offset"):
        offset = float(kind.split("_")[1])
        transform.Translate(offset, -2 * offset, 3 * offset)
    else:
        factor = float(kind.split("_")[1])
        transform.Scale(factor, factor, factor)
    moved = vtkTransformFilter()
    moved.SetTransform(transform)
    moved.SetOutputPointsPrecision(1)  # double: an offset of 1e6 in float would move the points
    moved.SetInputData(mesh)
    moved.Update()
    return moved.GetOutput()


def scalar_range(mesh):
    data = mesh.GetPointData().GetScalars() or mesh.GetCellData().GetScalars()
    values = [data.GetValue(i) for i in range(data.GetNumberOfTuples())]
    finite = [v for v in values if math.isfinite(v)]
    return (min(finite), max(finite)) if finite else (0.0, 1.0)


def make_property(mesh, case):
    from fixtures import property_from_nodes
    low, high = scalar_range(mesh)
    if high <= low:
        high = low + 1.0
    unit = 0.3 * mesh.GetLength()
    kind = case["function"]
    colours = ((low, (0.2, 0.3, 0.9)), (high, (0.9, 0.3, 0.1)))
    if kind == "empty":  # no node at all: VTK evaluates both functions to zero
        return property_from_nodes((), (), unit)
    if kind.startswith("unit_distance"):
        return property_from_nodes(((low, 0.0), (high, 0.8)), colours, float(kind.split("_")[-1]))
    if kind == "spike":
        centre = low + 0.6 * (high - low)
        opacity = ((low, 0.0), (centre - 0.01 * (high - low), 0.0), (centre, 0.9), (centre + 0.01 * (high - low), 0.0),
                   (high, 0.0))
    elif kind == "all_opaque":
        opacity = ((low, 1.0), (high, 1.0))
    elif kind == "all_transparent":
        opacity = ((low, 0.0), (high, 0.0))
    elif kind == "single_node":
        opacity, colours = ((0.5 * (low + high), 0.4),), ((0.5 * (low + high), (0.8, 0.6, 0.2)),)
    else:
        opacity = ((low, 0.0), (high, 0.8))
    return property_from_nodes(opacity, colours, unit)


def make_camera(mesh, case):
    from fixtures import camera_for
    from vtkmodules.vtkRenderingCore import vtkCamera
    bounds = mesh.GetBounds()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    size = mesh.GetLength()
    kind = case["camera"]
    if kind in ("outside", "parallel", "far_away", "axis_aligned"):
        distance = 50.0 if kind == "far_away" else 2.6
        camera = camera_for(mesh, *((0.0, 0.0) if kind == "axis_aligned" else (30.0, 25.0)),
                            parallel=kind == "parallel", distance=distance)
        camera.SetClippingRange(0.01 * size, 10 * (distance + 1) * size)  # in proportion, as VTK's reset
        return camera
    camera = vtkCamera()
    if kind == "on_vertex":
        # Exactly on the mesh's point nearest its lowest corner, looking at the centre.
        corner = min(range(mesh.GetNumberOfPoints()),
                     key=lambda i: sum((mesh.GetPoint(i)[a] - bounds[2 * a]) ** 2 for a in range(3)))
        camera.SetPosition(mesh.GetPoint(corner))
        camera.SetFocalPoint(centre)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(60)
        camera.SetClippingRange(0.005 * size, 5 * size)
        return camera
    if kind == "grazing":
        # The view direction in the plane of a layer of points near the middle, so the middle row of
        # pixels (odd sizes) runs along the faces in that plane.
        middle = min(range(mesh.GetNumberOfPoints()), key=lambda i: abs(mesh.GetPoint(i)[2] - centre[2]))
        z = mesh.GetPoint(middle)[2]
        camera.SetPosition(centre[0], bounds[2] - 1.5 * size, z)
        camera.SetFocalPoint(centre[0], centre[1], z)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(30)
        camera.SetClippingRange(0.01 * size, 5 * size)
        return camera
    # Inside, on the boundary face x = xmin, or just outside it with the near plane beyond it.
    x = {"inside": centre[0] - 0.2 * size, "on_boundary_face": bounds[0],
         "near_plane_inside": bounds[0] - 0.003 * size}[kind]
    camera.SetPosition(x, centre[1] + 0.01 * size, centre[2] + 0.02 * size)
    camera.SetFocalPoint(bounds[1], centre[1] + 0.01 * size, centre[2] + 0.02 * size)
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(60)
    camera.SetClippingRange(0.005 * size, 5 * size)
    return camera


def mappers_for(mesh):
    """(name, factory, settings) of every mapper that takes the mesh: the tetrahedral ones only where
    every cell is a tetrahedron."""
    from vtkmodules.vtkCommonDataModel import VTK_TETRA
    from unstructuredvolume import (vtkBarycentricShellMapper, vtkHexahedralRayCastMapper,
                                    vtkPreIntegratedTetrahedraMapper)
    found = [("hexahedral", vtkHexahedralRayCastMapper, {})]
    solid = [mesh.GetCellType(c) for c in range(mesh.GetNumberOfCells()) if mesh.GetCell(c).GetCellDimension() == 3]
    if all(kind == VTK_TETRA for kind in solid):
        found += [("tetrahedra", vtkPreIntegratedTetrahedraMapper, {}),
                  ("shells", vtkBarycentricShellMapper, {}),
                  ("cell projection", vtkBarycentricShellMapper, {"RenderMode": 1})]
    return found


def accuracy_against(image, expected):
    """(RMSE, covered pixels the image leaves out) against `expected`."""
    from fixtures import rmse
    truth, rgba = expected.GetPointData().GetScalars(), image.GetPointData().GetScalars()
    missed = sum(1 for p in range(truth.GetNumberOfTuples())
                 if truth.GetTuple4(p)[3] > COVERED_ALPHA and rgba.GetTuple4(p)[3] < 0.5 * COVERED_ALPHA)
    return rmse(image, expected)[0], missed


def run_case(seed, number):
    """Renders the case; returns a list of failures (empty: passed)."""
    from fixtures import Scene, finite_image, reference, rmse
    from unstructuredvolume import vtkUnstructuredVolumeMapper
    vtkUnstructuredVolumeMapper.SetGLErrorChecks(True)
    case = choose(seed, number)
    mesh = place(apply_scalars(build_mesh(case), case), case)
    prop, camera, size = make_property(mesh, case), make_camera(mesh, case), case["size"]
    expected = reference(mesh, prop, camera, size)
    limits = None  # the reference's one-sided limits, made at the first accuracy failure
    failures = []
    for name, factory, settings in mappers_for(mesh):
        scene = Scene(mesh, prop, camera, size, mapper=factory(), **settings)
        image = scene.render()
        if image is None or image.GetNumberOfPoints() != size * size:
            failures.append(f"{name}: no float image")
            continue
        if scene.events.errors or scene.window_events.errors:
            failures.append(f"{name}: {scene.events.errors + scene.window_events.errors} VTK errors")
        if not finite_image(image):
            failures.append(f"{name}: non-finite or out of [0, 1]")
            continue
        rgba = image.GetPointData().GetScalars()
        if any(max(rgba.GetTuple4(p)[:3]) > rgba.GetTuple4(p)[3] + 1e-3 for p in range(rgba.GetNumberOfTuples())):
            failures.append(f"{name}: colour above alpha (not premultiplied)")
        # Accuracy failures only may fall to the contracts below: errors, non-finite and
        # unpremultiplied images never do.
        error, missed = accuracy_against(image, expected)
        if not (error <= RMSE_BOUND and missed == 0):
            if limits is None:
                limits = [expected] + [reference(mesh, prop, moved, size)
                                       for moved in nudged_cameras(camera, NUDGE * mesh.GetLength())]
            nearest = nearest_limits(image, limits)
            error, missed = accuracy_against(image, nearest)
            band = None if error <= RMSE_BOUND and missed == 0 else rasteriser_band(image, nearest, mesh, camera, size)
            if band is not None:
                banded_error, banded_missed = accuracy_against(image, band)
                if banded_error <= RMSE_BOUND and banded_missed == 0:
                    failures.append(f"CONTRACT {name}: pixels within 1/16 pixel of an edge, covered as the "
                                    "rasteriser decides (test_routes.SubPixelCoverage)")
                    continue
        if not error <= RMSE_BOUND:
            failures.append(f"{name}: RMSE {error:.3g} > {RMSE_BOUND}")
        if missed:
            failures.append(f"{name}: {missed} covered pixels not drawn")
    return failures


def run_all(seed, count, where=(), first=0):
    """Runs `count` cases from case number `first` on, each in its own process; with `where`
    ("axis=value" ...), the first `count` case numbers from `first` whose choices match."""
    failed = stated_count = 0
    wanted = dict(condition.split("=", 1) for condition in where)
    for axis, value in wanted.items():
        choices = AXES.get(axis)
        if choices is None or value not in map(str, choices):
            sys.exit(f"--where {axis}={value}: the axes are {', '.join(AXES)}; {axis}'s values: {choices}")
    numbers = (n for n in itertools.count(first)
               if all(str(choose(seed, n)[axis]) == value for axis, value in wanted.items()))
    for _, number in zip(range(count), numbers):
        case = choose(seed, number)
        start = time.time()
        try:
            result = subprocess.run([sys.executable, os.path.abspath(__file__), "--case", str(number), "--seed", str(seed)],
                                    capture_output=True, text=True, timeout=TIMEOUT_S)
            lines = [line for line in result.stdout.splitlines() if line.startswith("FAIL")]
            stated = [line for line in result.stdout.splitlines() if line.startswith("CONTRACT")]
            if result.returncode != 0 and not lines:
                lines = [f"FAIL crashed (exit {result.returncode}): {result.stderr.strip().splitlines()[-1:]}"]
        except subprocess.TimeoutExpired:
            lines, stated = [f"FAIL hung (over {TIMEOUT_S} s)"], []
        status = "FAILED" if lines else ("stated" if stated else "ok")
        failed += bool(lines)
        stated_count += bool(stated) and not lines
        print(f"case {number:4d} {status:6s} {time.time() - start:5.1f} s  " +
              " ".join(f"{k}={v}" for k, v in case.items()), flush=True)
        for line in lines + stated:
            print("    " + line, flush=True)
    print(f"{count - failed} of {count} cases passed (seed {seed}), {stated_count} of them within the stated "
          "contract (a few pixels within 1/16 pixel of an edge)")
    return failed == 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--cases", type=int, default=12, help="how many cases, each in its own process")
    parser.add_argument("--case", type=int, default=None, help="run this one case here")
    parser.add_argument("--first", type=int, default=0,
                        help="the first case number of the run (to split a long run over processes)")
    parser.add_argument("--where", action="append", default=[], metavar="AXIS=VALUE",
                        help="only cases with this choice (e.g. mesh=slivers); repeatable")
    args = parser.parse_args()
    if args.case is not None:
        failures = run_case(args.seed, args.case)
        for failure in failures:
            print(failure if failure.startswith("CONTRACT") else "FAIL " + failure)
        sys.exit(1 if any(not failure.startswith("CONTRACT") for failure in failures) else 0)
    sys.exit(0 if run_all(args.seed, args.cases, args.where, args.first) else 1)


if __name__ == "__main__":
    main()
