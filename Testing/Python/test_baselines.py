"""The image-baseline helper (baselines.py) that the Python and ParaView tests share: alternates in
VTK's naming, the nearest of them counting, and a clear failure when the baseline is missing."""
import os
import tempfile
import unittest

import baselines

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR
from vtkmodules.vtkIOImage import vtkPNGWriter


def write_png(path, rgb, size=16):
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    image.AllocateScalars(VTK_UNSIGNED_CHAR, 3)
    scalars = image.GetPointData().GetScalars()
    for i in range(size * size):
        scalars.SetTuple3(i, *rgb)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    return path


class BaselineTests(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def path(self, name):
        return os.path.join(self.folder.name, name)

    def test_alternates_follow_the_baseline_in_numeric_order(self):
        for name in ("scene.png", "scene_2.png", "scene_10.png", "scene_1.png", "scene_x.png", "other_1.png"):
            write_png(self.path(name), (0, 0, 0))
        found = [os.path.basename(p) for p in baselines.with_alternates(self.path("scene.png"))]
        self.assertEqual(found, ["scene.png", "scene_1.png", "scene_2.png", "scene_10.png"])

    def test_the_nearest_alternate_counts(self):
        write_png(self.path("scene.png"), (255, 0, 0))
        write_png(self.path("scene_1.png"), (0, 255, 0))
        candidate = write_png(self.path("candidate.png"), (0, 255, 0))
        error, used = baselines.nearest_baseline(candidate, self.path("scene.png"))
        self.assertEqual((error, os.path.basename(used)), (0.0, "scene_1.png"))
        other = write_png(self.path("blue.png"), (0, 0, 255))
        error, _ = baselines.nearest_baseline(other, self.path("scene.png"))
        self.assertGreater(error, 0.0)

    def test_a_missing_baseline_says_where_to_look(self):
        candidate = write_png(self.path("candidate.png"), (1, 2, 3))
        with self.assertRaises(FileNotFoundError) as raised:
            baselines.nearest_baseline(candidate, self.path("absent.png"))
        self.assertIn(candidate, str(raised.exception))
        self.assertIn("absent.png", str(raised.exception))


if __name__ == "__main__":
    unittest.main()
