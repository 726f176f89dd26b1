"""Every mapper and route on small scenes against the reference, with one set of bounds for every
OpenGL driver: ctest runs this module on llvmpipe and on softpipe (GALLIUM_DRIVER), whose 3.3 core
context and interpreted shaders run GLSL differently where the specification leaves room. The
meshes are just large enough that each route's draws pass 4096 vertices (softpipe cuts longer
non-indexed draws into pieces) and that 2x2 pixel quads diverge in every loop. Run by ctest under
Xvfb with /usr/bin/python3."""
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import uvrender  # noqa: E402
from fixtures import (HexScene, Scene, SceneTestCase, analytic, analytic_hexahedra, camera_for,  # noqa: E402
                      folded_slab, reference, rmse, shared_window, thin_shell_property, transparent_property)

from unstructuredvolume import vtkBarycentricShellMapper  # noqa: E402

PROJECTION, RAY_CASTING = 0, 1                   # vtkPreIntegratedTetrahedraMapper::RenderModes
VERTEX_PULLING, GEOMETRY_SHADER = 0, 1           # vtkUnstructuredVolumeMapper::ProjectionRoutes
TABLE, EXACT = 1, 2                              # vtkUnstructuredVolumeMapper::SegmentIntegrations
ACCURATE, FAST, FIXED_STEPS = 0, 1, 2            # vtkHexahedralRayCastMapper::IntegrationModes
SHELLS, CELL_PROJECTION = 0, 1                   # vtkBarycentricShellMapper::RenderModes
SIZE = 64
COLOR = (0.9, 0.6, 0.2)
DRIVER = os.environ.get("GALLIUM_DRIVER", "llvmpipe")


class RouteTestCase(SceneTestCase):
    @classmethod
    def setUpClass(cls):
        # Mesa falls back to another driver without a word where the one asked for is missing.
        window = shared_window()
        window.Render()  # makes the context
        renderer = [line for line in window.ReportCapabilities().splitlines() if "renderer string" in line]
        assert renderer and DRIVER in renderer[0], f"asked for {DRIVER}, got {renderer}"

    def check(self, make_scene, mesh, bound, isovalue=None, camera=None):
        """Renders the scene `make_scene(mesh, property, camera)` makes and checks its RMSE against the
        reference. With `isovalue` (a fraction of the range) the volume is transparent and the scene
        draws an opaque, unlit isosurface there, which the reference renders as its limit: a thin,
        very opaque shell of the transfer function (only rays grazing it differ)."""
        camera = camera or camera_for(mesh)
        if isovalue is None:
            prop = uvrender.volume_property((0.0, 1.0))
            expected = reference(mesh, prop, camera, SIZE)
        else:
            low, high = mesh.GetPointData().GetScalars().GetRange()
            value = low + isovalue * (high - low)
            prop = transparent_property(COLOR)
            expected = reference(mesh, thin_shell_property(low, high, value, COLOR, mesh.GetLength()), camera, SIZE)
        scene = make_scene(mesh, prop, camera)
        if isovalue is not None:
            scene.mapper.AddIsosurface(value, *COLOR, 1.0)
        error, largest = rmse(scene.render(), expected)
        print(f"\n  {DRIVER}: RMSE {error:.3g}, largest {largest:.3g}", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.window_events.errors, 0)
        self.assertLess(error, bound)
        return error


class TetrahedraRoutes(RouteTestCase):
    """vtkPreIntegratedTetrahedraMapper: projection by either route, ray casting, table and exact."""

    def scene(self, **settings):
        return lambda mesh, prop, camera: Scene(mesh, prop, camera, SIZE, **settings)

    def test_projection_vertex_pulling(self):
        for integration, bound in ((TABLE, 1e-4), (EXACT, 5e-5)):
            self.check(self.scene(RenderMode=PROJECTION, ProjectionRoute=VERTEX_PULLING,
                                  SegmentIntegration=integration), analytic(12), bound)

    def test_projection_geometry_shader(self):
        for integration, bound in ((TABLE, 1e-4), (EXACT, 5e-5)):
            self.check(self.scene(RenderMode=PROJECTION, ProjectionRoute=GEOMETRY_SHADER,
                                  SegmentIntegration=integration), analytic(12), bound)

    def test_ray_casting(self):
        for integration, bound in ((TABLE, 1e-4), (EXACT, 1e-6)):
            self.check(self.scene(RenderMode=RAY_CASTING, SegmentIntegration=integration), analytic(12), bound)

    def test_ray_casting_with_an_isosurface(self):
        self.check(self.scene(RenderMode=RAY_CASTING, SegmentIntegration=EXACT), analytic(12), 1e-3, isovalue=0.5)


class HexahedralRoutes(RouteTestCase):
    """vtkHexahedralRayCastMapper in each integration mode."""

    def scene(self, **settings):
        return lambda mesh, prop, camera: HexScene(mesh, prop, camera, SIZE, **settings)

    def test_accurate(self):
        self.check(self.scene(IntegrationMode=ACCURATE), analytic_hexahedra(12), 1.5e-3)

    def test_accurate_with_an_isosurface(self):
        self.check(self.scene(IntegrationMode=ACCURATE), analytic_hexahedra(12), 1e-3, isovalue=0.5)

    def test_fast(self):
        self.check(self.scene(IntegrationMode=FAST), analytic_hexahedra(12), 4e-3)

    def test_fixed_steps(self):
        self.check(self.scene(IntegrationMode=FIXED_STEPS), analytic_hexahedra(12), 1.5e-3)

    def test_folded_and_overlapping_cells(self):
        # The folded-cell program: a folded cell's parts from its faces' hits in order, the media of
        # overlapping cells added. softpipe wrote those hits to the wrong slots where the pixels of a
        # 2x2 quad walked different cells.
        mesh = folded_slab(4, -0.5, layers=2)
        for azimuth, elevation in ((30, 25), (120, -20)):
            self.check(self.scene(), mesh, 1e-3, camera=camera_for(mesh, azimuth, elevation, distance=1.8))


class ShellRoutes(RouteTestCase):
    """vtkBarycentricShellMapper: shells, and cell projection by either route."""

    def scene(self, **settings):
        return lambda mesh, prop, camera: Scene(mesh, prop, camera, SIZE, mapper_class=vtkBarycentricShellMapper,
                                                **settings)

    def test_shells(self):
        self.check(self.scene(RenderMode=SHELLS), analytic(12), 1e-3)

    def test_shells_with_an_isosurface(self):
        self.check(self.scene(RenderMode=SHELLS), analytic(12), 1e-3, isovalue=0.5)

    def test_cell_projection(self):
        for route in (VERTEX_PULLING, GEOMETRY_SHADER):
            self.check(self.scene(RenderMode=CELL_PROJECTION, ProjectionRoute=route, SegmentIntegration=EXACT),
                       analytic(12), 2e-5)


class SubPixelCoverage(RouteTestCase):
    """The contract for geometry finer than a pixel: every mapper finds the cells a ray crosses by
    rasterising their projected faces, and a rasteriser snaps projected corners to its sub-pixel grid
    (GL_SUBPIXEL_BITS: at least 4 bits, a sixteenth of a pixel; llvmpipe's is 8). Coverage of a pixel
    is therefore the reference's wherever the pixel's centre is at least 1/16 pixel from every
    projected edge, and the rasteriser's closer than that. A mesh a fraction of a pixel across (the
    stress suite's far-away camera at one pixel) lies wholly within that band."""

    COLUMN, PIXELS = 3, 8

    def scenes(self, mesh, prop, camera):
        yield "tetrahedra, projection", Scene(mesh, prop, camera, self.PIXELS, RenderMode=PROJECTION)
        yield "tetrahedra, ray casting", Scene(mesh, prop, camera, self.PIXELS, RenderMode=RAY_CASTING)
        yield "shells", Scene(mesh, prop, camera, self.PIXELS, mapper_class=vtkBarycentricShellMapper)
        yield "cell projection", Scene(mesh, prop, camera, self.PIXELS, mapper_class=vtkBarycentricShellMapper,
                                       RenderMode=CELL_PROJECTION)
        yield "hexahedral", HexScene(mesh, prop, camera, self.PIXELS)

    def camera(self, offset):
        """Parallel view down z with column COLUMN's pixel centres `offset` pixels right of x = 0."""
        from vtkmodules.vtkRenderingCore import vtkCamera
        scale = 0.2
        pixel = 2.0 * scale / self.PIXELS
        x = offset * pixel + scale - (self.COLUMN + 0.5) * pixel
        camera = vtkCamera()
        camera.ParallelProjectionOn()
        camera.SetParallelScale(scale)
        camera.SetPosition(x, 0.35, 5.0)
        camera.SetFocalPoint(x, 0.35, 0.0)
        camera.SetViewUp(0.0, 1.0, 0.0)
        camera.SetClippingRange(1.0, 10.0)
        return camera

    def test_coverage_is_exact_a_sixteenth_of_a_pixel_from_an_edge(self):
        # One tetrahedron whose outline has an edge along x = 0, on its right and then on its left
        # (rasterisers count a pixel centre on an edge to one side only), a face rising steeply from
        # it so the volume is thick close to it, moved across column COLUMN's centres.
        from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
        from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkUnstructuredGrid
        prop = uvrender.volume_property((0.0, 1.0))
        prop.SetScalarOpacityUnitDistance(0.002)
        band = {}
        for side in (1, -1):
            mesh = vtkUnstructuredGrid()
            points, scalars = vtkPoints(), vtkDoubleArray()
            scalars.SetName("f")
            for (x, y, z), value in (((0, 0, 0), 0.2), ((1, 0, 0), 0.8), ((0, 1, 0), 0.5), ((0.002, 0.3, 1), 0.6)):
                points.InsertNextPoint(side * x, y, z)
                scalars.InsertNextValue(value)
            mesh.SetPoints(points)
            mesh.GetPointData().SetScalars(scalars)
            mesh.InsertNextCell(VTK_TETRA, 4, [0, 1, 2, 3])
            for sixteenths in (8, 2, 1, -1, -2, -8, 1 / 16, -1 / 16, 1 / 256, -1 / 256):
                self.check_coverage(mesh, prop, sixteenths / 16, side, band)
        print("\n  " + DRIVER + ", pixels the rasteriser decided within 1/16 pixel: " +
              ", ".join(f"{name} {count}" for name, count in band.items()), end="")

    def check_coverage(self, mesh, prop, offset, side, band):
        """Every mapper's image against the reference with the edge `offset` pixels left of column
        COLUMN's centres: the same wherever |offset| >= 1/16; within, different in that column only
        (counted in `band`)."""
        camera = self.camera(offset)
        expected = reference(mesh, prop, camera, self.PIXELS)
        alpha = expected.GetPointData().GetScalars()
        column = [alpha.GetTuple4(row * self.PIXELS + self.COLUMN)[3] for row in range(self.PIXELS)]
        if abs(offset) >= 1 / 16:
            self.assertEqual(max(column) > 0.1, side * offset > 0)  # the column is inside, or not
        for name, scene in self.scenes(mesh, prop, camera):
            with self.subTest(mapper=name, offset=offset, side=side):
                image = scene.render()
                self.assertEqual(scene.events.errors, 0)
                self.assertEqual(scene.window_events.errors, 0)
                drawn = image.GetPointData().GetScalars()
                off = [p for p in range(self.PIXELS * self.PIXELS)
                       if abs(drawn.GetTuple4(p)[3] - alpha.GetTuple4(p)[3]) > 0.01]
                if abs(offset) >= 1 / 16:
                    self.assertEqual(off, [])
                else:
                    self.assertTrue(all(p % self.PIXELS == self.COLUMN for p in off), off)
                    band[name] = band.get(name, 0) + len(off)


class BufferTextureLimit(SceneTestCase):
    """A mesh that needs more buffer-texture texels than the driver allows (GL_MAX_TEXTURE_BUFFER_SIZE:
    softpipe's is 65536, OpenGL 3.3's least) gets one clear error per frame and a transparent image."""

    @unittest.skipUnless(DRIVER == "softpipe", "llvmpipe holds 2^27 texels: the mesh would take gigabytes")
    def test_each_mapper_refuses_a_mesh_over_the_limit(self):
        prop = uvrender.volume_property((0.0, 1.0))
        tetrahedra, hexahedra = analytic(24), analytic_hexahedra(33)  # 82944 tetrahedra; 35937 cells of 2 texels
        for name, scene in (("tetrahedra", Scene(tetrahedra, prop, camera_for(tetrahedra), 32)),
                            ("shells", Scene(tetrahedra, prop, camera_for(tetrahedra), 32,
                                             mapper_class=vtkBarycentricShellMapper)),
                            ("hexahedral", HexScene(hexahedra, prop, camera_for(hexahedra), 32))):
            with self.subTest(name):
                image = scene.render()
                self.assertEqual(scene.events.errors, 1)
                self.assertEqual(image.GetPointData().GetScalars().GetRange(3), (0.0, 0.0))
                self.assertEqual(scene.window_events.errors, 0)


if __name__ == "__main__":
    unittest.main()
