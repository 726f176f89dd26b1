"""Isosurfaces of cell data: the faces between cells on either side of the value (a cell at exactly the
value counts as above it; the mesh boundary holds none), composited where a ray crosses the face and
lit with the face's normal.

- The reference draws them unlit; checked against independent methods on exactly those faces, found
  by brute force over every cell's faces: VTK's own polygon rendering (the colour of the first), and
  VTK's line-polygon intersection (how many each ray crosses, which sets a translucent one's alpha).
- Every mapper against the reference (unlit), with a translucent volume between translucent surfaces
  (the shell mapper draws them by cell projection, with one warning in shells mode); and lit, against
  the analytic Phong colour of a plane of faces.
Run by ctest under Xvfb with /usr/bin/python3."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402
import uvrender  # noqa: E402
from fixtures import (HexScene, Scene, SceneTestCase, analytic_hexahedra, camera_for, copy_image,  # noqa: E402
                      hex_dominant, load_shared, mean_cell_values, rmse, shared_window, OPEN_SCENES)

from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper,  # noqa: E402
                                vtkHexahedraToTetrahedra, vtkPreIntegratedTetrahedraMapper,
                                vtkUnstructuredVolumeReferenceRenderer)
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkGenericCell, vtkPolyData  # noqa: E402
from vtkmodules.vtkCommonMath import vtkMatrix4x4  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkFiltersFlowPaths import vtkModifiedBSPTree  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,  # noqa: E402
                                         vtkWindowToImageFilter)

SIZE = 96
ISOVALUE_FRACTIONS = (0.35, 0.6)
# Mappers against the reference, RMSE over the image: float arithmetic, and pixels whose centre
# passes within rounding of a face's edge. The tetrahedra mapper and cell projection decide per
# tetrahedron which face the ray enters by; where the ray passes within rounding of an edge that
# choice can take the face beside the one the reference crosses, whose neighbour lies on the same
# side of the value (a few pixels on the split hex-dominant mesh and on the jittered tetrahedra, by
# cell projection and by the tetrahedra mapper, whose default route finds the entry face the same
# way; MESH_BOUNDS).
MAPPER_BOUNDS = {"hexahedral": 2e-3, "preintegrated": 2e-3, "cell projection": 2e-3, "shells": 2e-3}
MESH_BOUNDS = {("hex_dominant", "preintegrated"): 5e-3, ("hex_dominant", "cell projection"): 5e-3,
               ("hex_dominant", "shells"): 5e-3, ("tetrahedra", "preintegrated"): 5e-3,
               ("tetrahedra", "cell projection"): 5e-3, ("tetrahedra", "shells"): 5e-3}
EVERY_MAPPER = ["hexahedral", "preintegrated", "cell projection", "shells"]


def wavy_cell_values(mesh):
    """A cell value that rises and falls several times across the mesh (sheets a ray crosses often)."""
    values = vtkDoubleArray()
    values.SetName("wavy")
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        x, y, z = [sum(mesh.GetPoint(ids.GetId(k))[a] for k in range(ids.GetNumberOfIds())) / ids.GetNumberOfIds()
                   for a in range(3)]
        values.InsertNextValue(math.sin(5 * x + 3 * y) * math.cos(4 * z))
    mesh.GetPointData().Initialize()
    mesh.GetCellData().SetScalars(values)
    return mesh


def isovalues(mesh):
    """Near quantiles of the cell values (a real field's range is often set by a few cells), each in
    the middle of the widest gap between consecutive values there: no cell within float rounding of
    it, where the tie rule would decide differently in float and in double."""
    scalars = mesh.GetCellData().GetScalars()
    values = sorted(set(scalars.GetValue(c) for c in range(scalars.GetNumberOfTuples())))
    chosen = []
    for f in ISOVALUE_FRACTIONS:
        near = int(f * (len(values) - 2))
        gaps = range(max(0, near - 10), min(len(values) - 1, near + 10))
        i = max(gaps, key=lambda k: values[k + 1] - values[k])
        chosen.append(0.5 * (values[i] + values[i + 1]))
    return chosen


def near_camera(mesh, azimuth=30.0, elevation=25.0):
    return camera_for(mesh, azimuth, elevation, distance=1.4)


def faces_between_cells(mesh, value):
    """Brute force: every face two cells share, whose cells lie on either side of `value`."""
    scalars = mesh.GetCellData().GetScalars()
    cell = vtkGenericCell()
    faces = {}
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCell(c, cell)
        for f in range(cell.GetNumberOfFaces()):
            ids = cell.GetFace(f).GetPointIds()
            corners = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
            faces.setdefault(tuple(sorted(set(corners))), []).append((c, corners))
    polygons = vtkCellArray()
    count = 0
    for sharing in faces.values():
        if len(sharing) != 2:
            continue
        (a, corners), (b, _) = sharing
        if (scalars.GetValue(a) < value) != (scalars.GetValue(b) < value):
            polygons.InsertNextCell(len(corners), corners)
            count += 1
    surface = vtkPolyData()
    surface.SetPoints(mesh.GetPoints())
    surface.SetPolys(polygons)
    return surface, count


def vtk_surface_image(surface, colour, camera):
    """The surface drawn opaque and unlit in `colour` by VTK's own polygon mapper: float RGB rows."""
    window = shared_window()
    for scene in OPEN_SCENES:
        window.RemoveRenderer(scene.renderer)
    renderer = vtkRenderer()
    renderer.SetBackground(0, 0, 0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(surface)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    actor.GetProperty().SetLighting(False)
    renderer.AddActor(actor)
    renderer.SetActiveCamera(camera)
    window.SetSize(SIZE, SIZE)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    window.RemoveRenderer(renderer)
    pixels = grab.GetOutput().GetPointData().GetScalars()
    return [[pixels.GetComponent(i, k) / 255.0 for k in range(3)] for i in range(SIZE * SIZE)]


def pixel_rays(camera):
    """Each pixel centre's ray as (near point, far point), the way the reference unprojects them."""
    matrix = vtkMatrix4x4()
    matrix.DeepCopy(camera.GetCompositeProjectionTransformMatrix(1.0, -1, 1))
    matrix.Invert()

    def unproject(x, y, z):
        p = matrix.MultiplyPoint((x, y, z, 1.0))
        return [p[i] / p[3] for i in range(3)]

    for i in range(SIZE * SIZE):
        x, y = ((i % SIZE) + 0.5) / SIZE * 2 - 1, ((i // SIZE) + 0.5) / SIZE * 2 - 1
        yield unproject(x, y, -1.0), unproject(x, y, 1.0)


def crossings_per_pixel(surface, camera):
    """How many faces each pixel's ray crosses: VTK's own line-polygon intersection (vtkModifiedBSPTree)."""
    triangles = vtkTriangleFilter()
    triangles.SetInputData(surface)
    triangles.Update()
    tree = vtkModifiedBSPTree()
    tree.SetDataSet(triangles.GetOutput())
    tree.BuildLocator()
    counts = []
    for near, far in pixel_rays(camera):
        points, cells = vtkPoints(), vtkIdList()
        tree.IntersectWithLine(near, far, 1e-9, points, cells)
        counts.append(cells.GetNumberOfIds())
    return counts


def surface_property(mesh, opacity_fraction=0.0):
    """Unlit (ambient 1): the surfaces show their colour. The volume is transparent, or a faint ramp."""
    low, high = mesh.GetCellData().GetScalars().GetRange()
    prop = uvrender.volume_property((low, high))
    prop.GetScalarOpacity().RemoveAllPoints()
    prop.GetScalarOpacity().AddPoint(low, 0.0)
    prop.GetScalarOpacity().AddPoint(high, opacity_fraction)
    prop.SetScalarOpacityUnitDistance(0.1 * mesh.GetLength())
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    return prop


SURFACE_COLOURS = ((1.0, 0.5, 0.1), (0.2, 0.6, 1.0))


def reference(mesh, prop, camera, surfaces):
    renderer = vtkUnstructuredVolumeReferenceRenderer()
    renderer.SetInputData(mesh)
    renderer.SetVolumeProperty(prop)
    renderer.SetCamera(camera)
    renderer.SetImageSize(SIZE, SIZE)
    for value, colour, opacity in surfaces:
        renderer.AddIsosurface(value, *colour, opacity)
    assert renderer.Render()
    return copy_image(renderer.GetOutput())


def split(mesh):
    """The mesh as vtkHexahedraToTetrahedra splits it (the cell data follows)."""
    tetrahedra = vtkHexahedraToTetrahedra()
    tetrahedra.SetInputData(mesh)
    tetrahedra.Update()
    return tetrahedra.GetOutput()


def rotated_hex_dominant():
    """hex_dominant on the 45-degree grid (its faces are planar, as VTK's polygon mapper draws them)."""
    return mean_cell_values(hex_dominant(6, distortion=vtkAnalyticMeshSource.ROTATE_45))


class ReferenceAgainstVTKPolygons(SceneTestCase):
    """One opaque surface over a transparent volume: the reference's colour at each pixel against VTK's
    rasterised faces between cells. Pixels whose centre lies within rounding of a face's edge may go
    either way: at most EDGE_SHARE of the covered pixels differ."""

    EDGE_SHARE = 0.02
    # Counting needs no colour at the edge pixels, and a reference that lost the faces between cells
    # meeting within rounding of each other (a pyramid's triangle, a tetrahedron's plane) differed at
    # some of them; none do now.
    CROSSING_SHARE = 0.001

    def check(self, mesh, value, camera):
        surface, count = faces_between_cells(mesh, value)
        self.assertGreater(count, 10)
        colour = SURFACE_COLOURS[0]
        expected = vtk_surface_image(surface, colour, camera)
        image = reference(mesh, surface_property(mesh), camera, [(value, colour, 1.0)])
        rgba = image.GetPointData().GetScalars()
        covered = sum(1 for p in expected if max(p) > 0)
        wrong = sum(1 for i in range(SIZE * SIZE)
                    if max(abs(a - b) for a, b in zip(rgba.GetTuple4(i)[:3], expected[i])) > 3 / 255)
        print(f"\n  {count} faces, {covered} pixels covered, {wrong} differ (bound {self.EDGE_SHARE:.0%})", end="")
        self.assertGreater(covered, SIZE * SIZE / 50)
        self.assertLessEqual(wrong, self.EDGE_SHARE * covered)

    def test_hex_dominant_mesh(self):
        mesh = rotated_hex_dominant()
        for value in isovalues(mesh):
            self.check(mesh, value, near_camera(mesh))

    def test_every_crossing_counts(self):
        """Translucent, every face the ray crosses shows: alpha 1 - (1 - opacity)^crossings. On the
        jittered mesh (its curved faces triangulated for VTK: rays between the two rarely)."""
        mesh = wavy_cell_values(hex_dominant(6))
        camera = near_camera(mesh)
        for value in isovalues(mesh):
            surface, _ = faces_between_cells(mesh, value)
            counts = crossings_per_pixel(surface, camera)
            image = reference(mesh, surface_property(mesh), camera, [(value, SURFACE_COLOURS[0], 0.5)])
            rgba = image.GetPointData().GetScalars()
            covered = sum(1 for n in counts if n > 0)
            several = sum(1 for n in counts if n > 1)
            wrong = sum(1 for i, n in enumerate(counts) if abs(rgba.GetTuple4(i)[3] - (1 - 0.5 ** n)) > 1e-3)
            print(f"\n  {covered} pixels covered, {several} by several faces, {wrong} differ "
                  f"(bound {self.CROSSING_SHARE:.1%})", end="")
            self.assertGreater(several, covered / 10)
            self.assertLessEqual(wrong, self.CROSSING_SHARE * covered)

    def test_openfoam_cavity(self):
        mesh = load_shared(self, shared_data.openfoam_cavity_cells)
        mesh.GetCellData().SetActiveScalars("p")
        for value in isovalues(mesh):
            self.check(mesh, value, near_camera(mesh, 10, 40))


class MappersAgainstReference(SceneTestCase):
    """Two translucent surfaces in a faint volume, unlit, each mapper against the reference."""

    def scene(self, kind, mesh, prop, camera, surfaces):
        if kind == "hexahedral":
            scene = HexScene(mesh, prop, camera, SIZE)
        elif kind == "preintegrated":
            scene = Scene(mesh, prop, camera, SIZE, mapper_class=vtkPreIntegratedTetrahedraMapper)
        else:
            mode = vtkBarycentricShellMapper.CELL_PROJECTION if kind == "cell projection" else vtkBarycentricShellMapper.SHELLS
            scene = Scene(mesh, prop, camera, SIZE, mapper_class=vtkBarycentricShellMapper, RenderMode=mode)
        for value, colour, opacity in surfaces:
            scene.mapper.AddIsosurface(value, *colour, opacity)
        return scene

    def check(self, name, mesh, kinds, camera):
        """The hexahedral mapper on the mesh itself; the tetrahedra mapper on the mesh split into
        tetrahedra, which is what it draws (on curved cells the split's flat faces move the faces
        between cells: that is the split's error, not the mapper's)."""
        prop = surface_property(mesh, 0.3)
        surfaces = [(v, c, 0.6) for v, c in zip(isovalues(mesh), SURFACE_COLOURS)]
        tetrahedra = split(mesh)
        for kind in kinds:
            drawn = mesh if kind == "hexahedral" else tetrahedra
            expected = reference(drawn, prop, camera, surfaces)
            self.assertGreater(rmse(expected, reference(drawn, prop, camera, []))[0], 0.02)  # the surfaces show
            scene = self.scene(kind, drawn, prop, camera, surfaces)
            image = scene.render()
            error, worst = rmse(image, expected)
            bound = MESH_BOUNDS.get((name, kind), MAPPER_BOUNDS[kind])
            print(f"\n  {kind}: RMSE {error:.3g} (bound {bound}), largest {worst:.3g}", end="")
            # The shells draw a cell scalar's surfaces by cell projection, and say so once.
            self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1 if kind == "shells" else 0), kind)
            self.assertLess(error, bound, kind)

    def test_hex_dominant_mesh(self):
        mesh = mean_cell_values(hex_dominant(6))
        self.check("hex_dominant", mesh, EVERY_MAPPER, near_camera(mesh))

    def test_tetrahedra(self):
        mesh = mean_cell_values(split(analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.JITTER)))
        self.check("tetrahedra", mesh, EVERY_MAPPER, near_camera(mesh))

    def test_openfoam_cavity(self):
        mesh = load_shared(self, shared_data.openfoam_cavity_cells)
        mesh.GetCellData().SetActiveScalars("p")
        self.check("openfoam_cavity", mesh, EVERY_MAPPER, near_camera(mesh, 10, 40))


class LitFaces(SceneTestCase):
    """Cells valued by their centre's x on a regular grid: the surface at 0 is the plane x = 0, made
    of faces between cells. Opaque and Phong-lit by the headlight under a parallel view, every pixel
    it covers has the analytic colour."""

    def test_plane_of_faces(self):
        mesh = analytic_hexahedra(4)
        values = vtkDoubleArray()
        values.SetName("x")
        ids = vtkIdList()
        for c in range(mesh.GetNumberOfCells()):
            mesh.GetCellPoints(c, ids)
            values.InsertNextValue(sum(mesh.GetPoint(ids.GetId(k))[0] for k in range(8)) / 8)
        mesh.GetPointData().Initialize()
        mesh.GetCellData().SetScalars(values)
        camera = camera_for(mesh, 30, 25, parallel=True)
        prop = surface_property(mesh)
        prop.SetAmbient(0.15)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.3)
        prop.SetSpecularPower(8)
        colour = (0.9, 0.6, 0.3)
        view = camera.GetDirectionOfProjection()
        lambert = abs(view[0])  # the plane's normal is x
        highlight = max(2 * lambert * lambert - 1, 0.0) ** 8
        expected = [c * (0.15 + 0.7 * lambert) + 0.3 * highlight for c in colour]
        projection = vtkBarycentricShellMapper()
        projection.SetRenderModeToCellProjection()
        for kind, drawn, mapper in (("hexahedral", mesh, None), ("preintegrated", split(mesh),
                                    vtkPreIntegratedTetrahedraMapper()), ("cell projection", split(mesh), projection)):
            scene = HexScene(drawn, prop, camera, SIZE, mapper=mapper)
            scene.mapper.AddIsosurface(0.0, *colour, 1.0)
            rgba = scene.render().GetPointData().GetScalars()
            covered = [rgba.GetTuple4(i) for i in range(SIZE * SIZE) if rgba.GetTuple4(i)[3] > 0.5]
            off = sum(1 for p in covered if max(abs(a - b) for a, b in zip(p[:3], expected)) > 2e-3)
            print(f"\n  {kind}: {len(covered)} pixels on the plane, {off} off the analytic colour", end="")
            self.assertEqual((scene.events.errors, scene.events.warnings), (0, 0), kind)
            self.assertGreater(len(covered), SIZE * SIZE / 10, kind)
            self.assertLessEqual(off, 0.01 * len(covered), kind)


if __name__ == "__main__":
    unittest.main()
