"""The module from VTK's own Python (/usr/bin/python3 with python3-vtk9)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402
import uvrender  # noqa: E402
from fixtures import OUTPUT, Events, as_polyhedra, assert_matches_baseline  # noqa: E402

from unstructuredvolume import (vtkAnalyticMeshSource, vtkHexahedraToTetrahedra,  # noqa: E402
                                vtkVertexGradientFilter)
from vtkmodules.vtkCommonCore import vtkIdList  # noqa: E402
from vtkmodules.vtkCommonDataModel import VTK_POLYHEDRON, vtkImageData, vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader  # noqa: E402


def split(mesh):
    """vtkHexahedraToTetrahedra's output and its error count."""
    splitter = vtkHexahedraToTetrahedra()
    events = Events(splitter)
    splitter.SetInputData(mesh)
    splitter.Update()
    return splitter.GetOutput(), events.errors


def tet_set(tets):
    """The tets as sorted point-id tuples."""
    ids = vtkIdList()
    found = set()
    for t in range(tets.GetNumberOfCells()):
        tets.GetCellPoints(t, ids)
        found.add(tuple(sorted(ids.GetId(v) for v in range(4))))
    return found


def total_volume(mesh):
    """Sum of vtkCellSizeFilter's cell volumes (VTK's own measure, independent of the split)."""
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(mesh)
    sizes.ComputeVolumeOn()
    sizes.Update()
    volume = sizes.GetOutput().GetCellData().GetArray("Volume")
    return sum(volume.GetValue(i) for i in range(volume.GetNumberOfTuples()))


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

    def test_hexahedra_as_polyhedra_give_the_hexahedron_split(self):
        source = vtkAnalyticMeshSource()
        source.SetResolution(3, 2, 2)
        source.SetDistortion(vtkAnalyticMeshSource.ROTATE_45)
        source.Update()
        hexes = source.GetOutput()
        expected, errors = split(hexes)
        self.assertEqual(errors, 0)
        tets, errors = split(as_polyhedra(hexes))
        self.assertEqual(errors, 0)
        self.assertEqual(tets.GetNumberOfPoints(), hexes.GetNumberOfPoints())
        self.assertEqual(tet_set(tets), tet_set(expected))
        self.assertAlmostEqual(total_volume(tets), total_volume(hexes), places=12)

    def test_shared_prism_files_split_to_their_volume(self):
        for name, count in (("PentagonalPrism.vtu", 9), ("HexagonalPrism.vtu", 12)):
            with self.subTest(name):
                try:
                    path = shared_data.path("cells", name)
                except FileNotFoundError:
                    self.skipTest("../shared/data is absent")
                reader = vtkXMLUnstructuredGridReader()
                reader.SetFileName(path)
                reader.Update()
                prism = reader.GetOutput()
                tets, errors = split(prism)
                self.assertEqual(errors, 0)
                self.assertEqual(tets.GetNumberOfCells(), count)
                volumes = vtkCellSizeFilter()
                volumes.SetInputData(tets)
                volumes.Update()
                volume = volumes.GetOutput().GetCellData().GetArray("Volume")
                self.assertGreater(min(volume.GetValue(i) for i in range(count)), 0.0)
                self.assertAlmostEqual(total_volume(tets), total_volume(prism), places=6)
                polyhedral, errors = split(as_polyhedra(prism))
                self.assertEqual(errors, 0)
                self.assertEqual(tet_set(polyhedral), tet_set(tets))

    def test_open_polyhedron_is_an_error_not_a_crash(self):
        source = vtkAnalyticMeshSource()
        source.SetResolution(1, 1, 1)
        source.Update()
        cube = as_polyhedra(source.GetOutput())
        stream = vtkIdList()
        cube.GetFaceStream(0, stream)
        stream.SetId(0, stream.GetId(0) - 1)  # drop the last face
        stream.SetNumberOfIds(stream.GetNumberOfIds() - 5)
        cube.InsertNextCell(VTK_POLYHEDRON, stream)
        tets, errors = split(cube)
        self.assertEqual(errors, 1)
        self.assertEqual(tets.GetNumberOfCells(), 6)  # the closed cube only

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
