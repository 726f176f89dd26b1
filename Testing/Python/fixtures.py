"""Fixtures shared by the Python tests: generated meshes, transfer functions, cameras, the scene that
puts one mapper in an off-screen window, the reference and the error measures, baseline comparison
and checks every tetrahedral mapper shares.

Test modules import from here, from uvrender (the rendering helpers the main job also uses), from
shared_data (the real meshes) and from corner_point (generated reservoir grids), never from one another: each test module is one ctest test, and one
that borrows another's helpers or subclasses its test classes breaks when that module changes."""
import math
import os
import tempfile
import unittest

import baselines
import shared_data
import uvrender

from unstructuredvolume import (vtkAnalyticMeshSource, vtkHexahedraToTetrahedra, vtkHexahedralRayCastMapper,
                                vtkLocatorRayMarcher,
                                vtkPreIntegratedTetrahedraMapper, vtkUnstructuredVolumeReferenceRenderer,
                                vtkVolumeImageErrorMetrics)
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkFloatArray, vtkIdList, vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_POLYHEDRON, VTK_PYRAMID, VTK_QUADRATIC_TETRA, VTK_TETRA,
                                           VTK_WEDGE, vtkGenericCell, vtkImageData,
                                           vtkPiecewiseFunction, vtkUnstructuredGrid)
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkColorTransferFunction, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)

IMAGE_THRESHOLD = 10.0  # vtkImageDifference's thresholded error against a baseline (VTK's tests use 10)
OUTPUT = os.environ.get("UV_TEST_OUTPUT", tempfile.gettempdir())
ML, STEINER = vtkAnalyticMeshSource.MARSCHNER_LOBB, vtkAnalyticMeshSource.STEINER


class Events:
    """Counts a VTK object's error and warning events instead of printing them."""

    def __init__(self, obj):
        self.errors = self.warnings = 0
        obj.AddObserver(vtkCommand.ErrorEvent, self.on_error)
        obj.AddObserver(vtkCommand.WarningEvent, self.on_warning)

    def on_error(self, caller, event):
        self.errors += 1

    def on_warning(self, caller, event):
        self.warnings += 1


# ---------------------------------------------------------------------------------------------
# Meshes
def analytic(resolution, field=ML, distortion=0, cells=vtkAnalyticMeshSource.SIX_TETRAHEDRA):
    """vtkAnalyticMeshSource's [-1, 1]^3 at resolution^3 cells (six tetrahedra each by default)."""
    source = vtkAnalyticMeshSource()
    source.SetResolution(resolution, resolution, resolution)
    source.SetField(field)
    source.SetDistortion(distortion)
    source.SetCellKind(cells)
    source.Update()
    return source.GetOutput()


def analytic_hexahedra(resolution, field=ML, distortion=0):
    return analytic(resolution, field, distortion, vtkAnalyticMeshSource.HEXAHEDRA)


def mean_cell_values(mesh, name="cells"):
    """The mesh's point scalar averaged over each cell's points, as the only data."""
    points = mesh.GetPointData().GetScalars()
    values = vtkDoubleArray()
    values.SetName(name)
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        values.InsertNextValue(sum(points.GetValue(ids.GetId(k)) for k in range(ids.GetNumberOfIds()))
                               / ids.GetNumberOfIds())
    mesh.GetPointData().Initialize()
    mesh.GetCellData().SetScalars(values)
    return mesh


def inside_out(mesh):
    """A copy of a tetrahedral mesh with the second and third point of every cell swapped: the same
    tetrahedra, each in the opposite orientation."""
    result = vtkUnstructuredGrid()
    result.SetPoints(mesh.GetPoints())
    result.GetPointData().ShallowCopy(mesh.GetPointData())
    result.Allocate(mesh.GetNumberOfCells())
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        a, b = ids.GetId(1), ids.GetId(2)
        ids.SetId(1, b)
        ids.SetId(2, a)
        result.InsertNextCell(VTK_TETRA, ids)
    return result


def folded_slab(columns, depth, layers=1):
    """A slab of columns x columns x layers unit hexahedra whose point nearest the middle of the
    first layer's top is pushed down to z = depth, below the bottom: the first layer's cells around it
    fold over themselves (their Jacobians take both signs) and their top faces, curved, poke out
    through the bottom. With a second layer, its cells above the point reach down through the folded
    ones and out through the bottom with them: different cells overlap."""
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    values = vtkDoubleArray()
    values.SetName("f")
    middle = (columns + 1) // 2
    for k in range(layers + 1):
        for j in range(columns + 1):
            for i in range(columns + 1):
                points.InsertNextPoint(i, j, depth if (i, j, k) == (middle, middle, 1) else k)
                values.InsertNextValue(0.2 + 0.15 * ((i + 2 * j + 3 * k) % 5))
    grid.SetPoints(points)

    def point(i, j, k):
        return (k * (columns + 1) + j) * (columns + 1) + i

    for layer in range(layers):
        for j in range(columns):
            for i in range(columns):
                grid.InsertNextCell(VTK_HEXAHEDRON, 8, [point(i + a, j + b, k) for k in (layer, layer + 1)
                                                        for a, b in ((0, 0), (1, 0), (1, 1), (0, 1))])
    grid.GetPointData().SetScalars(values)
    return grid


def hex_dominant(resolution, distortion=vtkAnalyticMeshSource.JITTER):
    """analytic_hexahedra(resolution) made hex-dominant and conforming, with every linear 3D cell
    type: the columns of the lowest x third split into two wedges each (the same diagonal all the
    way up, so the triangles match), and two neighbouring hexahedra near the centre split into six
    pyramids about their centres (the mean of the corners, valued the mean of the corner values),
    the two pyramids on the face they share each split into two tetrahedra on the same diagonal."""
    hexahedra = analytic_hexahedra(resolution, distortion=distortion)
    points = vtkPoints()
    points.DeepCopy(hexahedra.GetPoints())
    values = vtkDoubleArray()
    values.DeepCopy(hexahedra.GetPointData().GetScalars())
    out = vtkUnstructuredGrid()
    out.SetPoints(points)
    spacing = 2.0 / resolution

    def position(i):
        return points.GetPoint(i)

    def index_of(ids):
        centre = [sum(position(i)[a] for i in ids) / len(ids) for a in range(3)]
        return [min(resolution - 1, max(0, int((c + 1.0) / spacing))) for c in centre]

    def add(kind, ids):
        out.InsertNextCell(kind, len(ids), list(ids))

    def inward(quad, apex):
        """The quad turned so its right-hand normal points at `apex` (VTK's pyramid base)."""
        p = [position(i) for i in quad]
        normal = cross(sub(p[2], p[0]), sub(p[3], p[1]))
        centre = [sum(q[a] for q in p) / 4 for a in range(3)]
        return quad if dot(normal, sub(apex, centre)) > 0 else quad[::-1]

    middle = resolution // 2
    split_pair = ([resolution - 2, middle, middle], [resolution - 1, middle, middle])
    centres = {}
    for c in range(hexahedra.GetNumberOfCells()):
        ids = [hexahedra.GetCell(c).GetPointId(k) for k in range(8)]
        index = index_of(ids)
        if index[0] < resolution // 3:
            # VTK's wedge base faces away from its top: (0, 2, 1) of the hexahedron's bottom.
            add(VTK_WEDGE, [ids[0], ids[2], ids[1], ids[4], ids[6], ids[5]])
            add(VTK_WEDGE, [ids[0], ids[3], ids[2], ids[4], ids[7], ids[6]])
        elif index in split_pair:
            centre = [sum(position(i)[a] for i in ids) / 8 for a in range(3)]
            apex = points.InsertNextPoint(*centre)
            values.InsertNextValue(sum(values.GetValue(i) for i in ids) / 8)
            centres[tuple(index)] = (ids, apex, centre)
        else:
            add(VTK_HEXAHEDRON, ids)
    shared = set.intersection(*(set(ids) for ids, _, _ in centres.values()))
    for ids, apex, centre in centres.values():
        for face in ((0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2), (0, 3, 2, 1), (4, 5, 6, 7)):
            quad = inward([ids[k] for k in face], centre)
            if set(quad) != shared:
                add(VTK_PYRAMID, quad + [apex])
                continue
            start = quad.index(min(quad))  # the diagonal through the smallest id, from both sides
            quad = quad[start:] + quad[:start]
            for triangle in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
                add(VTK_TETRA, list(triangle) + [apex])  # the base's normal points at the apex
    out.GetPointData().SetScalars(values)
    return out


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def as_polyhedra(mesh):
    """Every cell of an unstructured grid rewritten as a VTK_POLYHEDRON of its own faces."""
    out = vtkUnstructuredGrid()
    out.SetPoints(mesh.GetPoints())
    cell = vtkGenericCell()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCell(c, cell)
        stream = vtkIdList()
        stream.InsertNextId(cell.GetNumberOfFaces())
        for f in range(cell.GetNumberOfFaces()):
            ids = cell.GetFace(f).GetPointIds()
            stream.InsertNextId(ids.GetNumberOfIds())
            for i in range(ids.GetNumberOfIds()):
                stream.InsertNextId(ids.GetId(i))
        out.InsertNextCell(VTK_POLYHEDRON, stream)
    out.GetPointData().ShallowCopy(mesh.GetPointData())
    return out


def load_shared(test, loader):
    """A mesh of ../shared/data from a shared_data loader, or the test skipped when it is absent."""
    try:
        return loader()
    except FileNotFoundError as missing:
        test.skipTest(f"{missing} is absent")


# ---------------------------------------------------------------------------------------------
# Transfer functions
def property_from_nodes(opacity_nodes, color_nodes, unit):
    """A vtkVolumeProperty of (scalar, opacity) and (scalar, (r, g, b)) nodes and opacity unit distance."""
    opacity = vtkPiecewiseFunction()
    for s, a in opacity_nodes:
        opacity.AddPoint(s, a)
    colors = vtkColorTransferFunction()
    for s, rgb in color_nodes:
        colors.AddRGBPoint(s, *rgb)
    prop = vtkVolumeProperty()
    prop.SetColor(colors)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit)
    return prop


def spike_property(low, high, unit):
    """One thin opaque spike at 60% of the range, over a faint ramp."""
    centre, width = low + 0.6 * (high - low), 0.02 * (high - low)
    return property_from_nodes(
        ((low, 0.0), (centre - width, 0.02), (centre, 0.95), (centre + width, 0.02), (high, 0.05)),
        ((low, (0.1, 0.3, 0.9)), (centre, (1.0, 0.7, 0.1)), (high, (0.9, 0.1, 0.1))), unit)


def sampled_color_map(low, high, count=256):
    """(opacity nodes, colour nodes): a colour map sampled at `count` nodes, as ParaView's presets are
    (a smooth curve through colour space), over an opacity ramp from a fifth of the range up."""
    colors = []
    for k in range(count):
        u = k / (count - 1)
        colors.append((low + u * (high - low), (0.27 + 0.7 * u * u, 0.5 + 0.4 * math.sin(3.0 * u),
                                                0.33 + 0.3 * math.cos(5.0 * u))))
    return [(low, 0.0), (low + 0.2 * (high - low), 0.0), (high, 0.7)], colors


def sampled_color_map_property(low, high, unit, count=256):
    """sampled_color_map as a vtkVolumeProperty."""
    return property_from_nodes(*sampled_color_map(low, high, count), unit)


def transparent_property(color=(0.9, 0.6, 0.2)):
    """A volume that shows nothing (isosurfaces only), unlit but for what a test sets."""
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(-1e9, 0.0)
    opacity.AddPoint(1e9, 0.0)
    colors = vtkColorTransferFunction()
    colors.AddRGBPoint(-1e9, *color)
    colors.AddRGBPoint(1e9, *color)
    prop = vtkVolumeProperty()
    prop.SetColor(colors)
    prop.SetScalarOpacity(opacity)
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    return prop


def thin_shell_property(low, high, value, color, length):
    """An unlit, very opaque shell of the transfer function 1e-4 of the range wide around `value`: what
    an opaque isosurface is the limit of, for the reference to render."""
    shell = transparent_property(color)
    opacity = shell.GetScalarOpacity()
    opacity.RemoveAllPoints()
    width = 1e-4 * (high - low)
    for s, a in ((low, 0.0), (value - width, 0.0), (value - 0.5 * width, 0.999), (value + 0.5 * width, 0.999),
                 (value + width, 0.0), (high, 0.0)):
        opacity.AddPoint(s, a)
    shell.SetScalarOpacityUnitDistance(1e-7 * length)
    return shell


PLANE_GRADIENT = (0.3, -0.5, 0.8)


def plane_scene_setup(mesh, camera, color):
    """Sets the linear field PLANE_GRADIENT . x as the mesh's scalar; returns a transparent lit property
    and the analytic Phong colour of its isosurface (a plane, one normal) under the renderer's
    headlight and `camera`'s parallel view."""
    values = vtkDoubleArray()
    values.SetName("plane")
    for i in range(mesh.GetNumberOfPoints()):
        values.InsertNextValue(sum(g * x for g, x in zip(PLANE_GRADIENT, mesh.GetPoint(i))))
    mesh.GetPointData().SetScalars(values)
    prop = transparent_property()
    prop.SetAmbient(0.15)
    prop.SetDiffuse(0.7)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(8)
    # Headlight and parallel view: the light and the eye are both along the view direction.
    view = camera.GetDirectionOfProjection()
    norm = math.sqrt(sum(g * g for g in PLANE_GRADIENT))
    lambert = abs(sum(g * v for g, v in zip(PLANE_GRADIENT, view))) / norm
    highlight = max(2 * lambert * lambert - 1, 0.0) ** 8
    return prop, [c * (0.15 + 0.7 * lambert) + 0.3 * highlight for c in color]


# ---------------------------------------------------------------------------------------------
# Cameras and scenes
def camera_for(mesh, azimuth=30.0, elevation=25.0, parallel=False, distance=2.6):
    """A camera `distance` diagonals from the mesh's centre, turned by azimuth and elevation."""
    bounds = mesh.GetBounds()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    camera = vtkCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0], centre[1] - distance * mesh.GetLength(), centre[2])
    camera.SetViewUp(0, 0, 1)
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    camera.SetParallelProjection(parallel)
    camera.SetParallelScale(0.6 * mesh.GetLength())
    camera.SetViewAngle(30)
    camera.SetClippingRange(0.01, 10 * (distance + 1) * mesh.GetLength())
    return camera


def inside_camera():
    """A wide perspective camera inside [-1, 1]^3, looking across it."""
    camera = vtkCamera()
    camera.SetPosition(0.05, -0.3, 0.1)
    camera.SetFocalPoint(0.2, 1.0, 0.0)
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(60)
    camera.SetClippingRange(0.01, 10)
    return camera


OPEN_SCENES = []
SHARED_WINDOW = []


def shared_window():
    """One off-screen window for every scene of a test process: creating one per scene aborted inside
    vtkXOpenGLRenderWindow::CreateAWindow now and then under Xvfb."""
    if not SHARED_WINDOW:
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetAlphaBitPlanes(1)
        window.SetMultiSamples(0)
        SHARED_WINDOW.append(window)
    return SHARED_WINDOW[0]


def statistic(mapper, name):
    """What `mapper` did, as its frame statistic `name` says (vtkUnstructuredVolumeFrameStatistics).
    A name the mapper does not report raises: its NaN would pass assertTrue."""
    statistics = mapper.GetFrameStatistics()
    if not statistics.HasValue(name):
        raise KeyError(f"{mapper.GetClassName()} reports no frame statistic {name}")
    return statistics.GetValue(name)


class SceneTestCase(unittest.TestCase):
    """Frees the GPU resources of the scenes a test made and takes their renderers out."""

    def tearDown(self):
        while OPEN_SCENES:
            scene = OPEN_SCENES.pop()
            scene.mapper.ReleaseGraphicsResources(scene.window)
            scene.window.RemoveRenderer(scene.renderer)

    def assert_near_reference(self, scene, mesh, prop, camera, size, bound):
        """Renders `scene` and fails unless it raised no VTK error and its RMSE over covered pixels
        against the reference is under `bound`; prints the RMSE and the largest error; returns the
        RMSE and the float image."""
        image = scene.render()
        error, worst = rmse(image, reference(mesh, prop, camera, size))
        print(f"\n  RMSE {error:.3g}, max {worst:.3g} (bound {bound})", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(error, bound, f"RMSE {error:.3g} against the reference (bound {bound})")
        return error, image


class Scene:
    """One mapper in the shared off-screen window with a transparent black background: `mapper` as
    given, else a new `mapper_class`, else a vtkPreIntegratedTetrahedraMapper. Each keyword setting
    calls the mapper's Set<name>(value)."""

    def __init__(self, mesh, prop, camera, size=128, props=(), mapper_class=None, mapper=None, **settings):
        OPEN_SCENES.append(self)
        self.size = size
        self.renderer = vtkRenderer()
        self.renderer.SetBackground(0, 0, 0)
        self.renderer.SetBackgroundAlpha(0.0)
        self.window = shared_window()
        for other in OPEN_SCENES[:-1]:
            self.window.RemoveRenderer(other.renderer)  # one scene shows at a time
        self.window.SetSize(size, size)
        self.window.AddRenderer(self.renderer)
        self.mapper = mapper or (mapper_class or vtkPreIntegratedTetrahedraMapper)()
        self.mapper.SetInputData(mesh)
        self.mapper.SetKeepFloatImage(True)
        for name, value in settings.items():
            getattr(self.mapper, "Set" + name)(value)
        self.events = Events(self.mapper)
        self.volume = vtkVolume()
        self.volume.SetMapper(self.mapper)
        self.volume.SetProperty(prop)
        self.renderer.AddVolume(self.volume)
        for p in props:
            self.renderer.AddActor(p)
        self.renderer.SetActiveCamera(camera)
        self.window_events = Events(self.window)

    def render(self):
        """Renders this scene alone in the window; returns the mapper's float image."""
        renderers = self.window.GetRenderers()
        if not renderers.IsItemPresent(self.renderer):
            renderers.RemoveAllItems()
            self.window.AddRenderer(self.renderer)
        self.window.SetSize(self.size, self.size)
        self.window.Render()
        return self.mapper.GetFloatImage()


def HexScene(mesh, prop, camera, size=128, mapper=None, **settings):  # noqa: N802  (reads as a class)
    """A Scene whose mapper is a vtkHexahedralRayCastMapper unless `mapper` is given."""
    return Scene(mesh, prop, camera, size, mapper=mapper or vtkHexahedralRayCastMapper(), **settings)


# ---------------------------------------------------------------------------------------------
# The reference and error measures
def reference(mesh, prop, camera, size, height=None):
    """vtkUnstructuredVolumeReferenceRenderer's float image of the mesh at size x size (size x height)."""
    renderer = vtkUnstructuredVolumeReferenceRenderer()
    renderer.SetInputData(mesh)
    renderer.SetVolumeProperty(prop)
    renderer.SetCamera(camera)
    renderer.SetImageSize(size, size if height is None else height)
    assert renderer.Render()
    return renderer.GetOutput()


def march(mesh, prop, camera, size, pixels, steps, array=None, cells=False, component=0):
    """vtkLocatorRayMarcher's premultiplied RGBA at `pixels` of a size x size image: the point (or,
    with `cells`, the cell) array `array` (else the active scalars), its `component` (-1: magnitude)."""
    marcher = vtkLocatorRayMarcher()
    marcher.SetInputData(mesh)
    marcher.SetScalarArrayName(array)
    marcher.SetCellScalars(cells)
    marcher.SetScalarComponent(component)
    marcher.SetVolumeProperty(prop)
    marcher.SetCamera(camera)
    marcher.SetImageSize(size, size)
    marcher.SetNumberOfSteps(steps)
    ids = vtkIdTypeArray()
    for p in pixels:
        ids.InsertNextValue(p)
    rgba = vtkFloatArray()
    assert marcher.MarchPixels(ids, rgba)
    return [rgba.GetTuple4(i) for i in range(len(pixels))]


def grab_rgba(window):
    """The window's RGBA bytes as last rendered (not rendered again): an 8-bit image, which
    vtkVolumeImageErrorMetrics reads as premultiplied RGBA in [0, 1]."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    image = vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image


def largest_difference(a, b):
    """The largest difference of any channel between two lists of RGBA tuples."""
    return max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))


def rmse(candidate, expected):
    """(RMSE, maximum error) over premultiplied RGBA."""
    metrics = vtkVolumeImageErrorMetrics()
    metrics.SetChannels(4)
    assert metrics.Compare(candidate, expected)
    return metrics.GetRMSE(), metrics.GetMaximumError()


def finite_image(image):
    """Whether every RGBA value is finite and within [0, 1] (up to rounding)."""
    scalars = image.GetPointData().GetScalars()
    for c in range(4):
        low, high = scalars.GetRange(c)
        if not (math.isfinite(low) and math.isfinite(high)) or low < -1e-6 or high > 1.0 + 1e-4:
            return False
    return True


def covered_colour_error(image, expected):
    """The pixels of a float image opaque to 0.999, and their largest colour difference from `expected`."""
    rgba = image.GetPointData().GetScalars()
    covered, worst = 0, 0.0
    for i in range(rgba.GetNumberOfTuples()):
        pixel = rgba.GetTuple4(i)
        if pixel[3] > 0.999:
            covered += 1
            worst = max(worst, max(abs(pixel[k] - expected[k]) for k in range(3)))
    return covered, worst


def copy_image(image):
    """A deep copy: a mapper's float image is overwritten by its next frame."""
    copy = vtkImageData()
    copy.DeepCopy(image)
    return copy


def opaque_sphere(radius, center=(0.0, 0.0, 0.0), resolution=8, color=None):
    """An opaque sphere actor (vtkSphereSource; resolution 8 is its default), for scenes whose geometry
    ends the volume's rays."""
    sphere = vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetCenter(*center)
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(sphere_mapper)
    if color is not None:
        actor.GetProperty().SetColor(*color)
    return actor


def check_geometry_shown_later(test, **settings):
    """A scene with nothing opaque in it does not read the depth buffer (the mapper's `settings`);
    the same mapper must read it again the frame a prop is shown, and a hidden one changes nothing."""
    mesh = analytic(6)
    prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
    camera = camera_for(mesh)

    hidden = opaque_sphere(0.4)
    hidden.VisibilityOff()
    alone = copy_image(Scene(mesh, prop, camera, 96, **settings).render())
    # Rendered before the scene under test, so that nothing runs between its frames below.
    expected = copy_image(Scene(mesh, prop, camera, 96, (opaque_sphere(0.4),), **settings).render())
    scene = Scene(mesh, prop, camera, 96, (hidden,), **settings)
    test.assertLess(rmse(scene.render(), alone)[1], 1e-6)
    hidden.VisibilityOn()
    shown = copy_image(scene.render())
    test.assertLess(rmse(shown, expected)[1], 1e-6)
    test.assertGreater(rmse(shown, alone)[0], 0.01)  # the sphere hides what lies behind it
    hidden.VisibilityOff()
    test.assertLess(rmse(scene.render(), alone)[1], 1e-6)
    test.assertEqual(scene.events.errors, 0)


def plate_and_block():
    """A non-convex mesh: a long plate and a block floating above its near end, each one hexahedron
    split into 6 tetrahedra, a linear scalar "s"; and a camera from above the plate's far end, whose
    rays through the block go on to the plate. The plate's long tetrahedra have centroids nearer the
    eye than the block's, and no face joins the two."""
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    values = vtkFloatArray()
    values.SetName("s")
    for low, high in (((-2, 0, 0), (10, 1, 0.3)), ((1, 0, 1), (2, 1, 1.5))):
        ids = []
        for k in range(2):
            for i, j in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [low[a] + (i, j, k)[a] * (high[a] - low[a]) for a in range(3)]
                ids.append(points.InsertNextPoint(p))
                values.InsertNextValue(0.1 * p[0] + p[2])
        grid.InsertNextCell(VTK_HEXAHEDRON, 8, ids)
    grid.SetPoints(points)
    grid.GetPointData().SetScalars(values)
    split = vtkHexahedraToTetrahedra()
    split.SetInputData(grid)
    split.Update()
    camera = vtkCamera()
    camera.SetPosition(6, 0.5, 4)
    camera.SetFocalPoint(1.5, 0.5, 0.7)
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(40)
    camera.SetClippingRange(0.5, 20)
    return split.GetOutput(), camera


def check_order_across_a_gap(test, **settings):
    """The face order (the mapper's default, with `settings`) is exact across the gap of
    plate_and_block(): the integration's own error is left; the centroid order is off."""
    mesh, camera = plate_and_block()
    prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
    prop.SetScalarOpacityUnitDistance(1.0)
    expected = reference(mesh, prop, camera, 96)
    scene = Scene(mesh, prop, camera, 96, SegmentIntegration=2, **settings)
    face = rmse(scene.render(), expected)[0]
    centroid = rmse(Scene(mesh, prop, camera, 96, SegmentIntegration=2, VisibilityOrder=0, **settings).render(),
                    expected)[0]
    print(f"\n  face order RMSE {face:.3g}, centroid order {centroid:.3g}", end="")
    test.assertGreater(statistic(scene.mapper, "GapConstraints"), 0)
    test.assertEqual(statistic(scene.mapper, "CyclesBroken"), 0)
    test.assertLess(face, 1e-6)
    test.assertGreater(centroid, 1e-4)


# ---------------------------------------------------------------------------------------------
# Shared test bases
def assert_matches_baseline(test, candidate, name):
    """Fails `test` unless the PNG `candidate` is within IMAGE_THRESHOLD of the baseline `name` or
    of one of its alternates (baselines.py); returns the difference to the nearest."""
    try:
        error, baseline = baselines.nearest_baseline(candidate, os.path.join(baselines.BASELINES, name))
    except FileNotFoundError as missing:
        test.fail(str(missing))
    test.assertLessEqual(error, IMAGE_THRESHOLD, f"{candidate} differs from {baseline}, the nearest of its "
                         f"alternates: thresholded error {error:.3f}, at most {IMAGE_THRESHOLD}")
    return error


class BaselineTestCase(SceneTestCase):
    """Image baselines: a window's PNG against Testing/Data/Baseline (no tests of its own)."""

    def compare(self, window, name):
        candidate = os.path.join(OUTPUT, name)
        uvrender.write_png(window, candidate)
        return assert_matches_baseline(self, candidate, name)

    def scene(self, mesh, prop, camera, size=256, props=(), **settings):
        """A rendered Scene over the baselines' dark opaque background, drawn into the window."""
        scene = Scene(mesh, prop, camera, size, props, **settings)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.renderer.SetBackgroundAlpha(1.0)
        scene.mapper.SetKeepFloatImage(False)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        return scene

    def legacy(self, relative, array):
        """A legacy unstructured grid of ../shared/data (the test skipped when absent), `array` active."""
        path = os.path.join(shared_data.SHARED, relative)
        if not os.path.exists(path):
            self.skipTest(f"{path} is absent")
        reader = vtkUnstructuredGridReader()
        reader.ReadAllScalarsOn()
        reader.SetFileName(path)
        reader.Update()
        mesh = reader.GetOutput()
        if array:
            mesh.GetPointData().SetActiveScalars(array)
        return mesh


class TetrahedralInputChecks:
    """Bad input every tetrahedral mapper reports the same way; a mixin for each mapper's InputTests,
    whose scene(mesh, prop=None) builds a small scene with that mapper. Not a TestCase, so it runs
    only in the classes that mix it in."""

    def test_missing_scalars_are_an_error_and_cell_scalars_are_drawn(self):
        mesh = analytic(3)
        no_scalars = vtkUnstructuredGrid()
        no_scalars.CopyStructure(mesh)
        scene = self.scene(no_scalars)
        scene.render()
        self.assertEqual(scene.events.errors, 1)
        cells = vtkUnstructuredGrid()
        cells.CopyStructure(mesh)
        values = vtkDoubleArray()
        values.SetNumberOfTuples(mesh.GetNumberOfCells())
        for c in range(mesh.GetNumberOfCells()):
            values.SetValue(c, (c % 7) / 6.0)
        cells.GetCellData().SetScalars(values)
        scene = self.scene(cells)
        scene.mapper.SetScalarModeToUseCellData()
        alpha = scene.render().GetPointData().GetScalars().GetRange(3)
        self.assertEqual(scene.events.errors, 0)
        self.assertGreater(alpha[1], 0.01)

    def test_empty_grid_draws_nothing_quietly(self):
        scene = self.scene(vtkUnstructuredGrid())
        scene.render()
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)

    def test_an_opacity_function_without_nodes_draws_nothing_quietly(self):
        # VTK evaluates a node-less function to zero everywhere: transparent, as the reference draws
        # it, not an error (the mappers reported "no scalar opacity function").
        scene = self.scene(analytic(3), property_from_nodes((), (), 1.0))
        alpha = scene.render().GetPointData().GetScalars().GetRange(3)
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        self.assertEqual(alpha, (0.0, 0.0))

    def test_quadratic_cells_are_subdivided_and_drawn(self):
        grid = vtkUnstructuredGrid()
        points = vtkPoints()
        for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (.5, 0, 0), (.5, .5, 0), (0, .5, 0), (0, 0, .5),
                  (.5, 0, .5), (0, .5, .5)):
            points.InsertNextPoint(*p)
        grid.SetPoints(points)
        grid.InsertNextCell(VTK_QUADRATIC_TETRA, 10, list(range(10)))
        values = vtkDoubleArray()
        values.SetNumberOfTuples(10)
        values.Fill(0.5)
        grid.GetPointData().SetScalars(values)
        scene = self.scene(grid)
        alpha = scene.render().GetPointData().GetScalars().GetRange(3)
        # vtkHexahedraToTetrahedra subdivides it (straight, constant: its corner tet), with the split warning.
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.events.warnings, 1)
        self.assertGreater(alpha[1], 0.01)
