"""The module from VTK's own Python (/usr/bin/python3 with python3-vtk9)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import uvrender  # noqa: E402
from fixtures import OUTPUT, Events, assert_matches_baseline  # noqa: E402

from unstructuredvolume import (vtkAnalyticMeshSource, vtkHexahedraToTetrahedra,  # noqa: E402
                                vtkVertexGradientFilter)
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader  # noqa: E402


class FilterTests(unittest.TestCase):
    def test_split_and_gradient_pipeline(self):
        source = vtkAnalyticMeshSource()
        source.SetResolution(4, 3, 2)
        source.SetDistortion(vtkAnalyticMeshSource.JITTER)
        split = vtkHexahedraToTetrahedra()
        split.SetInputConnection(source.GetOutputPort())
        gradient = vtkVertexGradientFilter()
        gradient.SetInputConnection(split.GetOutputPort())
        gradient.SetInputArrayToProcess(0, 0, 0, 0, "Linear")
        gradient.Update()
        out = gradient.GetOutput()
        self.assertEqual(out.GetNumberOfCells(), 6 * 4 * 3 * 2)
        self.assertEqual(out.GetCellData().GetArray("vtkOriginalCellIds").GetValue(7), 1)
        gx, gy, gz = out.GetPointData().GetArray("Gradients").GetTuple3(11)
        self.assertAlmostEqual(gx, 0.25, places=12)
        self.assertAlmostEqual(gy, 0.15, places=12)
        self.assertAlmostEqual(gz, 0.10, places=12)

    def test_five_tetrahedra_on_image_data(self):
        image = vtkImageData()
        image.SetDimensions(3, 4, 5)
        split = vtkHexahedraToTetrahedra()
        split.SetSplitModeToFiveTetrahedra()
        split.SetInputData(image)
        split.Update()
        self.assertEqual(split.GetOutput().GetNumberOfCells(), 5 * 2 * 3 * 4)

    def test_missing_array_is_an_error_not_a_crash(self):
        gradient = vtkVertexGradientFilter()
        events = Events(gradient)
        gradient.SetInputData(vtkUnstructuredGrid())
        gradient.Update()  # empty: quiet
        self.assertEqual(events.errors, 0)
        source = vtkAnalyticMeshSource()
        source.SetResolution(2, 2, 2)
        gradient.SetInputConnection(source.GetOutputPort())
        gradient.SetInputArrayToProcess(0, 0, 0, 0, "NotThere")
        gradient.Update()
        self.assertEqual(events.errors, 1)
        self.assertIsNone(gradient.GetOutput().GetPointData().GetArray("Gradients"))

    def test_default_dataset_render_matches_baseline(self):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(uvrender.ROOT, "Data", "marschner_lobb_twisted_hex.vtu"))
        split = vtkHexahedraToTetrahedra()
        split.SetInputConnection(reader.GetOutputPort())
        split.Update()
        candidate = os.path.join(OUTPUT, "python_split_projected_tetrahedra.png")
        uvrender.render_projected_tetrahedra(split.GetOutput(), "MarschnerLobb", candidate, size=256)
        error = assert_matches_baseline(self, candidate, "python_split_projected_tetrahedra.png")
        self.assertTrue(math.isfinite(error))


class ReferenceTests(unittest.TestCase):
    def test_reference_and_metrics_from_python(self):
        from unstructuredvolume import vtkUnstructuredVolumeReferenceRenderer, vtkVolumeImageErrorMetrics
        from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
        from vtkmodules.vtkRenderingCore import vtkCamera, vtkColorTransferFunction, vtkVolumeProperty
        source = vtkAnalyticMeshSource()
        source.SetResolution(3, 3, 3)
        source.Update()
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0.0, 0.1)
        opacity.AddPoint(1.0, 0.6)
        colors = vtkColorTransferFunction()
        colors.AddRGBPoint(0.0, 0, 0, 1)
        colors.AddRGBPoint(1.0, 1, 0, 0)
        prop = vtkVolumeProperty()
        prop.SetScalarOpacity(opacity)
        prop.SetColor(colors)
        camera = vtkCamera()
        camera.SetPosition(4, 3, 2)
        camera.SetClippingRange(1, 20)
        images = []
        for tolerance in (1e-7, 1e-3):
            renderer = vtkUnstructuredVolumeReferenceRenderer()
            renderer.SetInputData(source.GetOutput())
            renderer.SetVolumeProperty(prop)
            renderer.SetCamera(camera)
            renderer.SetImageSize(16, 16)
            renderer.SetTolerance(tolerance)
            self.assertTrue(renderer.Render())
            images.append(renderer.GetOutput())
        self.assertGreater(images[0].GetPointData().GetScalars().GetRange(3)[1], 0.2)
        metrics = vtkVolumeImageErrorMetrics()
        self.assertTrue(metrics.Compare(images[0], images[0]))
        self.assertEqual(metrics.GetRMSE(), 0.0)
        self.assertTrue(metrics.Compare(images[1], images[0]))
        self.assertLess(metrics.GetMaximumError(), 1e-2)


if __name__ == "__main__":
    unittest.main()
