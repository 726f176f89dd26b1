"""Corner-point reservoir grids, as reservoir writers (Eclipse GRDECL, RESQML) hand them to VTK.

Hexahedra stand in columns on straight, slightly slanted pillars, one cell per layer and column.
What makes them hard, and what this generator reproduces on purpose:
- layers pinch out: where a layer's thickness is zero, its top and bottom nodes on a pillar are one
  node (merged ids). Its cells are then wedges, pyramids, tetrahedra or flat cells with no volume,
  written as hexahedra with repeated point ids;
- a fault with a throw: the columns past it are moved down, and the nodes on the fault's pillars
  are written twice, once per side, so faces across the fault do not match;
- left-handed ordering: depth grows downwards, points 0-3 are the top face and 4-7 the bottom one,
  so with z up every cell has a negative Jacobian;
- UTM-sized coordinates (hundreds of kilometres east, thousands north), in double precision.

A module of its own (not fixtures.py) so that the stress suite and the benchmark can share it."""
import math

from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, vtkUnstructuredGrid

UTM_ORIGIN = (3.0e5, 7.5e6)


def clamp(x, low=0.0, high=1.0):
    return max(low, min(high, x))


class CornerPointGrid:
    """The grid's geometry as functions of the unit column coordinates (u, v) in [0, 1]^2."""

    def __init__(self, columns, layers, pinch, fault, origin, spacing, throw):
        self.columns, self.layers = columns, layers
        self.pinch, self.fault, self.throw = pinch, fault, throw
        self.origin, self.spacing = origin, spacing
        self.fault_column = columns[0] // 2 if fault else None

    def top(self, u, v):
        """Depth of the top horizon: a dome (an anticline's crest is where the oil is)."""
        return 2000.0 - 40.0 * math.exp(-((u - 0.5) ** 2 + (v - 0.45) ** 2) / 0.08)

    def thickness(self, layer, u, v):
        """Layer thickness; zero where it pinches out. Layer 1 thins out westwards across a line
        (whole columns flat, a row of wedges); layer 3 vanishes inside a circle (one, two or three
        of a column's pillars pinched)."""
        base = 6.0 + 2.0 * (layer % 3) + 1.5 * math.sin(3.0 * u + layer) * math.cos(2.0 * v)
        if self.pinch and layer == 1:
            return base * clamp((u - 0.3) / 0.25)
        if self.pinch and layer == 3:
            radius = math.hypot(u - 0.75, v - 0.65)
            return base * clamp((radius - 0.15) / 0.15)
        return base

    def depths(self, u, v):
        """The depth of every horizon on one pillar, top first; a pinched layer repeats a depth."""
        depth = [self.top(u, v)]
        for layer in range(self.layers):
            depth.append(depth[-1] + self.thickness(layer, u, v))
        return depth

    def fault_throw(self, v):
        """A scissor fault: its throw grows along the fault trace."""
        return self.throw * (0.5 + v)

    def position(self, i, j, depth):
        """The point at `depth` on pillar (i, j): pillars lean eastwards with depth, a little."""
        nx, ny = self.columns
        wobble = 0.08 * math.sin(1.7 * i + 2.3 * j)
        x = self.origin[0] + self.spacing[0] * (i + wobble) + 0.02 * (depth - 2000.0)
        y = self.origin[1] + self.spacing[1] * (j - wobble)
        return x, y, -depth


def corner_point_grid(columns=(10, 8), layers=5, pinch=True, fault=True, left_handed=True,
                      origin=UTM_ORIGIN, spacing=(100.0, 100.0), throw=10.0):
    """A corner-point grid of columns[0] x columns[1] columns and `layers` layers of hexahedra.
    Cell data `PORO` (the active scalars) and point data `PRESSURE` carry smooth fields."""
    grid = CornerPointGrid(columns, layers, pinch, fault, origin, spacing, throw)
    nx, ny = columns
    points = vtkPoints()
    points.SetDataType(VTK_DOUBLE)
    pressure = vtkDoubleArray()
    pressure.SetName("PRESSURE")
    stacks = {}  # (pillar i, j, side of the fault) -> node id per horizon, merged where pinched

    def stack(i, j, side):
        key = (i, j, side)
        if key not in stacks:
            u, v = i / nx, j / ny
            ids = []
            for depth in grid.depths(u, v):
                if side:
                    depth += grid.fault_throw(v)
                if ids and points.GetPoint(ids[-1])[2] == -depth:
                    ids.append(ids[-1])  # a pinched layer: one node, as writers merge them
                    continue
                ids.append(points.InsertNextPoint(*grid.position(i, j, depth)))
                pressure.InsertNextValue(200.0 + 0.1 * (depth - 1950.0) + 3.0 * math.sin(4.0 * u + 3.0 * v))
            stacks[key] = ids
        return stacks[key]

    mesh = vtkUnstructuredGrid()
    porosity = vtkDoubleArray()
    porosity.SetName("PORO")
    for layer in range(layers):
        for j in range(ny):
            for i in range(nx):
                side = 1 if fault and i >= grid.fault_column else 0
                corners = [stack(i, j, side), stack(i + 1, j, side), stack(i + 1, j + 1, side), stack(i, j + 1, side)]
                top = [c[layer] for c in corners]
                bottom = [c[layer + 1] for c in corners]
                mesh.InsertNextCell(VTK_HEXAHEDRON, 8, top + bottom if left_handed else bottom + top)
                u, v = (i + 0.5) / nx, (j + 0.5) / ny
                porosity.InsertNextValue(0.08 + 0.04 * layer + 0.1 * math.sin(5.0 * u) * math.cos(4.0 * v) ** 2)
    mesh.SetPoints(points)
    mesh.GetPointData().AddArray(pressure)
    mesh.GetCellData().SetScalars(porosity)
    return mesh


def repeated_id_cells(mesh):
    """How many cells repeat a point id."""
    count = 0
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        values = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        count += len(set(values)) < len(values)
    return count


HEXAHEDRON_FACES = ((0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2), (0, 3, 2, 1), (4, 5, 6, 7))


def face_use_counts(mesh):
    """How many cells use each face of three or more distinct point ids, keyed by those ids."""
    uses = {}
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        for face in HEXAHEDRON_FACES:
            key = frozenset(ids.GetId(k) for k in face)
            if len(key) >= 3:
                uses[key] = uses.get(key, 0) + 1
    return uses


def corner_jacobian_signs(mesh):
    """The sign of each non-degenerate cell's Jacobian at corner 0 (edges 0-1, 0-3, 0-4)."""
    signs = []
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        p = [mesh.GetPoint(ids.GetId(k)) for k in (0, 1, 3, 4)]
        a, b, d = ([p[k][i] - p[0][i] for i in range(3)] for k in (1, 2, 3))
        det = (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
               + a[2] * (b[0] * d[1] - b[1] * d[0]))
        if det != 0.0:
            signs.append(1 if det > 0 else -1)
    return signs
