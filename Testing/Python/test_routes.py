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
                      reference, rmse, shared_window, thin_shell_property, transparent_property)

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

    def check(self, make_scene, mesh, bound, isovalue=None):
        """Renders the scene `make_scene(mesh, property, camera)` makes and checks its RMSE against the
        reference. With `isovalue` (a fraction of the range) the volume is transparent and the scene
        draws an opaque, unlit isosurface there, which the reference renders as its limit: a thin,
        very opaque shell of the transfer function (only rays grazing it differ)."""
        camera = camera_for(mesh)
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
