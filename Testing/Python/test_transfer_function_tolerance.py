"""TransferFunctionTolerance: a sampled 256-node colour map, as ParaView's presets are, is reduced to
the nodes its shape needs before any mapper cuts ray segments at them, and the image stays within
the bound that follows from the tolerance (uvTransferFunctionSimplification.h: colour within it,
extinction within it relatively, at every scalar, so each pixel within about twice it) of the same
mapper keeping every node. Run by ctest under Xvfb with /usr/bin/python3."""
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fixtures import (HexScene, Scene, SceneTestCase, analytic, analytic_hexahedra, camera_for,  # noqa: E402
                      largest_difference, reference, sampled_color_map_property, statistic)

from unstructuredvolume import vtkBarycentricShellMapper, vtkPreIntegratedTetrahedraMapper  # noqa: E402

TOLERANCE = 1e-3  # the default
BOUND = 2 * TOLERANCE + 1e-5  # per RGBA channel of every pixel; the rest is float rounding


def pixels(image):
    scalars = image.GetPointData().GetScalars()
    return [scalars.GetTuple4(p) for p in range(scalars.GetNumberOfTuples())]


class ToleranceTests(SceneTestCase):
    def render(self, scene_class, mesh, tolerance, **settings):
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = sampled_color_map_property(low, high, 0.05)
        scene = scene_class(mesh, prop, camera_for(mesh), 96, TransferFunctionTolerance=tolerance, **settings)
        scene.image = pixels(scene.render())
        self.assertEqual(scene.events.errors, 0)
        return scene

    def check(self, scene_class, mesh, **settings):
        exact = self.render(scene_class, mesh, 0.0, **settings)
        scene = self.render(scene_class, mesh, TOLERANCE, **settings)
        self.assertEqual(scene.mapper.GetTransferFunctionTolerance(), TOLERANCE)
        self.assertGreaterEqual(statistic(exact.mapper, "TransferFunctionNodes"), 256)
        self.assertLess(statistic(scene.mapper, "TransferFunctionNodes"), 64)
        self.assertGreater(max(p[3] for p in exact.image), 0.3)  # something is drawn
        difference = largest_difference(exact.image, scene.image)
        self.assertLessEqual(difference, BOUND)
        self.assertGreater(difference, 0.0)  # nodes were dropped

    def test_default(self):
        for mapper_class in (vtkPreIntegratedTetrahedraMapper, vtkBarycentricShellMapper):
            self.assertEqual(mapper_class().GetTransferFunctionTolerance(), TOLERANCE)

    # The tetrahedra mapper and cell projection cut their segments at the nodes (EXACT): AUTOMATIC
    # would read a table within the tolerance per segment instead, whose error adds to this one
    # (test_preintegrated_tetrahedra.py's test_segment_table_within_its_measured_error).
    def test_preintegrated_tetrahedra(self):
        self.check(Scene, analytic(8), mapper_class=vtkPreIntegratedTetrahedraMapper, SegmentIntegration=2)

    def test_barycentric_shells_and_cell_projection(self):
        mesh = analytic(8)
        self.check(Scene, mesh, mapper_class=vtkBarycentricShellMapper)
        self.check(Scene, mesh, mapper_class=vtkBarycentricShellMapper,
                   RenderMode=vtkBarycentricShellMapper.CELL_PROJECTION, SegmentIntegration=2)

    def test_hexahedral_ray_cast(self):
        # Its traversal reads at most 64 nodes from uniforms: every node means a resampled function
        # (with a warning), the dropped nodes the exact one within the tolerance. So both against
        # the reference, which keeps every node (and no early ray termination, whose error is its own).
        mesh = analytic_hexahedra(8)
        every_node = self.render(HexScene, mesh, 0.0, OpacityThreshold=1.0)
        self.assertEqual((every_node.events.warnings, statistic(every_node.mapper, "TransferFunctionNodes")), (1, 64))
        scene = self.render(HexScene, mesh, TOLERANCE, OpacityThreshold=1.0)
        self.assertEqual(scene.events.warnings, 0)
        self.assertLess(statistic(scene.mapper, "TransferFunctionNodes"), 64)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        truth = pixels(reference(mesh, sampled_color_map_property(low, high, 0.05), camera_for(mesh), 96))
        self.assertLessEqual(largest_difference(truth, scene.image), BOUND)
        self.assertGreater(largest_difference(truth, every_node.image), BOUND)


if __name__ == "__main__":
    unittest.main()
