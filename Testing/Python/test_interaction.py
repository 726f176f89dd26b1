"""Frames while the camera moves, for every mapper (AutoAdjustSampleDistances, on by default): a
frame the renderer allows a fraction of a second is drawn as a reduced image, stretched over the
window, within a stated error of the still frame; the still frame after interaction is bitwise the
still frame of a mapper that never interacted, and so is a still frame with the adjustment off."""
import unittest

from fixtures import (SceneTestCase, Scene, analytic, analytic_hexahedra, camera_for, copy_image, grab_rgba, reference,
                      rmse, statistic)
from uvrender import volume_property
from unstructuredvolume import (vtkBarycentricShellMapper, vtkHexahedralRayCastMapper,
                                vtkPreIntegratedTetrahedraMapper, vtkUnstructuredVolumeMapper)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factories)

# (name, mapper class, settings, mesh), as test_render_windows.py's.
MAPPERS = (("tetrahedra", vtkPreIntegratedTetrahedraMapper, {}, lambda: analytic(6)),
           ("shells", vtkBarycentricShellMapper, {}, lambda: analytic(6)),
           ("cell projection", vtkBarycentricShellMapper, {"RenderMode": 1}, lambda: analytic(6)),
           ("hexahedral", vtkHexahedralRayCastMapper, {}, lambda: analytic_hexahedra(6)))

SIZE = 128
STILL_RATE = 0.0001       # vtkRenderWindowInteractor's still update rate: 10,000 s allowed
INTERACTIVE_RATE = 1e6  # a microsecond allowed: less than any frame takes, so every one is reduced
COARSEST = 3.0             # the test's MaximumImageSampleDistance
# The reduced image against the reference drawn at its own size: the bound test_render_windows.py
# holds every mapper to (the shells' sampling is the loosest; interactive shells sample coarser).
REDUCED_RMSE = 0.03
# The stretched window against the still window (8-bit, over the tile): the stretch blurs edges and
# detail a few pixels wide, never more (an image drawn over part of the tile, or unstretched, is off
# by far more).
STRETCHED_RMSE = 0.05


def setUpModule():  # noqa: N802  (unittest's name)
    vtkUnstructuredVolumeMapper.SetGLErrorChecks(True)


def same_pixels(a, b):
    """Whether two float images are bitwise equal."""
    if a.GetDimensions() != b.GetDimensions():
        return False
    x, y = a.GetPointData().GetScalars(), b.GetPointData().GetScalars()
    return all(x.GetTuple4(i) == y.GetTuple4(i) for i in range(x.GetNumberOfTuples()))


class InteractionTests(SceneTestCase):
    def scene(self, mapper_class, settings, mesh, **more):
        prop = volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        scene = Scene(mesh, prop, camera, SIZE, mapper_class=mapper_class, **settings, **more)
        scene.window.SetDesiredUpdateRate(STILL_RATE)
        return scene, prop, camera

    def test_interactive_frames_are_reduced_and_still_frames_unchanged(self):
        for name, mapper_class, settings, make_mesh in MAPPERS:
            with self.subTest(mapper=name):
                mesh = make_mesh()
                untouched, _, _ = self.scene(mapper_class, settings, mesh, AutoAdjustSampleDistances=False)
                expected = copy_image(untouched.render())
                scene, prop, camera = self.scene(mapper_class, settings, mesh, MaximumImageSampleDistance=COARSEST)
                still = copy_image(scene.render())
                self.assertTrue(same_pixels(still, expected), "a still frame changed with the adjustment on")
                self.assertEqual(statistic(scene.mapper, "InteractiveFrame"), 0.0)
                still_window = grab_rgba(scene.window)

                scene.window.SetDesiredUpdateRate(INTERACTIVE_RATE)
                for _ in range(3):  # the distance at most doubles a frame: 2, then the coarsest
                    reduced = copy_image(scene.render())
                distance = statistic(scene.mapper, "UsedImageSampleDistance")
                width, height, _ = reduced.GetDimensions()
                print(f"\n  {name}: distance {distance:.3g}, image {width} x {height}", end="")
                self.assertEqual(statistic(scene.mapper, "InteractiveFrame"), 1.0)
                self.assertEqual(distance, COARSEST)
                self.assertEqual((width, height), (43, 43))  # 128 / 3, rounded up
                error, _ = rmse(reduced, reference(mesh, prop, camera, width, height))
                stretched, _ = rmse(grab_rgba(scene.window), still_window)
                print(f"; against the reference {error:.3g}, the stretched window {stretched:.3g}", end="")
                self.assertLess(error, REDUCED_RMSE)
                self.assertLess(stretched, STRETCHED_RMSE)

                scene.window.SetDesiredUpdateRate(STILL_RATE)
                after = scene.render()
                self.assertEqual(statistic(scene.mapper, "InteractiveFrame"), 0.0)
                self.assertEqual(statistic(scene.mapper, "UsedImageSampleDistance"), 1.0)
                self.assertTrue(same_pixels(after, expected), "the still frame after interaction differs")
                self.assertEqual(scene.events.errors + untouched.events.errors, 0)

    def test_adjustment_off_keeps_the_full_image_while_interacting(self):
        mesh = analytic(6)
        scene, _, _ = self.scene(vtkPreIntegratedTetrahedraMapper, {}, mesh, AutoAdjustSampleDistances=False)
        scene.window.SetDesiredUpdateRate(INTERACTIVE_RATE)
        image = scene.render()
        self.assertEqual(image.GetDimensions()[:2], (SIZE, SIZE))
        self.assertEqual(statistic(scene.mapper, "UsedImageSampleDistance"), 1.0)
        self.assertEqual(statistic(scene.mapper, "InteractiveFrame"), 0.0)
        scene.window.SetDesiredUpdateRate(STILL_RATE)


if __name__ == "__main__":
    unittest.main()
