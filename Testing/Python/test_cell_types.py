"""Prisms and polyhedra through the reference and the mappers.

Their field is the one vtkHexahedraToTetrahedra's conforming split defines (linear in each tet; a
non-convex polyhedron's centre point takes the mean of its vertices). Checks:
- the reference renders hexahedra written as VTK_POLYHEDRON exactly as the same hexahedra split;
- against vtkLocatorRayMarcher, which samples VTK's own vtkPolyhedron / prism cells (its own
  inside test, VTK's mean value weights, not the split): for a linear field both definitions agree,
  so the two renderers must;
- every mapper against the reference on a polyhedral mesh; the hexahedral mapper also on hexahedra
  mixed with polyhedra (split triangles meeting quads) and on the prisms;
- the real prism files of ../shared/data (skipped when absent).
"""
import os
import random
import sys
import unittest
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402
import uvrender  # noqa: E402
from fixtures import (HexScene, Scene, SceneTestCase, analytic_hexahedra, as_polyhedra, camera_for,  # noqa: E402
                      largest_difference, load_shared, march, reference, rmse)

from unstructuredvolume import vtkAnalyticMeshSource, vtkBarycentricShellMapper, vtkHexahedraToTetrahedra  # noqa: E402
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader  # noqa: E402

SIZE = 64
PIXELS = 600
BOUND = 1e-3


def linear_field(mesh, name="linear"):
    """A point scalar linear in x, y, z (the same under every interpolation that reproduces linear
    functions), made active."""
    values = vtkDoubleArray()
    values.SetName(name)
    values.SetNumberOfTuples(mesh.GetNumberOfPoints())
    for i in range(mesh.GetNumberOfPoints()):
        x, y, z = mesh.GetPoint(i)
        values.SetValue(i, 0.3 * x - 0.2 * y + 0.5 * z)
    mesh.GetPointData().AddArray(values)
    mesh.GetPointData().SetActiveScalars(name)
    return mesh


def constant_cells(mesh, value=0.7):
    """A cell scalar `value` as the only data."""
    values = vtkDoubleArray()
    values.SetName("cells")
    values.SetNumberOfTuples(mesh.GetNumberOfCells())
    values.Fill(value)
    mesh.GetPointData().Initialize()
    mesh.GetCellData().SetScalars(values)
    return mesh


def polyhedral_grid():
    """A 5^3 grid of hexahedra, rotated 45 degrees (planar faces), as polyhedra, with a linear field."""
    return as_polyhedra(linear_field(analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.ROTATE_45)))


def some_polyhedra(mesh, every):
    """The mesh with every `every`-th cell rewritten as a VTK_POLYHEDRON of its own faces."""
    polyhedra = as_polyhedra(mesh)
    out = vtkUnstructuredGrid()
    out.SetPoints(mesh.GetPoints())
    for c in range(mesh.GetNumberOfCells()):
        source = polyhedra if c % every == 3 else mesh
        ids = vtkIdList()
        if source is polyhedra:
            polyhedra.GetFaceStream(c, ids)
        else:
            mesh.GetCellPoints(c, ids)
        out.InsertNextCell(source.GetCellType(c), ids)
    out.GetPointData().ShallowCopy(mesh.GetPointData())
    out.GetCellData().ShallowCopy(mesh.GetCellData())
    return out


def split(mesh):
    tetrahedra = vtkHexahedraToTetrahedra()
    tetrahedra.SetInputData(mesh)
    tetrahedra.Update()
    return tetrahedra.GetOutput()


def on_cells(mesh):
    return mesh.GetPointData().GetScalars() is None


def scene_of(mesh):
    scalars = mesh.GetPointData().GetScalars() or mesh.GetCellData().GetScalars()
    low, high = scalars.GetRange()
    prop = uvrender.volume_property((low, high) if high > low else (0.0, 1.0))
    prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
    return prop, camera_for(mesh, 30, 25, distance=1.6)


class ReferenceOnPolygonalCells(unittest.TestCase):
    def test_hexahedra_as_polyhedra_render_as_their_split(self):
        mesh = polyhedral_grid()
        prop, camera = scene_of(mesh)
        error, worst = rmse(reference(mesh, prop, camera, SIZE), reference(split(mesh), prop, camera, SIZE))
        self.assertLess(worst, 1e-6)

    def check_against_marcher(self, mesh, steps=1000):
        prop, camera = scene_of(mesh)
        image = reference(mesh, prop, camera, SIZE).GetPointData().GetScalars()
        chooser = random.Random(zlib.crc32(f"{mesh.GetNumberOfCells()} {mesh.GetLength():.9g}".encode()))
        pixels = chooser.sample(range(SIZE * SIZE), PIXELS)
        fine = march(mesh, prop, camera, SIZE, pixels, steps, cells=on_cells(mesh))
        coarse = march(mesh, prop, camera, SIZE, pixels, steps // 2, cells=on_cells(mesh))
        truth = [image.GetTuple4(p) for p in pixels]
        covered = sum(1 for r in truth if r[3] > 1e-3)
        difference, marcher_error = largest_difference(truth, fine), largest_difference(fine, coarse) / 3.0
        print(f"\n  {covered} of {PIXELS} pixels covered; largest difference {difference:.3g} (bound {BOUND}), "
              f"marcher's own error {marcher_error:.2g}", end="")
        self.assertGreater(covered, 30)
        self.assertLess(marcher_error, BOUND / 4)
        self.assertLess(difference, BOUND)

    def test_polyhedra_against_the_marcher(self):
        self.check_against_marcher(polyhedral_grid())

    def test_shared_prisms_against_the_marcher(self):
        # A cell scalar checks the cells' shape alone; the linear field also the field inside, on the
        # hexagonal prism only: VTK's vtkPentagonalPrism weights do not reproduce a linear field
        # inside the prism, so there the marcher's field is not the exact one.
        for name, field in (("PentagonalPrism.vtu", "cell"), ("HexagonalPrism.vtu", "cell"),
                            ("HexagonalPrism.vtu", "linear")):
            with self.subTest(f"{name}, {field}"):
                def load():
                    reader = vtkXMLUnstructuredGridReader()
                    reader.SetFileName(shared_data.path("cells", name))
                    reader.Update()
                    return linear_field(reader.GetOutput()) if field == "linear" else constant_cells(reader.GetOutput())
                self.check_against_marcher(load_shared(self, load))


class MappersOnPolyhedra(SceneTestCase):
    BOUNDS = {"preintegrated": 1e-3, "cell projection": 1e-3, "shells": 1e-2}

    def test_tetrahedral_mappers_against_the_reference(self):
        mesh = polyhedral_grid()
        prop, camera = scene_of(mesh)
        expected = reference(mesh, prop, camera, SIZE)
        for kind, settings in (("preintegrated", {}),
                               ("shells", {"mapper_class": vtkBarycentricShellMapper}),
                               ("cell projection", {"mapper_class": vtkBarycentricShellMapper,
                                                    "RenderMode": vtkBarycentricShellMapper.CELL_PROJECTION})):
            scene = Scene(mesh, prop, camera, SIZE, **settings)
            error, _ = rmse(scene.render(), expected)
            print(f"\n  {kind}: RMSE {error:.3g} (bound {self.BOUNDS[kind]})", end="")
            self.assertEqual(scene.events.errors, 0, kind)
            self.assertLess(error, self.BOUNDS[kind], kind)

    def check_hexahedral(self, mesh, bound=1e-3):
        prop, camera = scene_of(mesh)
        scene = HexScene(mesh, prop, camera, SIZE)
        error, worst = rmse(scene.render(), reference(mesh, prop, camera, SIZE))
        print(f"\n  hexahedral: RMSE {error:.3g}, largest {worst:.3g} (bound {bound})", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(error, bound)

    def test_hexahedral_mapper_splits_polyhedra_on_the_way(self):
        # Before, the hexahedral entry refused every mesh holding a polyhedron or a prism.
        self.check_hexahedral(polyhedral_grid())

    def test_hexahedral_mapper_walks_hexahedra_and_split_polyhedra_together(self):
        # Every seventh hexahedron written as a polyhedron: its tetrahedra's triangles meet the
        # hexahedra's quads, sharing no face key; the walk crosses them as faces lying against
        # each other (uvNonConformingFaces.h), with point and with cell data.
        mesh = some_polyhedra(linear_field(analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.ROTATE_45)), 7)
        with self.subTest(data="points"):
            self.check_hexahedral(mesh)
        with self.subTest(data="cells"):
            self.check_hexahedral(constant_cells(mesh))

    def test_hexahedral_mapper_takes_shared_prisms(self):
        for name in ("PentagonalPrism.vtu", "HexagonalPrism.vtu"):
            with self.subTest(name):
                def load():
                    reader = vtkXMLUnstructuredGridReader()
                    reader.SetFileName(shared_data.path("cells", name))
                    reader.Update()
                    return constant_cells(reader.GetOutput())
                self.check_hexahedral(load_shared(self, load))


if __name__ == "__main__":
    unittest.main()
