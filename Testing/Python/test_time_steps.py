"""Time steps as a reader delivers them: every step a new vtkUnstructuredGrid whose arrays are new
objects. Each mapper must recognise from the content what changed (nothing, the values, the points,
the cells), redo only what that needs, and draw each step as a new mapper given that step draws it."""
import math
import unittest

from fixtures import (SceneTestCase, Scene, analytic, analytic_hexahedra, camera_for, property_from_nodes, rmse,
                      statistic)
import uvrender

from unstructuredvolume import vtkBarycentricShellMapper, vtkHexahedralRayCastMapper, vtkPreIntegratedTetrahedraMapper
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
from vtkmodules.util.numpy_support import vtk_to_numpy

# Exact segments: a time step may keep the last step's scalar normalisation and segment tables
# (while its values and edges fit them), whose reads differ from a new mapper's tables by up to the
# transfer-function tolerance; cut exactly, the same mesh, scalar and view differ by rounding only.
MAPPERS = {
    "tetrahedra": lambda: configured(vtkPreIntegratedTetrahedraMapper(), "SegmentIntegrationToExact"),
    "shells": lambda: fixed_samples(configured(vtkBarycentricShellMapper(), "SegmentIntegrationToExact")),
    "cell projection": lambda: configured(vtkBarycentricShellMapper(), "RenderModeToCellProjection",
                                          "SegmentIntegrationToExact"),
    "hexahedral": vtkHexahedralRayCastMapper,
}
SAME_IMAGE = 1e-5


def configured(mapper, *calls):
    """`mapper` after Set<call>() for each call."""
    for call in calls:
        getattr(mapper, "Set" + call)()
    return mapper


def fixed_samples(mapper):
    # The automatic sample distance follows the bounds of the last build, not of moved points (so a
    # deforming mesh keeps its segment table): a fixed one makes the steps comparable with new mappers.
    mapper.SetSampleDistance(0.02)
    return mapper


CELL_FIELD = ("ScalarModeToUseCellFieldData",)


def step(base, values=None, points=None, cell_values=None):
    """`base` as a reader's next step: a deep copy (every array new), with new point values, points or
    cell values where given (functions of the point or cell centre)."""
    grid = vtkUnstructuredGrid()
    grid.DeepCopy(base)
    if values:
        array = vtkDoubleArray()
        array.SetName("MarschnerLobb")
        array.SetNumberOfTuples(grid.GetNumberOfPoints())
        for p in range(grid.GetNumberOfPoints()):
            array.SetValue(p, values(grid.GetPoint(p)))
        grid.GetPointData().RemoveArray("MarschnerLobb")
        grid.GetPointData().SetScalars(array)
    if cell_values:
        array = vtkDoubleArray()
        array.SetName("cellField")
        array.SetNumberOfTuples(grid.GetNumberOfCells())
        for c in range(grid.GetNumberOfCells()):
            bounds = grid.GetCell(c).GetBounds()
            array.SetValue(c, cell_values([(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]))
        grid.GetCellData().RemoveArray("cellField")
        grid.GetCellData().AddArray(array)
    if points:
        moved = vtkPoints()
        moved.SetNumberOfPoints(grid.GetNumberOfPoints())
        for p in range(grid.GetNumberOfPoints()):
            moved.SetPoint(p, points(grid.GetPoint(p)))
        grid.SetPoints(moved)
    return grid


def wave(t):
    return lambda x: 0.5 + 0.5 * math.sin(3.0 * x[0] + t) * math.cos(2.0 * x[1] - t)


def swirl(t):
    return lambda x: (x[0] + 0.06 * math.sin(3 * x[1] + t), x[1] + 0.05 * math.cos(2 * x[2] - t), x[2])


def turned(x):
    """Half a turn about the z axis and a shear: what was in front is behind, so every order changes."""
    return (-x[0] + 0.3 * x[2], -x[1], x[2])


class TimeStepTests(SceneTestCase):
    def setUp(self):
        self.prop = uvrender.volume_property((0.0, 1.0))
        self.size = 64

    def mapper(self, mapper_name, calls):
        mapper = configured(MAPPERS[mapper_name](), *calls)
        if calls == CELL_FIELD:
            mapper.SelectScalarArray("cellField")
        return mapper

    def play(self, mapper_name, base, steps, calls=()):
        """Renders `base`, then each (name, grid, expected counts) step through the same mapper; checks
        each image against a fresh mapper's and the mapper's counts of builds and refreshes."""
        camera = camera_for(base)
        scene = Scene(base, self.prop, camera, self.size, mapper=self.mapper(mapper_name, calls))
        scene.render()
        for name, grid, (builds, point_refreshes, value_refreshes) in steps:
            with self.subTest(mapper=mapper_name, step=name):
                scene.mapper.SetInputData(grid)
                image = scene.render()
                fresh = Scene(grid, self.prop, camera, self.size, mapper=self.mapper(mapper_name, calls))
                expected = fresh.render()
                self.assertLess(rmse(image, expected)[1], SAME_IMAGE)
                self.assertGreater(vtk_to_numpy(expected.GetPointData().GetScalars())[:, 3].max(), 0.05)
                counts = (statistic(scene.mapper, "MeshBuilds"), statistic(scene.mapper, "PointRefreshes"),
                          statistic(scene.mapper, "ValueRefreshes"))
                self.assertEqual(counts, (builds, point_refreshes, value_refreshes))
                self.assertEqual(scene.events.errors, 0)

    def test_point_values_points_and_both_change_by_content(self):
        for mapper_name in MAPPERS:
            base = analytic_hexahedra(5) if mapper_name == "hexahedral" else analytic(5)
            values = step(base, values=wave(0.3))
            self.play(mapper_name, base, [
                ("same content, new arrays", step(base), (1, 0, 0)),
                ("new values", values, (1, 0, 1)),
                ("new points", step(values, points=swirl(0.4)), (1, 1, 1)),
                ("both", step(base, values=wave(0.9), points=swirl(0.8)), (1, 1, 2)),
                ("both, the mesh turned around", step(base, values=wave(1.4), points=turned), (1, 1, 3)),
                ("new cells", analytic(4) if mapper_name != "hexahedral" else analytic_hexahedra(4), (2, 1, 3)),
            ])

    def test_points_moved_with_new_values_reorder_the_cells(self):
        # Every cell visible whatever its values, so the visible list cannot change: the order must
        # follow the points by itself when a step brings new values and moved points together.
        self.prop = property_from_nodes([(0.0, 0.3), (1.0, 0.9)], [(0.0, (0.1, 0.3, 1.0)), (1.0, (1.0, 0.5, 0.1))], 0.3)
        base = analytic(5)
        for mapper_name in ("tetrahedra", "cell projection"):
            self.play(mapper_name, base, [
                ("both, the mesh turned around", step(base, values=wave(0.7), points=turned), (1, 0, 1)),
            ])

    def test_split_cells_keep_their_split(self):
        # Hexahedra to the tetrahedral mappers: a value step moves the values onto the split instead
        # of splitting again; a cell scalar through the split's original cell ids.
        base = analytic_hexahedra(5)
        cells = step(base, cell_values=wave(0.0))
        for mapper_name in ("tetrahedra", "cell projection"):
            self.play(mapper_name, base, [
                ("new values", step(base, values=wave(0.5)), (1, 0, 1)),
                ("new points", step(base, values=wave(0.5), points=swirl(0.2)), (1, 1, 1)),
            ])
            self.play(mapper_name, cells, [
                ("new cell values", step(cells, cell_values=wave(1.1)), (1, 0, 1)),
            ], CELL_FIELD)

    def test_a_nan_appearing_changes_the_cells_drawn(self):
        base = analytic(5)

        def with_a_nan(t):
            field = wave(t)
            return lambda x: float("nan") if x[0] > 0.6 and x[1] > 0.6 else field(x)
        for mapper_name in ("tetrahedra", "hexahedral"):
            mesh = analytic_hexahedra(5) if mapper_name == "hexahedral" else base
            # A value refresh that changes which cells are drawn counts as one and draws as a build.
            self.play(mapper_name, mesh, [
                ("a NaN appears", step(mesh, values=with_a_nan(0.2)), (1, 0, 1) if mapper_name != "hexahedral"
                 else (2, 0, 0)),
            ])


if __name__ == "__main__":
    unittest.main()
