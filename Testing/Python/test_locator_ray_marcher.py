"""vtkLocatorRayMarcher, the independent brute-force check of the reference renderer, against closed
forms: constant media in (curvilinear) cubes, a linear scalar with linear extinction, overlapping
cells, step halving and bad input. No render window needed."""
import math
import os
import random
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fixtures  # noqa: E402

from unstructuredvolume import vtkHexahedraToTetrahedra, vtkLocatorRayMarcher  # noqa: E402
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkFloatArray, vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_TRIANGLE, vtkPiecewiseFunction,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkRenderingCore import vtkCamera, vtkColorTransferFunction, vtkVolumeProperty

SIZE = 16


class Cube:
    """n^3 hexahedra filling [origin, origin + side]^3, interior nodes jittered (curvilinear cells
    with non-planar faces; the outer surface stays the cube), face nodes jittered within the face."""

    def __init__(self, n=4, origin=(0.0, 0.0, 0.0), side=1.0, jitter=0.3, seed=1):
        rng = random.Random(seed)
        h = side / n
        self.points = []
        for k in range(n + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    p = [origin[0] + i * h, origin[1] + j * h, origin[2] + k * h]
                    for axis, index in enumerate((i, j, k)):
                        if 0 < index < n:  # not on this axis' boundary planes: may move along it
                            p[axis] += rng.uniform(-jitter, jitter) * h
                    self.points.append(p)
        node = lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)  # noqa: E731
        self.cells = []
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    self.cells.append([node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                                       node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                                       node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)])


def grid(cubes, field, name="s", extra_triangle=False):
    """One vtkUnstructuredGrid of several cubes (their cells as given: repeats overlap); point array
    `name` = field(point, cube index)."""
    points = vtkPoints()
    values = vtkDoubleArray()
    values.SetName(name)
    ug = vtkUnstructuredGrid()
    cell_lists = []
    for index, cube in enumerate(cubes):
        base = points.GetNumberOfPoints()
        for p in cube.points:
            points.InsertNextPoint(p)
            values.InsertNextValue(field(p, index))
        cell_lists.append([[base + c for c in cell] for cell in cube.cells])
    ug.SetPoints(points)
    ug.GetPointData().AddArray(values)
    ug.GetPointData().SetActiveScalars(name)
    for cells in cell_lists:
        for cell in cells:
            ug.InsertNextCell(VTK_HEXAHEDRON, 8, cell)
    if extra_triangle:
        ug.InsertNextCell(VTK_TRIANGLE, 3, cell_lists[0][0][:3])
    return ug


def linear_property(alpha0, alpha1, rgb0, rgb1, unit=1.0):
    """Opacity and colour with nodes at s = 0 and 1 only: tau and colour linear in s on [0, 1]."""
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, alpha0)
    opacity.AddPoint(1.0, alpha1)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, *rgb0)
    colour.AddRGBPoint(1.0, *rgb1)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(unit)
    return prop


def tau_of(alpha, unit=1.0):
    return -math.log(1.0 - alpha) / unit


def parallel_camera(position, focal, up, scale):
    camera = vtkCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal)
    camera.SetViewUp(*up)
    camera.ParallelProjectionOn()
    camera.SetParallelScale(scale)
    camera.SetClippingRange(1.0, 10.0)
    return camera


def perspective_camera(position, focal, up, angle=30.0):
    camera = vtkCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal)
    camera.SetViewUp(*up)
    camera.SetViewAngle(angle)
    camera.SetClippingRange(0.5, 10.0)
    return camera


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalized(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def perspective_ray(camera, px, py, size=SIZE):
    """The pixel's ray from the camera's parameters (not its matrices): unit direction and origin."""
    eye, focal = camera.GetPosition(), camera.GetFocalPoint()
    forward = normalized(sub(focal, eye))
    right = normalized(cross(forward, camera.GetViewUp()))
    up = cross(right, forward)
    half = math.tan(math.radians(camera.GetViewAngle()) / 2.0)
    x = (2.0 * (px + 0.5) / size - 1.0) * half
    y = (2.0 * (py + 0.5) / size - 1.0) * half
    return list(eye), normalized([forward[i] + x * right[i] + y * up[i] for i in range(3)])


def box_span(origin, direction, low, high):
    """Where the line origin + t direction (unit direction, t >= 0) enters the box, and its length
    inside (0 when it misses)."""
    t0, t1 = 0.0, math.inf
    for i in range(3):
        if direction[i] == 0.0:
            if not low[i] <= origin[i] <= high[i]:
                return 0.0, 0.0
            continue
        a, b = (low[i] - origin[i]) / direction[i], (high[i] - origin[i]) / direction[i]
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    return (t0, t1 - t0) if t1 > t0 else (0.0, 0.0)


def box_chord(origin, direction, low, high):
    """Length of the line origin + t direction (unit direction, t >= 0) inside the box."""
    return box_span(origin, direction, low, high)[1]


class Messages:
    """Collects a VTK object's error messages instead of printing them."""

    def __init__(self, obj):
        self.errors = []
        obj.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    @calldata_type(VTK_STRING)
    def on_error(self, caller, event, message):
        self.errors.append(message)


def march(mesh, prop, camera, steps, pixels=None, name="s", size=SIZE):
    """fixtures.march over `pixels` (default: every pixel) as a dict pixel -> RGBA."""
    pixels = list(range(size * size) if pixels is None else pixels)
    return dict(zip(pixels, fixtures.march(mesh, prop, camera, size, pixels, steps, name)))


def composite(pieces):
    """Front-to-back composite of homogeneous pieces (tau, emission rgb, length)."""
    transmittance, colour = 1.0, [0.0, 0.0, 0.0]
    for tau, emission, length in pieces:
        absorbed = 1.0 - math.exp(-tau * length)
        for c in range(3):
            colour[c] += transmittance * emission[c] / tau * absorbed
        transmittance *= 1.0 - absorbed
    return colour + [1.0 - transmittance]


class LocatorRayMarcherTests(unittest.TestCase):
    def assertPixel(self, got, expected, tolerance, where=""):
        for c in range(4):
            self.assertAlmostEqual(got[c], expected[c], delta=tolerance,
                                   msg="channel %d of %s: %r vs %r" % (c, where, got, expected))

    def test_constant_cube_parallel(self):
        """(a) Parallel view along -z: every covered pixel's chord is the side; alpha = 1 - exp(-tau)."""
        alpha, rgb = 0.6, (0.2, 0.5, 0.9)
        prop = linear_property(alpha, alpha, rgb, rgb)
        mesh = grid([Cube()], lambda p, i: 0.5)
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)
        result = march(mesh, prop, camera, steps=200)
        tau = tau_of(alpha)
        covered = 0
        for p, got in result.items():
            x, y = -0.3 + 0.1 * (p % SIZE + 0.5), -0.3 + 0.1 * (p // SIZE + 0.5)
            inside = 0 < x < 1 and 0 < y < 1
            a = 1.0 - math.exp(-tau * 1.0) if inside else 0.0
            covered += inside
            self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)
        self.assertEqual(covered, 100)

    def test_shared_faces_count_once(self):
        """(a) A point on a face between cells belongs to one of them only: at the default 4000
        steps samples fall within VTK's 1e-3 parametric tolerance of the faces, and in the
        unjittered grid the rays of pixels (5, 4) and (10, 9) lie in a face, that of (5, 5) along an
        edge of four cells. None may count twice."""
        alpha, rgb = 0.6, (0.2, 0.5, 0.9)
        prop = linear_property(alpha, alpha, rgb, rgb)
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)
        a = 1.0 - math.exp(-tau_of(alpha))
        pixels = [4 * SIZE + 5, 5 * SIZE + 5, 9 * SIZE + 10, 8 * SIZE + 7]
        for jitter in (0.0, 0.3):
            mesh = grid([Cube(jitter=jitter)], lambda p, i: 0.5)
            marcher_steps = vtkLocatorRayMarcher().GetNumberOfSteps()
            for p, got in march(mesh, prop, camera, marcher_steps, pixels).items():
                self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)

    def test_constant_cube_perspective(self):
        """(a) Oblique perspective view: chords from the camera's parameters and the slab method."""
        alpha, rgb = 0.5, (0.9, 0.4, 0.1)
        prop = linear_property(alpha, alpha, rgb, rgb, unit=0.7)
        mesh = grid([Cube(jitter=0.35, seed=7)], lambda p, i: 0.3)
        camera = perspective_camera((1.9, 1.3, 2.7), (0.5, 0.5, 0.5), (0, 1, 0), angle=35.0)
        result = march(mesh, prop, camera, steps=200)
        tau = tau_of(alpha, 0.7)
        covered = 0
        for p, got in result.items():
            origin, direction = perspective_ray(camera, p % SIZE, p // SIZE)
            chord = box_chord(origin, direction, (0, 0, 0), (1, 1, 1))
            covered += chord > 0
            a = 1.0 - math.exp(-tau * chord)
            self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)
        self.assertGreater(covered, 80)

    def test_tetrahedra_count_once(self):
        """(a) The jittered cube split into tetrahedra, oblique view: the same chords. vtkTetra's
        parametric distance ignores the fourth barycentric coordinate, so without its own check the
        marcher counted samples up to 1e-3 outside a face twice (measured 3.6e-2 on tetraMesh)."""
        alpha, rgb = 0.5, (0.9, 0.4, 0.1)
        prop = linear_property(alpha, alpha, rgb, rgb, unit=0.7)
        split = vtkHexahedraToTetrahedra()
        split.SetInputData(grid([Cube(jitter=0.35, seed=7)], lambda p, i: 0.3))
        split.Update()
        camera = perspective_camera((1.9, 1.3, 2.7), (0.5, 0.5, 0.5), (0, 1, 0), angle=35.0)
        tau = tau_of(alpha, 0.7)
        for p, got in march(split.GetOutput(), prop, camera, steps=4000).items():
            origin, direction = perspective_ray(camera, p % SIZE, p // SIZE)
            a = 1.0 - math.exp(-tau * box_chord(origin, direction, (0, 0, 0), (1, 1, 1)))
            self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)

    def test_boundary_crossings_exact_with_few_steps(self):
        """(a) Two cubes with a gap, seen obliquely with 6 steps: the mesh boundary is crossed inside
        steps (entering the upper cube, the gap, leaving the lower); bisection makes a constant
        medium exact anyway, alpha = 1 - exp(-tau (L1 + L2)), wherever each step holds at most one
        crossing, or two on either side of its middle (crossings at a step's end count as in it)."""
        alpha, rgb, steps = 0.45, (0.7, 0.2, 0.4), 6
        prop = linear_property(alpha, alpha, rgb, rgb)
        boxes = [((0, 0, 0), (1, 1, 1)), ((0, 0, 1.1), (0.63, 0.63, 1.73))]
        lower, upper = Cube(n=2, seed=8), Cube(n=2, origin=(0.0, 0.0, 1.1), side=0.63, seed=9)
        mesh = grid([lower, upper], lambda p, i: 0.5)
        camera = perspective_camera((0.6, 0.2, 3.5), (0.5, 0.5, 1.0), (0, 1, 0), angle=35.0)
        result = march(mesh, prop, camera, steps=steps)
        tau = tau_of(alpha)
        checked = through_both = two_in_a_step = 0
        for p, got in result.items():
            origin, direction = perspective_ray(camera, p % SIZE, p // SIZE)
            start, length = box_span(origin, direction, (0, 0, 0), (1, 1, 1.73))
            ends = [start + length * k / steps for k in range(steps + 1)]
            spans = [box_span(origin, direction, low, high) for low, high in boxes]
            crossings = [t for t0, l in spans if l > 0 for t in (t0, t0 + l)]
            resolvable = True
            for a, b in zip(ends, ends[1:]):
                inside = [t for t in crossings if a - 1e-9 <= t <= b + 1e-9]
                middle = 0.5 * (a + b)
                if len(inside) == 2 and min(inside) < middle < max(inside):
                    two_in_a_step += 1
                elif len(inside) > 1:
                    resolvable = False
            if not resolvable:
                continue
            checked += 1
            through_both += all(l > 0 for _, l in spans)
            a = 1.0 - math.exp(-tau * sum(l for _, l in spans))
            self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)
        self.assertGreater(checked, 250)
        self.assertGreater(through_both, 40)
        self.assertGreater(two_in_a_step, 30)

    def test_pixel_order(self):
        """Pixel p is (p % width, p // width) with y counting from the bottom: a cube in the lower left."""
        prop = linear_property(0.5, 0.5, (1, 1, 1), (1, 1, 1))
        mesh = grid([Cube(n=2)], lambda p, i: 0.5)
        camera = parallel_camera((1.0, 1.0, 5.0), (1.0, 1.0, 0.5), (0, 1, 0), 0.8)
        result = march(mesh, prop, camera, steps=50)
        for p, got in result.items():
            lower_left = p % SIZE < 8 and p // SIZE < 8
            self.assertEqual(got[3] > 0.1, lower_left, "pixel %d: %r" % (p, got))

    def test_linear_scalar_linear_extinction(self):
        """(b) s = z seen along -z, tau and colour linear in s: closed forms (erf for the colour)."""
        a0, a1 = 0.6, 0.2  # alpha at s = 0 (back) and s = 1 (front)
        rgb0, rgb1 = (0.1, 0.8, 0.3), (0.9, 0.2, 0.6)
        prop = linear_property(a0, a1, rgb0, rgb1)
        mesh = grid([Cube(jitter=0.3, seed=3)], lambda p, i: p[2])  # isoparametric: s = z exactly
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)
        pixels = [y * SIZE + x for y in (3, 7, 12) for x in (3, 8, 12)]
        result = march(mesh, prop, camera, steps=400, pixels=pixels)
        # Distance u from the front face: s = 1 - u, tau(u) = a + b u, depth(u) = a u + b u^2 / 2.
        tau0, tau1 = tau_of(a0), tau_of(a1)
        a, b = tau1, tau0 - tau1
        depth = a + b / 2.0
        gauss = math.exp(a * a / (2 * b)) * math.sqrt(math.pi / (2 * b)) * (
            math.erf(math.sqrt(b / 2) * (1 + a / b)) - math.erf(math.sqrt(b / 2) * (a / b)))
        expected = []
        for c in range(3):
            p, q = rgb1[c], rgb0[c] - rgb1[c]  # colour at u: p + q u
            # integral of (p + q u) tau(u) exp(-depth(u)) du, by parts.
            expected.append(p - (p + q) * math.exp(-depth) + q * gauss)
        expected.append(1.0 - math.exp(-depth))
        for p, got in result.items():
            self.assertPixel(got, expected, 2e-5, "pixel %d" % p)

    def test_step_halving_is_second_order(self):
        """(c) A smooth scene (linear scalar, two-node transfer function, oblique perspective view):
        the change from N to 2N steps falls about fourfold with each halving."""
        prop = linear_property(0.7, 0.1, (1.0, 0.2, 0.1), (0.1, 0.3, 1.0))
        mesh = grid([Cube(jitter=0.3, seed=5)], lambda p, i: 0.2 * p[0] + 0.3 * p[1] + 0.5 * p[2])
        camera = perspective_camera((1.9, 1.3, 2.7), (0.5, 0.5, 0.5), (0, 1, 0), angle=35.0)
        pixels = [y * SIZE + x for y in range(2, 14, 3) for x in range(2, 14, 3)]
        runs = [march(mesh, prop, camera, steps=n, pixels=pixels) for n in (25, 50, 100, 200)]
        differences = []
        for coarse, fine in zip(runs, runs[1:]):
            differences.append(max(abs(coarse[p][c] - fine[p][c]) for p in pixels for c in range(4)))
        print("\nstep halving, max |I(N) - I(2N)| for N = 25, 50, 100: %s" %
              ", ".join("%.3e" % d for d in differences))
        self.assertGreater(differences[0], 1e-6)  # the steps do matter
        for d, d_half in zip(differences, differences[1:]):
            self.assertGreater(d / d_half, 3.3)
            self.assertLess(d / d_half, 4.7)

    def test_duplicated_cells_double_extinction(self):
        """(d) The same cells twice: the opacity of doubled extinction, 1 - exp(-2 tau L)."""
        alpha, rgb = 0.4, (0.3, 0.6, 0.2)
        prop = linear_property(alpha, alpha, rgb, rgb)
        cube = Cube(seed=11)
        mesh = grid([cube, cube], lambda p, i: 0.5)
        camera = perspective_camera((1.9, 1.3, 2.7), (0.5, 0.5, 0.5), (0, 1, 0), angle=35.0)
        result = march(mesh, prop, camera, steps=200)
        tau = tau_of(alpha)
        for p, got in result.items():
            origin, direction = perspective_ray(camera, p % SIZE, p // SIZE)
            a = 1.0 - math.exp(-2.0 * tau * box_chord(origin, direction, (0, 0, 0), (1, 1, 1)))
            self.assertPixel(got, [rgb[0] * a, rgb[1] * a, rgb[2] * a, a], 2e-6, "pixel %d" % p)

    def test_partly_overlapping_cubes_superpose(self):
        """(d) Cubes [0,1]^3 (s = 0.25) and [0.5,1.5]x[0,1]^2 (s = 0.75) seen along -x: B alone, both
        (extinction and emission added), then A alone."""
        prop = linear_property(0.3, 0.6, (1.0, 0.0, 0.0), (0.0, 0.0, 1.0))
        mesh = grid([Cube(seed=2), Cube(origin=(0.5, 0.0, 0.0), seed=4)],
                    lambda p, i: 0.25 if i == 0 else 0.75)
        camera = parallel_camera((5.0, 0.5, 0.5), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)
        result = march(mesh, prop, camera, steps=300)
        tau0, tau1 = tau_of(0.3), tau_of(0.6)

        def medium(s):
            tau = tau0 + s * (tau1 - tau0)
            colour = (1.0 - s, 0.0, s)
            return tau, [tau * c for c in colour]

        (ta, ea), (tb, eb) = medium(0.25), medium(0.75)
        expected = composite([(tb, eb, 0.5), (ta + tb, [ea[c] + eb[c] for c in range(3)], 0.5),
                              (ta, ea, 0.5)])
        covered = 0
        for p, got in result.items():
            # Looking along -x with up +y: the image's right is -z.
            z, y = 1.3 - 0.1 * (p % SIZE + 0.5), -0.3 + 0.1 * (p // SIZE + 0.5)
            inside = 0 < z < 1 and 0 < y < 1
            covered += inside
            self.assertPixel(got, expected if inside else [0, 0, 0, 0], 2e-6, "pixel %d" % p)
        self.assertEqual(covered, 100)

    def test_ignored_cells(self):
        """Active scalars when no name is set; a triangle is ignored; a cell with a NaN scalar is left out."""
        alpha = 0.5
        prop = linear_property(alpha, alpha, (1, 1, 1), (1, 1, 1))
        lower, upper = Cube(n=1, jitter=0), Cube(n=1, origin=(0.0, 0.0, 1.0), jitter=0)
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 1.0), (0, 1, 0), 0.8)
        centre = [8 * SIZE + 8]
        whole = march(grid([lower, upper], lambda p, i: 0.5, extra_triangle=True), prop, camera, 100,
                      centre, name=None)
        self.assertAlmostEqual(whole[centre[0]][3], 1.0 - math.exp(-2.0 * tau_of(alpha)), delta=2e-6)
        holed = grid([lower, upper], lambda p, i: 0.5)
        holed.GetPointData().GetArray("s").SetValue(9, math.nan)  # a point of the upper cell only
        part = march(holed, prop, camera, 100, centre)
        self.assertAlmostEqual(part[centre[0]][3], 1.0 - math.exp(-tau_of(alpha)), delta=2e-6)

    def test_locator_follows_input_changes(self):
        """The locator is kept across calls and rebuilt when the input changes (moved points)."""
        prop = linear_property(0.5, 0.5, (1, 1, 1), (1, 1, 1))
        mesh = grid([Cube(n=2)], lambda p, i: 0.5)
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)
        marcher = vtkLocatorRayMarcher()
        marcher.SetInputData(mesh)
        marcher.SetVolumeProperty(prop)
        marcher.SetCamera(camera)
        marcher.SetImageSize(SIZE, SIZE)
        marcher.SetNumberOfSteps(50)
        self.assertEqual(vtkLocatorRayMarcher().GetNumberOfSteps(), 4000)
        ids, rgba = vtkIdTypeArray(), vtkFloatArray()
        ids.InsertNextValue(8 * SIZE + 8)
        self.assertTrue(marcher.MarchPixels(ids, rgba))
        self.assertGreater(rgba.GetValue(3), 0.3)
        self.assertTrue(marcher.MarchPixels(ids, rgba))  # the same locator again
        self.assertGreater(rgba.GetValue(3), 0.3)
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            points.SetPoint(i, x + 5.0, y, z)
        points.Modified()
        self.assertTrue(marcher.MarchPixels(ids, rgba))
        self.assertEqual(rgba.GetValue(3), 0.0)

    def test_bad_input(self):
        """(e) Missing array, non-RGB colour space, non-linear nodes, no camera, bad pixel: False and
        an error."""
        mesh = grid([Cube(n=1)], lambda p, i: 0.5)
        camera = parallel_camera((0.5, 0.5, 5.0), (0.5, 0.5, 0.5), (0, 1, 0), 0.8)

        def attempt(name="s", prop=None, cam=camera, pixel=0):
            marcher = vtkLocatorRayMarcher()
            messages = Messages(marcher)
            marcher.SetInputData(mesh)
            marcher.SetScalarArrayName(name)
            marcher.SetVolumeProperty(prop or linear_property(0.5, 0.5, (1, 1, 1), (1, 1, 1)))
            if cam:
                marcher.SetCamera(cam)
            marcher.SetImageSize(SIZE, SIZE)
            ids, rgba = vtkIdTypeArray(), vtkFloatArray()
            ids.InsertNextValue(pixel)
            ok = marcher.MarchPixels(ids, rgba)
            return ok, " ".join(messages.errors)

        ok, text = attempt(name="nope")
        self.assertFalse(ok)
        self.assertIn("nope", text)

        hsv = linear_property(0.5, 0.5, (1, 0, 0), (0, 0, 1))
        hsv.GetRGBTransferFunction(0).SetColorSpaceToHSV()
        ok, text = attempt(prop=hsv)
        self.assertFalse(ok)
        self.assertIn("RGB", text)

        bent = linear_property(0.5, 0.5, (1, 0, 0), (0, 0, 1))
        bent.GetRGBTransferFunction(0).AddRGBPoint(0.5, 0.5, 0.5, 0.5, 0.3, 0.0)
        ok, text = attempt(prop=bent)
        self.assertFalse(ok)
        self.assertIn("midpoint", text)

        sharp = linear_property(0.5, 0.5, (1, 0, 0), (0, 0, 1))
        sharp.GetScalarOpacity(0).AddPoint(0.5, 0.5, 0.5, 0.4)
        ok, text = attempt(prop=sharp)
        self.assertFalse(ok)
        self.assertIn("sharpness", text)

        ok, text = attempt(cam=None)
        self.assertFalse(ok)
        self.assertIn("camera", text)

        ok, text = attempt(pixel=SIZE * SIZE)
        self.assertFalse(ok)
        self.assertIn("outside", text)


if __name__ == "__main__":
    unittest.main()
