"""Broken meshes as files deliver them: point ids out of range, a cell with fewer or more ids than its
type has, NaN or infinite coordinates, polyhedra whose face streams are short or name missing
points, cell types VTK does not know. Each mapper, the reference and each filter gives an error (a
warning for an unknown cell type, which is left out) and draws or outputs nothing, with no crash, no
hang and no read outside the arrays (the sanitizer run includes this module)."""
import math
import os
import unittest

from fixtures import OUTPUT, Events, Scene, SceneTestCase, analytic, analytic_hexahedra, property_from_nodes

from unstructuredvolume import (vtkBarycentricShellMapper, vtkHexahedraToTetrahedra, vtkHexahedralRayCastMapper,
                                vtkPreIntegratedTetrahedraMapper, vtkUnstructuredVolumeReferenceRenderer,
                                vtkVertexGradientFilter)
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray, vtkPoints, vtkUnsignedCharArray, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkCamera

UNIT_CUBE = ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1), (0.5, 0.5, 2))
HEXAHEDRON, TETRA, POLYHEDRON = 12, 10, 42
# name: (cells as id lists, their VTK types).
BROKEN_FILES = {
    "id_past_the_points": ([[0, 1, 2, 3, 4, 5, 6, 1000]], [HEXAHEDRON]),
    "negative_id": ([[0, 1, 2, 3, 4, 5, 6, -5]], [HEXAHEDRON]),
    "far_id_after_a_sound_cell": ([[4, 5, 6, 8], [0, 1, 3, 4000000]], [TETRA, TETRA]),
    "hexahedron_with_four_ids": ([[0, 1, 2, 3], [4, 5, 6, 8]], [HEXAHEDRON, TETRA]),
    "tetrahedron_with_eight_ids": ([[0, 1, 2, 3, 4, 5, 6, 7]], [TETRA]),
}
# A polyhedron (point ids, face stream) whose fourth face names a point that does not exist: read
# from a .vtu file (VTK's legacy reader itself crashes on some broken polyhedra).
POLYHEDRON_NAMING_A_MISSING_POINT = ([0, 1, 3, 4], [4, 3, 0, 1, 3, 3, 0, 1, 4, 3, 1, 3, 4, 3, 0, 3, 400])


def write_legacy(name, cells, types):
    """A legacy ASCII .vtk file of the cube's points and these cells, with a point scalar."""
    lines = ["# vtk DataFile Version 4.2", name, "ASCII", "DATASET UNSTRUCTURED_GRID",
             f"POINTS {len(UNIT_CUBE)} double"]
    lines += [" ".join(map(str, p)) for p in UNIT_CUBE]
    lines += [f"CELLS {len(cells)} {sum(len(c) + 1 for c in cells)}"]
    lines += [" ".join(map(str, [len(c)] + list(c))) for c in cells]
    lines += [f"CELL_TYPES {len(types)}"] + [str(t) for t in types]
    lines += [f"POINT_DATA {len(UNIT_CUBE)}", "SCALARS s double 1", "LOOKUP_TABLE default"]
    lines += [str(0.1 * i) for i in range(len(UNIT_CUBE))]
    path = os.path.join(OUTPUT, f"broken_input_{name}.vtk")
    with open(path, "w") as stream:
        stream.write("\n".join(lines) + "\n")
    return path


def read(name, cells, types):
    reader = vtkUnstructuredGridReader()
    reader.SetFileName(write_legacy(name, cells, types))
    reader.Update()
    mesh = reader.GetOutput()
    assert mesh.GetNumberOfCells() == len(cells), f"the reader dropped cells of {name}"
    return mesh


def read_polyhedron(name, ids, faces):
    """A .vtu file of the cube's points and one polyhedron, with a point scalar."""
    def values(numbers):
        return " ".join(map(str, numbers))
    text = f"""<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints="{len(UNIT_CUBE)}" NumberOfCells="1">
<PointData Scalars="s"><DataArray type="Float64" Name="s" format="ascii">
{values(0.1 * i for i in range(len(UNIT_CUBE)))}</DataArray></PointData>
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">
{values(x for p in UNIT_CUBE for x in p)}</DataArray></Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">{values(ids)}</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">{len(ids)}</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">{POLYHEDRON}</DataArray>
<DataArray type="Int64" Name="faces" format="ascii">{values(faces)}</DataArray>
<DataArray type="Int64" Name="faceoffsets" format="ascii">{len(faces)}</DataArray>
</Cells></Piece></UnstructuredGrid></VTKFile>
"""
    path = os.path.join(OUTPUT, f"broken_input_{name}.vtu")
    with open(path, "w") as stream:
        stream.write(text)
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    assert mesh.GetNumberOfCells() == 1, f"the reader dropped the polyhedron of {name}"
    return mesh


def polyhedron_with_a_short_face_stream():
    """A polyhedron whose stream promises five faces and holds two (VTK's own polyhedron functions read
    on past its end: the reference hung, growing to gigabytes), built as VTK 9.1 to 9.3 let a reader
    build it (from 9.4 faces are cell arrays, whose streams cannot be short): None there."""
    grid = vtkUnstructuredGrid()
    if not hasattr(grid, "GetFaceLocations") or vtkVersion.GetVTKMajorVersion() * 100 + vtkVersion.GetVTKMinorVersion() >= 904:
        return None
    points = vtkPoints()
    for p in UNIT_CUBE:
        points.InsertNextPoint(*p)
    grid.SetPoints(points)
    cells = vtkCellArray()
    cells.InsertNextCell(8, list(range(8)))
    types = vtkUnsignedCharArray()
    types.InsertNextValue(POLYHEDRON)
    locations, faces = vtkIdTypeArray(), vtkIdTypeArray()
    locations.InsertNextValue(0)
    for value in (5, 4, 0, 1, 2, 3, 4, 4, 5, 6, 7):
        faces.InsertNextValue(value)
    grid.SetCells(types, cells, locations, faces)
    values = vtkDoubleArray()
    for i in range(len(UNIT_CUBE)):
        values.InsertNextValue(0.1 * i)
    grid.GetPointData().SetScalars(values)
    return grid


def with_point(mesh, value):
    mesh.GetPoints().SetPoint(5, value, 0.2, 0.1)
    mesh.GetPoints().Modified()
    return mesh


def camera():
    view = vtkCamera()
    view.SetPosition(3, 2, 4)
    view.SetFocalPoint(0.5, 0.5, 0.5)
    view.SetClippingRange(0.1, 20)
    return view


PROPERTY = property_from_nodes(((0, 0.0), (1, 0.8)), ((0, (1, 0, 0)), (1, (0, 0, 1))), 1.0)
MAPPERS = {"tetrahedra": vtkPreIntegratedTetrahedraMapper, "shells": vtkBarycentricShellMapper,
           "hexahedral": vtkHexahedralRayCastMapper}


class BrokenInputTests(SceneTestCase):
    def assert_refused_by_the_reference(self, mesh):
        reference = vtkUnstructuredVolumeReferenceRenderer()
        events = Events(reference)
        reference.SetInputData(mesh)
        reference.SetVolumeProperty(PROPERTY)
        reference.SetCamera(camera())
        reference.SetImageSize(24, 24)
        self.assertFalse(reference.Render())
        self.assertEqual(events.errors, 1)

    def assert_refused_everywhere(self, mesh, label):
        """Every mapper (two frames), the reference and both filters: an error, nothing drawn."""
        for name, mapper_class in MAPPERS.items():
            with self.subTest(label, mapper=name):
                scene = Scene(mesh, PROPERTY, camera(), 24, mapper=mapper_class())
                for frame in range(2):
                    alpha = scene.render().GetPointData().GetScalars().GetRange(3)
                    self.assertEqual(alpha, (0.0, 0.0), f"frame {frame}")
                self.assertEqual(scene.events.errors, 2)  # one a frame: the mesh stays broken
                self.assertEqual(scene.window_events.errors, 0)
        with self.subTest(label, mapper="reference"):
            self.assert_refused_by_the_reference(mesh)
        for filter_class in (vtkHexahedraToTetrahedra, vtkVertexGradientFilter):
            with self.subTest(label, filter=filter_class.__name__):
                algorithm = filter_class()
                events = Events(algorithm)
                algorithm.SetInputData(mesh)
                algorithm.Update()
                self.assertEqual(events.errors, 1)
                self.assertEqual(algorithm.GetOutput().GetNumberOfCells(), 0)

    def test_broken_cells_from_files(self):
        for name, (cells, types) in BROKEN_FILES.items():
            self.assert_refused_everywhere(read(name, cells, types), name)

    def test_broken_polyhedra(self):
        self.assert_refused_everywhere(read_polyhedron("polyhedron_naming_a_missing_point",
                                                       *POLYHEDRON_NAMING_A_MISSING_POINT), "missing point")
        short = polyhedron_with_a_short_face_stream()
        if short is not None:
            self.assert_refused_everywhere(short, "short face stream")

    def test_non_finite_coordinates(self):
        # The filters only read ids, so they pass non-finite points on; a renderer cannot place them.
        for value in (math.nan, math.inf, -math.inf):
            for mesh in (with_point(analytic(3), value), with_point(analytic_hexahedra(3), value)):
                label = f"{value} in a {mesh.GetCell(0).GetClassName()} mesh"
                for name, mapper_class in MAPPERS.items():
                    with self.subTest(label, mapper=name):
                        scene = Scene(mesh, PROPERTY, camera(), 24, mapper=mapper_class())
                        alpha = scene.render().GetPointData().GetScalars().GetRange(3)
                        self.assertEqual(alpha, (0.0, 0.0))
                        self.assertEqual(scene.events.errors, 1)
                with self.subTest(label, mapper="reference"):
                    self.assert_refused_by_the_reference(mesh)

    def test_a_repaired_mesh_draws_again(self):
        # The check runs whenever cells or points change, and an error is not remembered as a build.
        mesh = with_point(analytic_hexahedra(3), math.nan)
        for name, mapper_class in MAPPERS.items():
            with self.subTest(mapper=name):
                scene = Scene(mesh, PROPERTY, camera(), 24, mapper=mapper_class())
                self.assertEqual(scene.render().GetPointData().GetScalars().GetRange(3), (0.0, 0.0))
                with_point(mesh, 0.2)
                self.assertGreater(scene.render().GetPointData().GetScalars().GetRange(3)[1], 0.05)
                self.assertEqual(scene.events.errors, 1)
                with_point(mesh, math.nan)

    def test_unknown_cell_types_are_left_out_with_a_warning(self):
        # A type number VTK does not know: that cell is left out, the rest drawn.
        mesh = read("unknown_type", [[0, 1, 2, 3, 4, 5, 6, 7], [4, 5, 6, 8]], [99, TETRA])
        for name, mapper_class in MAPPERS.items():
            with self.subTest(mapper=name):
                scene = Scene(mesh, PROPERTY, camera(), 24, mapper=mapper_class())
                self.assertGreater(scene.render().GetPointData().GetScalars().GetRange(3)[1], 0.05)
                self.assertEqual(scene.events.errors, 0)
                self.assertEqual(scene.events.warnings, 1)


if __name__ == "__main__":
    unittest.main()
