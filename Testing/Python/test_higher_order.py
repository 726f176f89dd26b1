"""Higher-order cells (quadratic, triquadratic and biquadratic cells; Lagrange and Bezier cells)
through the reference and the mappers.

- The reference renders them exactly (curved faces met by Newton, the isoparametric field): against
  vtkLocatorRayMarcher, which samples VTK's own cells (VTK's shape functions, its own inverse), on a
  generated curved quadratic mesh, on generated curved Lagrange and Bezier tetrahedra, hexahedra and
  wedges of orders 2 and 3, and on every real higher-order mesh, point and cell data.
- Straight-sided quadratic tetrahedra carrying a linear field render as their corner tetrahedra.
- The mappers draw vtkHigherOrderSubdivision's linear cells: against the exact reference their error
  falls by second order as the level doubles, and fed the higher-order mesh itself they subdivide it
  on the way in (the hexahedral mapper walks the linear hexahedra, wedges, pyramids and tetrahedra).
- Baselines: the quadratic cylinder (tetrahedra mapper) and the triquadratic hexahedra with cell
  data (hexahedral mapper).
"""
import os
import random
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402
import uvrender  # noqa: E402
from fixtures import (BaselineTestCase, HexScene, Scene, SceneTestCase, analytic, camera_for,  # noqa: E402
                      largest_difference, load_shared, march, reference, rmse)

from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper, vtkHexahedralRayCastMapper,  # noqa: E402
                                vtkHigherOrderSubdivision, vtkPreIntegratedTetrahedraMapper)
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import (VTK_BEZIER_HEXAHEDRON, VTK_BEZIER_TETRAHEDRON,  # noqa: E402
                                            VTK_BEZIER_WEDGE, VTK_LAGRANGE_HEXAHEDRON, VTK_LAGRANGE_TETRAHEDRON,
                                            VTK_LAGRANGE_WEDGE, VTK_QUADRATIC_TETRA, VTK_TETRA, vtkBezierHexahedron,
                                            vtkBezierTetra, vtkBezierWedge, vtkHexahedron, vtkLagrangeHexahedron,
                                            vtkLagrangeTetra, vtkLagrangeWedge, vtkUnstructuredGrid, vtkWedge)
from vtkmodules.vtkRenderingCore import vtkCamera  # noqa: E402

SIZE = 64
MARCH_PIXELS = 24
MARCH_STEPS = 6000
MARCH_BOUND = 5e-6  # reference against marcher, largest RGBA difference
QUADRATIC_EDGES = ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))  # VTK's mid-edge node order


def quadratic_tetrahedra(bulge=0.0, field=lambda x, y, z: 0.3 * x - 0.2 * y + 0.5 * z):
    """vtkAnalyticMeshSource's 3^3 x 6 tetrahedra as VTK_QUADRATIC_TETRA: each edge's node is its
    midpoint moved by `bulge` times a smooth displacement (curved, conforming: one node per edge),
    every node carrying `field` of its own position."""
    linear = analytic(3)
    points = vtkPoints()
    for i in range(linear.GetNumberOfPoints()):
        points.InsertNextPoint(linear.GetPoint(i))
    midpoints = {}
    mesh = vtkUnstructuredGrid()
    ids = vtkIdList()
    for c in range(linear.GetNumberOfCells()):
        linear.GetCellPoints(c, ids)
        corners = [ids.GetId(k) for k in range(4)]
        nodes = list(corners)
        for a, b in QUADRATIC_EDGES:
            key = (min(corners[a], corners[b]), max(corners[a], corners[b]))
            if key not in midpoints:
                p, q = linear.GetPoint(key[0]), linear.GetPoint(key[1])
                x, y, z = ((u + v) / 2 for u, v in zip(p, q))
                midpoints[key] = points.InsertNextPoint(x + bulge * (1 - x * x), y + bulge * (1 - z * z) * x, z)
            nodes.append(midpoints[key])
        mesh.InsertNextCell(VTK_QUADRATIC_TETRA, 10, nodes)
    mesh.SetPoints(points)
    values = vtkDoubleArray()
    values.SetName("field")
    for i in range(points.GetNumberOfPoints()):
        values.InsertNextValue(field(*points.GetPoint(i)))
    mesh.GetPointData().SetScalars(values)
    return mesh


LATTICE_CELLS = {VTK_LAGRANGE_TETRAHEDRON: vtkLagrangeTetra, VTK_BEZIER_TETRAHEDRON: vtkBezierTetra,
                 VTK_LAGRANGE_HEXAHEDRON: vtkLagrangeHexahedron, VTK_BEZIER_HEXAHEDRON: vtkBezierHexahedron,
                 VTK_LAGRANGE_WEDGE: vtkLagrangeWedge, VTK_BEZIER_WEDGE: vtkBezierWedge}
TETRAHEDRA = (VTK_LAGRANGE_TETRAHEDRON, VTK_BEZIER_TETRAHEDRON)
WEDGES = (VTK_LAGRANGE_WEDGE, VTK_BEZIER_WEDGE)
# Each hexahedron of vtkAnalyticMeshSource as two wedges over its bottom face's 0-2 diagonal, each
# base triangle ordered as VTK's wedge wants it (its normal away from the top triangle).
HEXAHEDRON_AS_WEDGES = ((0, 3, 1, 4, 7, 5), (1, 3, 2, 5, 7, 6))


def lattice_node_count(cell_type, order):
    if cell_type in TETRAHEDRA:
        return (order + 1) * (order + 2) * (order + 3) // 6
    if cell_type in WEDGES:
        return (order + 1) * (order + 2) // 2 * (order + 1)
    return (order + 1) ** 3


def node_parametric_coordinates(cell_type, order):
    """The parametric coordinates VTK gives the nodes of a Lagrange or Bezier cell of `order`."""
    count = lattice_node_count(cell_type, order)
    cell = LATTICE_CELLS[cell_type]()
    cell.GetPointIds().SetNumberOfIds(count)
    cell.GetPoints().SetNumberOfPoints(count)
    if cell_type not in TETRAHEDRA:
        cell.SetUniformOrderFromNumPoints(count)
    cell.Initialize()
    flat = cell.GetParametricCoords()
    return [flat[3 * k:3 * k + 3] for k in range(count)]


def linear_map(cell_type, corners, r, s, t):
    """The position at (r, s, t) of the straight cell over `corners`."""
    if cell_type in TETRAHEDRA:
        weights = (1 - r - s - t, r, s, t)
    else:
        weights = [0.0] * len(corners)
        (vtkWedge if cell_type in WEDGES else vtkHexahedron).InterpolationFunctions((r, s, t), weights)
    return [sum(w * p[axis] for w, p in zip(weights, corners)) for axis in range(3)]


def lattice_cells(cell_type, order, bulge, field):
    """Curved cells of `cell_type` and `order` filling [-1, 1]^3: vtkAnalyticMeshSource's tetrahedra
    (2^3 x 6) or hexahedra (2^3, or two wedges each), every node placed at its parametric position in
    the straight cell and then displaced by `bulge` times a smooth map (nodes merged by position, so
    the cells conform), carrying `field` of that position (a Bezier cell's control points too)."""
    if cell_type in TETRAHEDRA:
        linear, corner_sets = analytic(2), ((0, 1, 2, 3),)
    else:
        linear = analytic(2, cells=vtkAnalyticMeshSource.HEXAHEDRA)
        corner_sets = HEXAHEDRON_AS_WEDGES if cell_type in WEDGES else (tuple(range(8)),)
    parametric = node_parametric_coordinates(cell_type, order)
    points, values, merged = vtkPoints(), vtkDoubleArray(), {}
    values.SetName("field")
    mesh = vtkUnstructuredGrid()
    ids = vtkIdList()
    for c in range(linear.GetNumberOfCells()):
        linear.GetCellPoints(c, ids)
        for corner_set in corner_sets:
            corners = [linear.GetPoint(ids.GetId(k)) for k in corner_set]
            nodes = []
            for r, s, t in parametric:
                x, y, z = linear_map(cell_type, corners, r, s, t)
                key = (round(x, 9), round(y, 9), round(z, 9))
                if key not in merged:
                    moved = (x + bulge * (1 - x * x), y + bulge * (1 - z * z) * x, z + bulge * x * y)
                    merged[key] = points.InsertNextPoint(moved)
                    values.InsertNextValue(field(*moved))
                nodes.append(merged[key])
            mesh.InsertNextCell(cell_type, len(nodes), nodes)
    mesh.SetPoints(points)
    mesh.GetPointData().SetScalars(values)
    return mesh


def corner_tetrahedra(mesh):
    """The quadratic tetrahedra's corners as linear tetrahedra, over the same points and data."""
    linear = vtkUnstructuredGrid()
    linear.SetPoints(mesh.GetPoints())
    linear.GetPointData().ShallowCopy(mesh.GetPointData())
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        linear.InsertNextCell(VTK_TETRA, 4, [ids.GetId(k) for k in range(4)])
    return linear


def scene_of(mesh, array, cells=False):
    data = mesh.GetCellData() if cells else mesh.GetPointData()
    data.SetActiveScalars(array)
    low, high = data.GetArray(array).GetRange()
    prop = uvrender.volume_property((low, high) if high > low else (low - 1.0, high + 1.0))
    prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
    return prop, camera_for(mesh, 30, 25, distance=1.6)


def subdivided(mesh, level=0, array=None):
    """vtkHigherOrderSubdivision's linear cells at `level` (0: its automatic choice, the field
    tolerance on `array`)."""
    subdivision = vtkHigherOrderSubdivision()
    subdivision.SetInputData(mesh)
    subdivision.SetLevel(level)
    subdivision.SetFieldArrayName(array)
    subdivision.Update()
    return subdivision.GetOutput()


def higher_order(name):
    """The loader of one of shared_data.HIGHER_ORDER_MESHES."""
    return dict((n, loader) for n, loader, _ in shared_data.HIGHER_ORDER_MESHES)[name]


class ReferenceAgainstMarcher(unittest.TestCase):
    def compare(self, mesh, array, cells=False, pixels=MARCH_PIXELS, steps=MARCH_STEPS):
        prop, camera = scene_of(mesh, array, cells)
        image = reference(mesh, prop, camera, SIZE).GetPointData().GetScalars()
        covered = [p for p in range(SIZE * SIZE) if image.GetTuple4(p)[3] > 0]
        self.assertGreater(len(covered), SIZE * SIZE // 20)
        pixels = random.Random(15).sample(covered, pixels)
        marched = march(mesh, prop, camera, SIZE, pixels, steps, array=array, cells=cells)
        difference = largest_difference([image.GetTuple4(p) for p in pixels], marched)
        self.assertLess(difference, MARCH_BOUND)
        return difference

    def test_generated_curved_quadratic_tetrahedra(self):
        self.compare(quadratic_tetrahedra(0.08, lambda x, y, z: x * x + y * z + 0.5 * z), "field")

    def test_generated_lagrange_and_bezier_cells(self):
        """VTK's Lagrange and Bezier cells, whose shape functions the marcher takes from VTK's cell
        objects and the reference from uvLatticeBasis.h."""
        # Fewer pixels and steps than for the other meshes: the marcher's Newton runs through VTK's
        # de Casteljau evaluation (slow) and, for Bezier wedges, one thread at a time.
        for cell_type, order in ((VTK_LAGRANGE_TETRAHEDRON, 3), (VTK_BEZIER_TETRAHEDRON, 2), (VTK_LAGRANGE_HEXAHEDRON, 2),
                                 (VTK_BEZIER_HEXAHEDRON, 3), (VTK_LAGRANGE_WEDGE, 2), (VTK_BEZIER_WEDGE, 2)):
            with self.subTest(cell=LATTICE_CELLS[cell_type].__name__, order=order):
                self.compare(lattice_cells(cell_type, order, 0.08, lambda x, y, z: x * x + y * z + 0.5 * z),
                             "field", pixels=6, steps=1000)

    def test_real_meshes_point_data(self):
        for name, loader, array in shared_data.HIGHER_ORDER_MESHES:
            with self.subTest(name):
                self.compare(load_shared(self, loader), array)

    def test_real_meshes_cell_data(self):
        for name, loader, _ in shared_data.HIGHER_ORDER_MESHES:
            mesh = load_shared(self, loader)
            if mesh.GetCellData().GetArray("material"):
                with self.subTest(name):
                    self.compare(mesh, "material", cells=True)


class StraightQuadraticCells(unittest.TestCase):
    def test_linear_field_renders_as_the_corner_tetrahedra(self):
        mesh = quadratic_tetrahedra()
        prop, camera = scene_of(mesh, "field")
        quadratic = reference(mesh, prop, camera, SIZE)
        linear = reference(corner_tetrahedra(mesh), prop, camera, SIZE)
        alpha = quadratic.GetPointData().GetScalars()
        self.assertGreater(max(alpha.GetTuple4(p)[3] for p in range(SIZE * SIZE)), 0.1)
        self.assertLess(rmse(quadratic, linear)[1], 1e-6)


MAPPERS = {"preintegrated": vtkPreIntegratedTetrahedraMapper, "shells": vtkBarycentricShellMapper,
           "hexahedral": vtkHexahedralRayCastMapper}


class MappersAgainstReference(SceneTestCase):
    """RMSE of each mapper on the subdivision at levels 2 and 4 against the exact higher-order
    reference: second order (ratios within RATIO_BOUND) and within LEVEL_4_BOUND at level 4."""

    RATIO_BOUND = 0.4
    LEVEL_4_BOUND = 8e-3  # at 64 x 64 pixels and the test's opacity

    def errors(self, mesh, array, mapper_names):
        prop, camera = scene_of(mesh, array)
        exact = reference(mesh, prop, camera, SIZE)
        errors = {}
        for level in (2, 4):
            linear = subdivided(mesh, level)
            for name in mapper_names:
                image = Scene(linear, prop, camera, SIZE, mapper_class=MAPPERS[name]).render()
                errors[name, level] = rmse(image, exact)[0]
        return errors

    def check(self, mesh, array, mapper_names):
        errors = self.errors(mesh, array, mapper_names)
        for name in mapper_names:
            with self.subTest(name):
                self.assertLess(errors[name, 4], self.RATIO_BOUND * errors[name, 2])
                self.assertLess(errors[name, 4], self.LEVEL_4_BOUND)

    def test_triquadratic_hexahedra(self):
        self.check(load_shared(self, higher_order("triquadratic_hexahedron")), "field",
                   ("preintegrated", "shells", "hexahedral"))

    def test_mixed_quadratic_cells(self):
        self.check(load_shared(self, higher_order("fichera_mixed_p2")), "field",
                   ("preintegrated", "shells", "hexahedral"))

    def test_generated_curved_tetrahedra(self):
        self.check(quadratic_tetrahedra(0.08, lambda x, y, z: x * x + y * z), "field",
                   ("preintegrated", "shells", "hexahedral"))


class MappersTakeHigherOrderInput(SceneTestCase):
    """Fed the higher-order mesh itself, each mapper draws what vtkHigherOrderSubdivision's default
    (its field tolerance on the rendered array) gives when fed directly."""

    def test_every_mapper(self):
        cases = [(quadratic_tetrahedra(0.08, lambda x, y, z: x * x + y * z), ("preintegrated", "shells", "hexahedral"))]
        try:
            cases.append((higher_order("triquadratic_hexahedron")(), ("hexahedral", "preintegrated")))
        except FileNotFoundError:
            pass
        for mesh, names in cases:
            prop, camera = scene_of(mesh, "field")
            for name in names:
                with self.subTest(name):
                    direct = Scene(mesh, prop, camera, SIZE, mapper_class=MAPPERS[name])
                    image = direct.render()
                    self.assertEqual(direct.events.errors, 0)
                    linear = subdivided(mesh, array="field")
                    expected = Scene(linear, prop, camera, SIZE, mapper_class=MAPPERS[name]).render()
                    self.assertLess(rmse(image, expected)[1], 1e-6)


class Baselines(BaselineTestCase):
    def test_quadratic_cylinder(self):
        """Down the pipe: the velocity profile, fast at the axis, still at the wall."""
        mesh = load_shared(self, higher_order("cylinder_quadratic"))
        prop, _ = scene_of(mesh, "velocity_norm")
        camera = vtkCamera()
        camera.SetFocalPoint(0.0, 0.0, 0.05)
        camera.SetPosition(0.02, 0.03, 0.22)
        camera.SetViewUp(0, 1, 0)
        camera.SetViewAngle(30)
        camera.SetClippingRange(0.001, 1.0)
        scene = self.scene(mesh, prop, camera)
        self.compare(scene.window, "preintegrated_quadratic_cylinder.png")

    def test_triquadratic_hexahedra_cell_data(self):
        """Each curved hexahedron in its own colour (its index as cell data)."""
        mesh = load_shared(self, higher_order("triquadratic_hexahedron"))
        index = vtkDoubleArray()
        index.SetName("index")
        for c in range(mesh.GetNumberOfCells()):
            index.InsertNextValue(c)
        mesh.GetCellData().AddArray(index)
        prop, camera = scene_of(mesh, "index", cells=True)
        scene = self.scene(mesh, prop, camera, mapper=vtkHexahedralRayCastMapper())
        self.compare(scene.window, "hexahedral_triquadratic_cells.png")


if __name__ == "__main__":
    unittest.main()
