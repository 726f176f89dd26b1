"""vtkHexahedralRayCastMapper: the paper's single-hexahedron test, accuracy against the reference on
generated grids, baselines, bad input and stress cases. Run by ctest under Xvfb with /usr/bin/python3."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(1, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Stress"))
import shared_data  # noqa: E402
import stress  # noqa: E402  (its generated degenerate meshes and placements)
import corner_point  # noqa: E402
import uvrender  # noqa: E402
from fixtures import (BaselineTestCase, HexScene, Scene, SceneTestCase, analytic, analytic_hexahedra, as_polyhedra,  # noqa: E402
                      camera_for, check_geometry_shown_later, copy_image, covered_colour_error, finite_image, folded_slab, hex_dominant, inside_camera,
                      largest_difference,
                      load_shared, plane_scene_setup, property_from_nodes, reference, rmse, statistic,
                      thin_shell_property, transparent_property)

from unstructuredvolume import (vtkAnalyticMeshSource, vtkHexahedraToTetrahedra,  # noqa: E402
                                vtkHexahedralRayCastMapper, vtkPreIntegratedTetrahedraMapper,
                                vtkVolumeImageErrorMetrics)
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_LINE, VTK_PYRAMID, VTK_QUAD,  # noqa: E402
                                           VTK_TETRA, VTK_VERTEX, VTK_VOXEL, VTK_WEDGE, vtkStructuredGrid,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkPointDataToCellData, vtkThreshold  # noqa: E402
from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkCamera  # noqa: E402


def single_hexahedron(values, shear=0.0, rotate=0.0):
    """One hexahedron: the unit cube sheared in x by z and rotated about z, with corner values."""
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    c, s = math.cos(rotate), math.sin(rotate)
    for x, y, z in ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)):
        x, y, z = x - 0.5 + shear * (z - 0.5), y - 0.5, z - 0.5
        points.InsertNextPoint(c * x - s * y, s * x + c * y, z)
    grid.SetPoints(points)
    grid.InsertNextCell(VTK_HEXAHEDRON, 8, list(range(8)))
    array = vtkDoubleArray()
    array.SetName("f")
    for v in values:
        array.InsertNextValue(v)
    grid.GetPointData().SetScalars(array)
    return grid


def six_spikes(unit):
    """The paper's transfer function: six thin spikes over [0, 1]."""
    palette = ((1, 0.2, 0.2), (1, 0.7, 0.1), (0.3, 1, 0.3), (0.2, 0.8, 1), (0.4, 0.3, 1), (1, 0.3, 0.9))
    opacity, colors = [(0.0, 0.0)], [(0.0, (0.5, 0.5, 0.5))]
    for k, rgb in enumerate(palette):
        centre = (k + 1) / 7.0
        opacity += [(centre - 0.01, 0.0), (centre, 0.9), (centre + 0.01, 0.0)]
        colors.append((centre, rgb))
    opacity.append((1.0, 0.0))
    colors.append((1.0, (0.5, 0.5, 0.5)))
    return property_from_nodes(opacity, colors, unit)


class SingleHexahedronTests(SceneTestCase):
    def test_six_spikes_accurate_against_splits(self):
        # The paper's test: one hexahedron, six thin spikes. The exact cubic matches the reference;
        # splitting into 5 or 6 tetrahedra replaces the trilinear field by piecewise-linear ones.
        values = [0.05, 0.9, 0.35, 0.6, 0.75, 0.15, 1.0, 0.4]
        mesh = single_hexahedron(values, shear=0.2, rotate=0.5)
        prop = six_spikes(0.3)
        camera = camera_for(mesh, 35, 25, distance=1.5)
        expected = reference(mesh, prop, camera, 128)
        accurate, worst = rmse(HexScene(mesh, prop, camera).render(), expected)
        errors = {}
        # The five-tetrahedra split needs structured input: the same cell as a 2x2x2 structured grid.
        structured = vtkStructuredGrid()
        structured.SetDimensions(2, 2, 2)
        points = vtkPoints()
        for k in (0, 1, 3, 2, 4, 5, 7, 6):
            points.InsertNextPoint(mesh.GetPoint(k))
        structured.SetPoints(points)
        values_array = vtkDoubleArray()
        values_array.SetName("f")
        for k in (0, 1, 3, 2, 4, 5, 7, 6):
            values_array.InsertNextValue(values[k])
        structured.GetPointData().SetScalars(values_array)
        for label, mode, source in (("six", 0, mesh), ("five", 1, structured)):
            split = vtkHexahedraToTetrahedra()
            split.SetInputData(source)
            split.SetSplitMode(mode)
            split.Update()
            tets = split.GetOutput()
            self.assertEqual(tets.GetNumberOfCells(), 6 if label == "six" else 5)
            scene = HexScene(tets, prop, camera, mapper=vtkPreIntegratedTetrahedraMapper())
            errors[label] = rmse(scene.render(), expected)[0]
        fast = rmse(HexScene(mesh, prop, camera, IntegrationMode=1).render(), expected)[0]
        steps = rmse(HexScene(mesh, prop, camera, IntegrationMode=2).render(), expected)[0]
        print(f"\n  accurate {accurate:.3g} (max {worst:.3g}); fast {fast:.3g}; 8 fixed steps {steps:.3g}; "
              f"6-tet split {errors['six']:.3g}; 5-tet split {errors['five']:.3g}", end="")
        self.assertLess(accurate, 2e-4)
        self.assertGreater(errors["six"], 10 * accurate)
        self.assertGreater(errors["five"], 10 * accurate)


class AccuracyTests(SceneTestCase):
    def check(self, mesh, prop, camera, bound, size=128, **settings):
        scene = HexScene(mesh, prop, camera, size, **settings)
        return self.assert_near_reference(scene, mesh, prop, camera, size, bound)[0]

    def test_regular_grid(self):
        # Boxes: the frame is exact. The bound is for one pixel whose ray passes through mesh
        # vertices and loses part of its walk; every other pixel is far closer.
        mesh = analytic_hexahedra(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, camera_for(mesh), 2e-3)

    def test_rotated_45_degrees(self):
        # The grid the paper's world-space fit cannot handle (its 8x8 system is singular).
        mesh = analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.ROTATE_45)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, camera_for(mesh, 20, 30), 2e-3)

    def test_twisted_grid(self):
        # Curved cells: exact bilinear faces; along each segment the cubic through the exact field at
        # its ends and two inner points; the largest errors are at silhouettes. The frame alone does
        # worse, as did the frame's cubic between exact ends.
        mesh = analytic_hexahedra(6, distortion=vtkAnalyticMeshSource.TWIST)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        exact = self.check(mesh, prop, camera_for(mesh), 5e-4)
        frame_only = self.check(mesh, prop, camera_for(mesh), 2e-2, ExactSegmentEnds=False)
        self.assertLess(exact, 0.85 * frame_only)

    def test_camera_inside_the_mesh(self):
        mesh = analytic_hexahedra(5)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, inside_camera(), 5e-3, size=96)

    def test_near_plane_inside_the_mesh_with_the_eye_outside(self):
        # The eye just outside a boundary face (or on it), the near plane beyond it: no entry face is
        # left in front of the rays, which start at their near-plane points (found by walking from
        # the cell holding the near plane's centre), as the reference's do. Also parallel rays whose
        # near plane cuts the mesh. The mapper drew nothing here before.
        mesh = analytic_hexahedra(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for x, parallel in ((-1.005, False), (-1.0, False), (-1.3, True)):
            with self.subTest(x=x, parallel=parallel):
                camera = vtkCamera()
                camera.SetPosition(x, 0.013, 0.021)
                camera.SetFocalPoint(1.0, 0.013, 0.021)
                camera.SetViewUp(0, 0, 1)
                camera.SetViewAngle(60)
                camera.SetParallelProjection(parallel)
                camera.SetParallelScale(0.8)
                camera.SetClippingRange(0.5 if parallel else 0.01, 10)
                self.check(mesh, prop, camera, 5e-3, size=64)


class MixedCellTests(SceneTestCase):
    """Tetrahedra, pyramids and wedges walk with the hexahedra, as hexahedra with repeated corners."""

    def check(self, mesh, camera, bound, size=96, **settings):
        scalars = mesh.GetPointData().GetScalars() or mesh.GetCellData().GetScalars()
        prop = uvrender.volume_property(scalars.GetRange())
        prop.SetScalarOpacityUnitDistance(0.3)
        scene = HexScene(mesh, prop, camera, size, **settings)
        image = self.assert_near_reference(scene, mesh, prop, camera, size, bound)[1]
        self.assertEqual(statistic(scene.mapper, "Cells"), mesh.GetNumberOfCells())
        return image

    def test_hex_dominant_mesh(self):
        mesh = hex_dominant(6)
        kinds = {}
        for c in range(mesh.GetNumberOfCells()):
            kinds[mesh.GetCellType(c)] = kinds.get(mesh.GetCellType(c), 0) + 1
        self.assertEqual(kinds, {VTK_WEDGE: 2 * 2 * 36, VTK_HEXAHEDRON: 4 * 36 - 2, VTK_PYRAMID: 10, VTK_TETRA: 4})
        self.check(mesh, camera_for(mesh), 2e-3)
        self.check(mesh, camera_for(mesh, 200, -30), 2e-3)  # from the wedges' side

    def test_cell_data(self):
        mesh = hex_dominant(5)
        values = vtkDoubleArray()
        values.SetName("mean")
        for c in range(mesh.GetNumberOfCells()):
            ids = mesh.GetCell(c).GetPointIds()
            point_values = [mesh.GetPointData().GetScalars().GetValue(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]
            values.InsertNextValue(sum(point_values) / len(point_values))
        mesh.GetPointData().Initialize()
        mesh.GetCellData().SetScalars(values)
        self.check(mesh, camera_for(mesh), 2e-3)

    def test_dense_voxels_with_cell_data_in_pieces(self):
        # Voxels with cell data in pieces that each hold their own points, as a partitioned .pvtu
        # reads, in a medium where most rays saturate: the blood-flow case of issue 44. Its error was
        # early termination: the caster's default threshold of 0.99 left up to a hundredth of each
        # saturated pixel's light behind, where the tetrahedra mapper's 0.999 leaves a thousandth.
        source = vtkRTAnalyticSource()
        source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
        cells = vtkPointDataToCellData()
        cells.SetInputConnection(source.GetOutputPort())
        cells.PassPointDataOff()
        append = vtkAppendFilter()
        append.MergePointsOff()
        for k in range(4):
            slab = vtkExtractVOI()
            slab.SetInputConnection(cells.GetOutputPort())
            slab.SetVOI(-10 + 5 * k, -5 + 5 * k, -10, 10, -10, 10)
            above = vtkThreshold()
            above.SetInputConnection(slab.GetOutputPort())
            above.SetInputArrayToProcess(0, 0, 0, 1, "RTData")
            above.SetLowerThreshold(150.0)
            above.SetUpperThreshold(1e9)
            above.Update()
            append.AddInputData(above.GetOutput())
        append.Update()
        mesh = append.GetOutput()
        mesh.GetCellData().SetActiveScalars("RTData")
        self.assertEqual({mesh.GetCellType(c) for c in range(mesh.GetNumberOfCells())}, {VTK_VOXEL})
        self.check(mesh, camera_for(mesh, 30, 25, distance=1.6), 4e-4, size=128)

    def jittered_tetrahedra(self):
        split = vtkHexahedraToTetrahedra()
        split.SetInputData(analytic_hexahedra(4, distortion=vtkAnalyticMeshSource.JITTER))
        split.Update()
        return split.GetOutput()

    def test_tetrahedra_alone(self):
        """The walk itself on tetrahedra (they also come in mixed meshes)."""
        mesh = self.jittered_tetrahedra()
        self.check(mesh, camera_for(mesh), 2e-3, DelegateTetrahedralMeshes=False)

    def test_tetrahedra_alone_are_handed_over(self):
        """A mesh of tetrahedra alone is drawn by the tetrahedra mapper, with this mapper's settings:
        the same image as that mapper's own, bit for bit; its warnings reach this mapper's observers."""
        mesh = self.jittered_tetrahedra()
        scalars = mesh.GetPointData().GetScalars()
        prop = uvrender.volume_property(scalars.GetRange())
        prop.SetScalarOpacityUnitDistance(0.3)
        camera = camera_for(mesh)
        scene = HexScene(mesh, prop, camera, 96)
        scene.mapper.AddIsosurface(sum(scalars.GetRange()) / 2, 1.0, 0.8, 0.2, 0.5)
        scene.mapper.SetGradientModeToVertexGradients()
        image = copy_image(scene.render())
        self.assertTrue(statistic(scene.mapper, "Delegated"))
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        for counter in ("Cells", "VisibleCells", "EntryFaces", "BoundaryFaces", "Peels", "TangledCells"):
            self.assertEqual(statistic(scene.mapper, counter), 0)  # this walk drew nothing
        self.assertGreater(scene.mapper.GetMeshMemoryInBytes(), 0)  # the other mapper's mesh
        own = Scene(mesh, prop, camera, 96)
        own.mapper.AddIsosurface(sum(scalars.GetRange()) / 2, 1.0, 0.8, 0.2, 0.5)
        self.assertEqual(rmse(image, own.render())[1], 0.0)
        # Lit by the cells' own gradients, the surfaces stay with this walk.
        scene.mapper.SetGradientModeToCellGradients()
        scene.render()
        self.assertFalse(statistic(scene.mapper, "Delegated"))
        # A NaN leaves cells out with a warning, which reaches this mapper.
        scene.mapper.RemoveAllIsosurfaces()
        scalars.SetValue(0, float("nan"))
        scalars.Modified()
        scene.render()
        self.assertTrue(statistic(scene.mapper, "Delegated"))
        self.assertEqual(scene.events.warnings, 1)

    def test_camera_inside(self):
        self.check(hex_dominant(5), inside_camera(), 5e-3)

    def test_no_ray_lost_on_a_larger_mesh(self):
        # Relocating a ray that passes within rounding of an edge: through wedges and pyramids by
        # their faces' planes (their inverse map is singular at the collapsed edge or apex). Newton
        # there lost the rest of one ray in this view.
        mesh = hex_dominant(24)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
        camera = vtkCamera()  # the benchmark's first orbit view
        camera.SetPosition(1.9 * mesh.GetLength() * math.cos(0.35), 0, 1.9 * mesh.GetLength() * math.sin(0.35))
        camera.SetFocalPoint(0, 0, 0)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(30)
        camera.SetClippingRange(0.9 * mesh.GetLength(), 2.9 * mesh.GetLength())
        scene = HexScene(mesh, prop, camera, 128)
        image = scene.render()
        expected = reference(mesh, prop, camera, 128)
        a, b = image.GetPointData().GetScalars(), expected.GetPointData().GetScalars()
        # Early termination at opacity 0.999 leaves up to 0.001 behind: only larger errors count.
        worst = max(max(abs(x - y) for x, y in zip(a.GetTuple4(i), b.GetTuple4(i))) for i in range(128 * 128))
        print(f"\n  largest error {worst:.3g}", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(worst, 0.05)

    def test_flat_cells_are_left_out_with_one_warning(self):
        mesh = hex_dominant(4)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        without = HexScene(mesh, prop, camera, 64).render()
        with_flat = vtkUnstructuredGrid()
        with_flat.DeepCopy(mesh)
        with_flat.InsertNextCell(VTK_QUAD, 4, [0, 1, 6, 5])
        with_flat.InsertNextCell(VTK_LINE, 2, [0, 7])
        with_flat.InsertNextCell(VTK_VERTEX, 1, [3])
        scene = HexScene(with_flat, prop, camera, 64)
        image = scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))
        self.assertEqual(rmse(image, without)[1], 0.0)


class OpaqueGeometryTests(SceneTestCase):
    def test_geometry_shown_later_cuts_the_volume_and_hidden_again_does_not(self):
        # The traversal reads the scene's depth every frame: copied where a prop may have drawn some,
        # cleared to the far plane where none did (after a copy, too).
        check_geometry_shown_later(self, mapper_class=vtkHexahedralRayCastMapper)


class IsosurfaceTests(SceneTestCase):
    def test_position_against_an_opaque_shell_in_the_reference(self):
        # An unlit opaque isosurface is the limit of a thin, very opaque shell of the transfer
        # function around the isovalue: the reference renders that shell. Curved cells (twist), so
        # the surface is the trilinear field's, cell by cell. Only rays grazing the surface (the
        # shell's rim) may differ.
        mesh = analytic_hexahedra(6, distortion=vtkAnalyticMeshSource.TWIST)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        value = low + 0.55 * (high - low)
        color = (0.9, 0.6, 0.2)
        camera = camera_for(mesh, 35, 20, distance=1.5)
        expected = reference(mesh, thin_shell_property(low, high, value, color, mesh.GetLength()), camera, 128)
        scene = HexScene(mesh, transparent_property(color), camera)
        scene.mapper.AddIsosurface(value, *color, 1.0)
        image = scene.render()
        metrics = vtkVolumeImageErrorMetrics()
        metrics.SetChannels(4)
        self.assertTrue(metrics.Compare(image, expected))
        print(f"\n  RMSE {metrics.GetRMSE():.3g}, 99th percentile {metrics.GetPercentile99Error():.3g}, "
              f"{metrics.GetNumberOfCoveredPixels()} covered pixels", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertGreater(metrics.GetNumberOfCoveredPixels(), 1500)
        self.assertLess(metrics.GetRMSE(), 0.02)  # a few rim pixels at the silhouette
        self.assertLess(metrics.GetPercentile99Error(), 1e-3)
        # Without the isosurface the image is empty: the cells it runs through are not skipped.
        scene.mapper.RemoveAllIsosurfaces()
        self.assertEqual(scene.render().GetPointData().GetScalars().GetRange(3), (0.0, 0.0))

    def test_exact_phong_on_a_plane_in_twisted_cells(self):
        # A linear field of position is trilinear in every cell, curved ones too: its isosurface is a
        # plane with one normal, so under a parallel headlight every covered pixel has the same
        # analytic Phong colour. Twisted (non-orthogonal) cells check the gradient's J^-T.
        mesh = analytic_hexahedra(4, distortion=vtkAnalyticMeshSource.TWIST)
        camera = camera_for(mesh, 30, 25, parallel=True)
        color = (0.2, 0.6, 1.0)
        prop, expected = plane_scene_setup(mesh, camera, color)
        scene = HexScene(mesh, prop, camera)
        scene.mapper.AddIsosurface(0.1, *color, 1.0)
        covered, worst = covered_colour_error(scene.render(), expected)
        print(f"\n  {covered} covered pixels, worst colour error {worst:.3g}", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertGreater(covered, 2000)
        self.assertLess(worst, 2e-3)

    def test_every_mode_draws_the_surface(self):
        mesh = analytic_hexahedra(5)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        camera = camera_for(mesh)
        images = []
        for mode in (0, 1, 2):
            scene = HexScene(mesh, transparent_property(), camera, 64, IntegrationMode=mode)
            scene.mapper.AddIsosurface(low + 0.5 * (high - low), 0.9, 0.6, 0.2, 0.8)
            images.append(scene.render())
        for image in images[1:]:
            self.assertLess(rmse(image, images[0])[0], 1e-3)
        self.assertGreater(images[0].GetPointData().GetScalars().GetRange(3)[1], 0.79)


SPHERE_RADIUS = 0.75


def sphere_mesh(resolution, analytic_gradients=False):
    """[-1, 1]^3 in resolution^3 hexahedra with the scalar |x|, whose isosurfaces are spheres about the
    origin; with `analytic_gradients` also its exact gradient x / |x| as the point array "Gradients"."""
    mesh = analytic_hexahedra(resolution)
    radius, gradients = vtkDoubleArray(), vtkDoubleArray()
    radius.SetName("radius")
    gradients.SetName("Gradients")
    gradients.SetNumberOfComponents(3)
    for i in range(mesh.GetNumberOfPoints()):
        x = mesh.GetPoint(i)
        length = math.sqrt(sum(c * c for c in x))
        radius.InsertNextValue(length)
        gradients.InsertNextTuple3(*(c / length if length > 0 else 0.0 for c in x))
    mesh.GetPointData().SetScalars(radius)
    if analytic_gradients:
        mesh.GetPointData().AddArray(gradients)
    return mesh


def sphere_camera():
    """An oblique parallel view of the origin, the sphere filling most of it (the renderer's own
    headlight then shines along the view)."""
    camera = vtkCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(1.5, -5.0, 2.2)
    camera.SetViewUp(0, 0, 1)
    camera.OrthogonalizeViewUp()
    camera.SetParallelProjection(True)
    camera.SetParallelScale(0.85)
    camera.SetClippingRange(0.1, 20)
    return camera


def diffuse_white_property():
    """A transparent volume whose isosurfaces reflect diffusely alone: a white surface's colour is then
    cos(angle between its normal and a headlight), nothing else."""
    prop = transparent_property((1.0, 1.0, 1.0))
    prop.SetAmbient(0.0)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(0.0)
    return prop


def trilinear_radius(x, resolution):
    """The trilinear interpolant of |x| on the lattice of sphere_mesh(resolution) at x: the field the
    mapper renders, so its isosurface is the surface the rays hit."""
    h = 2.0 / resolution
    cell, local = [], []
    for c in x:
        i = min(max(int((c + 1.0) / h), 0), resolution - 1)
        cell.append(i)
        local.append((c + 1.0) / h - i)
    value = 0.0
    for a in (0, 1):
        for b in (0, 1):
            for d in (0, 1):
                corner = (-1.0 + h * (cell[0] + a), -1.0 + h * (cell[1] + b), -1.0 + h * (cell[2] + d))
                weight = ((local[0] if a else 1 - local[0]) * (local[1] if b else 1 - local[1]) *
                          (local[2] if d else 1 - local[2]))
                value += weight * math.sqrt(sum(c * c for c in corner))
    return value


def first_crossing(origin, direction, near, far, resolution):
    """Where the ray origin + t direction crosses the isosurface of trilinear_radius at SPHERE_RADIUS
    between t = near (outside it) and far (inside), by bisection."""
    def along(t):
        return [p + t * d for p, d in zip(origin, direction)]
    assert trilinear_radius(along(near), resolution) > SPHERE_RADIUS > trilinear_radius(along(far), resolution)
    for _ in range(30):
        middle = 0.5 * (near + far)
        if trilinear_radius(along(middle), resolution) > SPHERE_RADIUS:
            near = middle
        else:
            far = middle
    return along(0.5 * (near + far))


def sphere_hits(camera, size, resolution, inside=0.9):
    """{pixel index: Lambert term the analytic normal gives} for the pixels of a size x size image whose
    ray meets the sphere within `inside` of its silhouette's radius (away from grazing rays): each
    ray's first crossing of the rendered (trilinear) isosurface is found (first_crossing), and the
    analytic normal there, x / |x|, is dotted with the headlight's direction, the view's. Also the
    pixels well outside the silhouette, which must stay empty."""
    view = camera.GetDirectionOfProjection()
    up = camera.GetViewUp()
    right = (view[1] * up[2] - view[2] * up[1], view[2] * up[0] - view[0] * up[2], view[0] * up[1] - view[1] * up[0])
    scale = camera.GetParallelScale()
    hits, outside = {}, []
    for j in range(size):
        for i in range(size):
            u, v = ((i + 0.5) / size * 2 - 1) * scale, ((j + 0.5) / size * 2 - 1) * scale
            plane = [u * r + v * w for r, w in zip(right, up)]  # the ray's point in the focal plane
            offset = math.sqrt(u * u + v * v) / SPHERE_RADIUS
            if offset > 1.1:
                outside.append(i + size * j)
            if offset >= inside:
                continue
            depth = math.sqrt(SPHERE_RADIUS ** 2 - (u * u + v * v))  # the exact sphere's, a bracket's centre
            x = first_crossing(plane, view, -depth - 0.15, -depth + 0.15, resolution)
            hits[i + size * j] = abs(sum(c * d for c, d in zip(x, view))) / math.sqrt(sum(c * c for c in x))
    return hits, outside


class SmoothIsosurfaceTests(SceneTestCase):
    """GradientMode on a sphere (|x| on coarse hexahedra, an opaque isosurface, one headlight): the
    shading against the analytic normal at each ray's hit."""

    RESOLUTION, SIZE = 6, 80  # cells almost half the sphere's radius across, about 16 pixels each

    def shading_error(self, mesh, hits, outside, mode):
        """(RMS, maximum) of |rendered - analytic Lambert| over `hits`, and the scene."""
        scene = HexScene(mesh, diffuse_white_property(), sphere_camera(), self.SIZE, GradientMode=mode)
        scene.mapper.AddIsosurface(SPHERE_RADIUS, 1.0, 1.0, 1.0, 1.0)
        rgba = scene.render().GetPointData().GetScalars()
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        self.assertTrue(all(rgba.GetTuple4(p)[3] > 0.999 for p in hits), "a ray inside the sphere missed it")
        self.assertTrue(all(rgba.GetTuple4(p)[3] == 0.0 for p in outside), "a ray outside the sphere met it")
        errors = [rgba.GetTuple4(p)[0] - lambert for p, lambert in hits.items()]
        return math.sqrt(sum(e * e for e in errors) / len(errors)), max(abs(e) for e in errors), scene

    def test_vertex_gradients_light_a_sphere_smoothly(self):
        mesh = sphere_mesh(self.RESOLUTION)
        hits, outside = sphere_hits(sphere_camera(), self.SIZE, self.RESOLUTION)
        self.assertGreater(len(hits), 2500)
        cell_rms, cell_max, cell = self.shading_error(
            mesh, hits, outside, vtkHexahedralRayCastMapper.CELL_GRADIENTS)
        vertex_rms, vertex_max, vertex = self.shading_error(
            mesh, hits, outside, vtkHexahedralRayCastMapper.VERTEX_GRADIENTS)
        given_rms, given_max, given = self.shading_error(
            sphere_mesh(self.RESOLUTION, analytic_gradients=True), hits, outside,
            vtkHexahedralRayCastMapper.VERTEX_GRADIENTS)
        print(f"\n  {len(hits)} pixels; |shade - cos(analytic normal, light)| RMS / max: cell gradients "
              f"{cell_rms:.3g} / {cell_max:.3g}, vertex gradients (computed) {vertex_rms:.3g} / {vertex_max:.3g}, "
              f"(analytic array) {given_rms:.3g} / {given_max:.3g}", end="")
        # The coarse cells really facet the exact gradient; interpolated vertex gradients, computed or
        # given, follow the analytic normal far more closely.
        self.assertGreater(cell_rms, 0.04)
        self.assertLess(vertex_rms, 0.01)
        self.assertLess(vertex_rms, 0.25 * cell_rms)
        self.assertLess(vertex_max, 0.25 * cell_max)
        self.assertLess(given_rms, 0.01)
        # Computed once per mesh and scalar, not per frame or isovalue; never for a given array or cell
        # gradients.
        vertex.render()
        vertex.mapper.RemoveAllIsosurfaces()
        vertex.mapper.AddIsosurface(0.6, 1.0, 1.0, 1.0, 1.0)
        vertex.render()
        self.assertEqual(statistic(vertex.mapper, "GradientComputations"), 1)
        scalars = mesh.GetPointData().GetScalars()
        scalars.Modified()  # touched, not changed: the mapper compares content
        vertex.render()
        self.assertEqual(statistic(vertex.mapper, "GradientComputations"), 1)
        scalars.SetTuple1(0, scalars.GetTuple1(0) + 0.01)
        scalars.Modified()
        vertex.render()
        self.assertEqual(statistic(vertex.mapper, "GradientComputations"), 2)
        self.assertEqual(statistic(given.mapper, "GradientComputations"), 0)
        self.assertEqual(statistic(cell.mapper, "GradientComputations"), 0)

    def test_vertex_gradients_of_a_linear_field_light_every_cell_kind_exactly(self):
        # vtkVertexGradientFilter is exact for a linear field and interpolating one gradient gives it
        # back: the plane isosurface takes the analytic Phong colour through jittered hexahedra, wedges,
        # pyramids and tetrahedra (whose repeated corners repeat their gradient).
        mesh = hex_dominant(6)
        camera = camera_for(mesh, 30, 25, parallel=True)
        color = (0.2, 0.6, 1.0)
        prop, expected = plane_scene_setup(mesh, camera, color)
        scene = HexScene(mesh, prop, camera, GradientMode=vtkHexahedralRayCastMapper.VERTEX_GRADIENTS)
        scene.mapper.AddIsosurface(0.1, *color, 1.0)
        covered, worst = covered_colour_error(scene.render(), expected)
        print(f"\n  {covered} covered pixels, worst colour error {worst:.3g}", end="")
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        self.assertGreater(covered, 2000)
        self.assertLess(worst, 2e-3)
        # A cell scalar's surfaces stay lit by their faces: nothing to compute.
        to_cells = vtkPointDataToCellData()
        to_cells.SetInputData(mesh)
        to_cells.Update()
        on_cells = HexScene(to_cells.GetOutput(), prop, camera, 32,
                            GradientMode=vtkHexahedralRayCastMapper.VERTEX_GRADIENTS)
        on_cells.mapper.AddIsosurface(0.1, *color, 1.0)
        on_cells.render()
        self.assertEqual(on_cells.events.errors, 0)
        self.assertEqual(statistic(on_cells.mapper, "GradientComputations"), 0)

    def test_the_default_is_the_cell_gradient(self):
        self.assertEqual(vtkHexahedralRayCastMapper().GetGradientMode(), vtkHexahedralRayCastMapper.CELL_GRADIENTS)


def sparse_property(low, high, unit, visible_from=0.55):
    """Nothing below `visible_from` of the range, a ramp above it: most cells are invisible."""
    start = low + visible_from * (high - low)
    return property_from_nodes(((low, 0.0), (start, 0.0), (start + 0.1 * (high - low), 0.3), (high, 0.8)),
                               ((low, (0.2, 0.3, 0.9)), (high, (1.0, 0.6, 0.1))), unit)


class SkippingTests(SceneTestCase):
    """SkipInvisibleCells walks only the cells the transfer function leaves visible, entering at that
    region's front and peeling over invisible runs: the image is the full walk's within float
    rounding (the walk's sum is cut where it leaves the region), on every pixel, the region is
    rebuilt only when an edit changes which cells are visible, and the eye may sit in an invisible
    cell."""

    BOUND = 2e-5  # RGBA difference from the full walk, on every pixel

    def compare(self, mesh, prop, camera, size=96, isovalues=(), bound=BOUND, **settings):
        images = []
        for skip in (False, True):
            scene = HexScene(mesh, prop, camera, size, SkipInvisibleCells=skip, **settings)
            for value in isovalues:
                scene.mapper.AddIsosurface(value, 1.0, 0.9, 0.3, 0.6)
            images.append(copy_image(scene.render()))
            self.assertEqual(scene.events.errors, 0)
        full, skipped = (image.GetPointData().GetScalars() for image in images)
        self.assertGreater(full.GetRange(3)[1], 0.05)  # something is drawn
        off = [p for p in range(full.GetNumberOfTuples())
               if max(abs(a - b) for a, b in zip(full.GetTuple4(p), skipped.GetTuple4(p))) > bound]
        self.assertEqual(off, [])
        return scene.mapper

    def test_sparse_transfer_function_on_a_twisted_grid(self):
        mesh = analytic_hexahedra(10, distortion=vtkAnalyticMeshSource.TWIST)
        # The automatic run limit, and a peel after every invisible cell: both the full walk's image.
        for limit in (0, 1):
            with self.subTest(limit=limit):
                mapper = self.compare(mesh, six_spikes(0.05), camera_for(mesh), InvisibleRunLimit=limit)
                self.assertLess(statistic(mapper, "VisibleCells"), statistic(mapper, "Cells"))
                self.assertGreater(statistic(mapper, "Peels"), 1)  # rays leapt over invisible runs

    def test_the_last_peel_walks_on_through_invisible_runs(self):
        # Columns of visible matter across a convex grid. Walking at most 4 invisible cells in a row,
        # most rays cross several columns, each a peel, where one pass does without skipping; fewer
        # peels allowed must still give the whole image. By default the gaps are walked: fewer peels.
        mesh = analytic_hexahedra(24)
        points, bounds = mesh.GetPoints(), mesh.GetBounds()
        columns = vtkDoubleArray()
        columns.SetName("columns")
        for i in range(points.GetNumberOfPoints()):
            x, y, _ = points.GetPoint(i)
            u, v = (x - bounds[0]) / (bounds[1] - bounds[0]), (y - bounds[2]) / (bounds[3] - bounds[2])
            columns.InsertNextValue(math.cos(4 * math.pi * u) * math.cos(4 * math.pi * v))
        mesh.GetPointData().SetScalars(columns)
        low, high = columns.GetRange()
        prop = sparse_property(low, high, 0.05, 0.8)
        short_runs = statistic(self.compare(mesh, prop, camera_for(mesh), InvisibleRunLimit=4), "Peels")
        walked = statistic(self.compare(mesh, prop, camera_for(mesh)), "Peels")
        self.assertGreaterEqual(short_runs, 3, "peels with runs of 4 cells at most")
        self.assertLess(walked, short_runs, f"peels walking the gaps, against {short_runs}")
        for peels in (1, 2):
            with self.subTest(peels=peels):
                mapper = self.compare(mesh, prop, camera_for(mesh), MaximumPeels=peels, InvisibleRunLimit=4)
                self.assertEqual(statistic(mapper, "Peels"), peels)

    def test_eye_in_an_invisible_cell(self):
        mesh = analytic_hexahedra(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        self.compare(mesh, sparse_property(low, high, 0.05, 0.7), inside_camera())

    def test_hex_dominant_mesh_and_cell_data_isosurfaces_between_invisible_cells(self):
        mesh = hex_dominant(6)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        mapper = self.compare(mesh, sparse_property(low, high, 0.05), camera_for(mesh))
        self.assertLess(statistic(mapper, "VisibleCells"), statistic(mapper, "Cells"))
        # A transparent volume of cell data: only the faces between cells across the isovalue draw,
        # so exactly the cells beside such a face are walked.
        cells = vtkPointDataToCellData()
        cells.SetInputData(mesh)
        cells.PassPointDataOff()
        cells.Update()
        on_cells = cells.GetOutput()
        middle = 0.5 * (low + high)
        mapper = self.compare(on_cells, transparent_property(), camera_for(mesh), isovalues=(middle,))
        self.assertLess(statistic(mapper, "VisibleCells"), statistic(mapper, "Cells") // 2)

    def test_real_meshes(self):
        for name, loader, array in shared_data.REFERENCE_MESHES:
            if name not in ("blunt_fin", "disk_out_ref", "lox_post", "can", "sample_struct_grid"):
                continue
            mesh = load_shared(self, loader)
            mesh.GetPointData().SetActiveScalars(array)
            low, high = mesh.GetPointData().GetArray(array).GetRange()
            with self.subTest(name):
                self.compare(mesh, sparse_property(low, high, 0.03 * mesh.GetLength()), camera_for(mesh),
                             DelegateTetrahedralMeshes=False)  # the walk's own skipping

    def test_rays_grazing_invisible_voxels_between_visible_ones(self):
        # neghip's voxels under a ramp: its visible region folds along edges of invisible voxels, where
        # a ray grazing such an edge leaves the region without crossing an entry face the rasteriser
        # gives it; the walk must carry it on through the invisible voxel. Where a ray grazes an edge
        # of four voxels, the walk and the next peel may take it through different ones for a sliver
        # within the faces' slack: a looser bound.
        image = load_shared(self, shared_data.neghip_image)
        low, high = image.GetPointData().GetScalars().GetRange()
        mesh = shared_data.image_as_voxels(image)
        prop = property_from_nodes(((low, 0.0), (low + 0.2 * (high - low), 0.02), (high, 0.6)),
                                   ((low, (0.2, 0.3, 0.8)), (high, (0.7, 0.1, 0.1))), 2.0)
        for azimuth in (0.0, 37.0, 74.0, 111.0):
            with self.subTest(azimuth=azimuth):
                mapper = self.compare(mesh, prop, camera_for(mesh, azimuth=azimuth), size=128, bound=1e-4)
        self.assertLess(statistic(mapper, "VisibleCells"), statistic(mapper, "Cells"))

    def test_region_rebuilt_only_when_visibility_changes(self):
        mesh = analytic_hexahedra(6)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = sparse_property(low, high, 0.05)
        scene = HexScene(mesh, prop, camera_for(mesh), 48)
        self.assertTrue(scene.mapper.GetSkipInvisibleCells())  # the default
        scene.render()
        self.assertEqual(statistic(scene.mapper, "VisibleRegionBuilds"), 1)
        visible = statistic(scene.mapper, "VisibleCells")
        prop.GetRGBTransferFunction().AddRGBPoint(0.5 * (low + high), 0.0, 1.0, 0.0)  # colour only
        scene.render()
        self.assertEqual(statistic(scene.mapper, "VisibleRegionBuilds"), 1)
        prop.GetScalarOpacity().AddPoint(low, 0.2)  # now every cell is visible
        scene.render()
        self.assertEqual(statistic(scene.mapper, "VisibleRegionBuilds"), 2)
        self.assertGreater(statistic(scene.mapper, "VisibleCells"), visible)
        self.assertEqual(statistic(scene.mapper, "VisibleCells"), statistic(scene.mapper, "Cells"))
        scene.mapper.SkipInvisibleCellsOff()
        scene.render()
        self.assertEqual(statistic(scene.mapper, "EntryFaces"), statistic(scene.mapper, "BoundaryFaces"))


class InputTests(SceneTestCase):
    def test_an_opacity_function_without_nodes_draws_nothing_quietly(self):
        # Zero everywhere, as VTK evaluates it and the reference draws it; it was an error.
        mesh = analytic_hexahedra(3)
        scene = HexScene(mesh, property_from_nodes((), (), 1.0), camera_for(mesh), 32)
        alpha = scene.render().GetPointData().GetScalars().GetRange(3)
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        self.assertEqual(alpha, (0.0, 0.0))

    def test_polyhedra_are_split_on_the_way(self):
        # They were refused before. A polyhedron's field is its split's (as the reference has it).
        polyhedra = as_polyhedra(analytic_hexahedra(2))
        prop, camera = uvrender.volume_property((0, 1)), camera_for(polyhedra)
        scene = HexScene(polyhedra, prop, camera, 48)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(rmse(image, reference(polyhedra, prop, camera, 48))[0], 1e-3)

    def test_image_and_structured_grids_render_as_they_are(self):
        # vtkImageData (voxels) and vtkStructuredGrid (hexahedra) straight in: the same image as
        # their vtkUnstructuredGrid copies, and the reference's; a blanked cell leaves a hole.
        wavelet = vtkRTAnalyticSource()
        wavelet.SetWholeExtent(-4, 4, -4, 4, -4, 4)
        wavelet.Update()
        image = wavelet.GetOutput()
        structured = vtkStructuredGrid()
        structured.SetDimensions(9, 9, 9)
        points = vtkPoints()
        for i in range(image.GetNumberOfPoints()):
            x, y, z = image.GetPoint(i)
            points.InsertNextPoint(x + 0.15 * z, y, z)  # sheared: no longer an image
        structured.SetPoints(points)
        structured.GetPointData().SetScalars(image.GetPointData().GetScalars())
        prop = uvrender.volume_property(image.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(2.0)
        for data in (image, structured):
            camera = camera_for(data, distance=1.8)
            converted = vtkAppendFilter()
            converted.SetInputData(data)
            converted.Update()
            direct_scene = HexScene(data, prop, camera, 64)
            direct = direct_scene.render()
            self.assertEqual(direct_scene.events.errors, 0)
            self.assertLess(rmse(direct, HexScene(converted.GetOutput(), prop, camera, 64).render())[0], 1e-6)
            self.assertLess(rmse(direct, reference(data, prop, camera, 64))[0], 1e-3)
        structured.BlankCell(4 + 8 * 4 + 64 * 4)  # cells (4, 4, 4) and (4, 4, 5)
        structured.BlankCell(4 + 8 * 4 + 64 * 5)
        scene = HexScene(structured, prop, camera, 64)
        holed = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(statistic(scene.mapper, "Cells"), 8 * 8 * 8 - 2)
        self.assertTrue(finite_image(holed))

    def test_empty_and_constant(self):
        scene = HexScene(vtkUnstructuredGrid(), uvrender.volume_property((0, 1)), camera_for(analytic_hexahedra(2)), 48)
        scene.render()
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)
        mesh = analytic_hexahedra(4)
        mesh.GetPointData().GetScalars().Fill(0.3)
        prop = uvrender.volume_property((0.0, 1.0))
        image = HexScene(mesh, prop, camera_for(mesh), 64).render()
        self.assertTrue(finite_image(image))
        self.assertLess(rmse(image, reference(mesh, prop, camera_for(mesh), 64))[0], 1e-3)


class ProgressTests(SceneTestCase):
    def test_preparation_reports_progress_once_per_data_change(self):
        # The mesh preparation (adjacency, split) reports progress like a filter (ParaView's progress
        # bar shows it through the plugin's representations); a frame with nothing changed does not.
        mesh = analytic_hexahedra(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for mapper in (vtkHexahedralRayCastMapper(), vtkPreIntegratedTetrahedraMapper()):
            progress = []
            mapper.AddObserver("ProgressEvent", lambda caller, event: progress.append(caller.GetProgress()))
            scene = HexScene(mesh, prop, camera_for(mesh), 48, mapper=mapper)
            scene.render()
            # The pipeline's own update reports 0 and 1 first; the preparation follows, 0 to 1.
            preparation = progress[len(progress) - 1 - progress[::-1].index(0.0):]
            self.assertGreaterEqual(len(preparation), 3, mapper.GetClassName())
            self.assertEqual(preparation[-1], 1.0)
            self.assertEqual(preparation, sorted(preparation))
            del progress[:]
            scene.render()
            self.assertEqual(progress, [])
            mesh.GetPointData().GetScalars().Modified()
            scene.render()
            self.assertEqual(progress[-1], 1.0)


class StressTests(SceneTestCase):
    def test_rays_along_faces_and_edges(self):
        # Axis-aligned views of a regular grid: rays run exactly along faces and edges.
        mesh = analytic_hexahedra(4)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for camera in (camera_for(mesh, 0, 0, parallel=True), camera_for(mesh, 90, 0, parallel=True),
                       camera_for(mesh, 0, 0)):
            scene = HexScene(mesh, prop, camera, 64)
            image = scene.render()
            self.assertEqual(scene.events.errors, 0)
            self.assertTrue(finite_image(image))
            self.assertLess(rmse(image, reference(mesh, prop, camera, 64))[0], 5e-3)

    def test_far_plane_far_beyond_the_near_plane(self):
        # The rays must not come from unprojecting through a float matrix: with the far plane 1e6
        # near distances away its depth rows lose the direction, and rays miss the shared edges of
        # the grid's faces (lost beyond them). The image is the one with a tight clipping range, within
        # what rays starting at other points round to where they graze edges.
        mesh = analytic_hexahedra(24)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        length = mesh.GetLength()
        images = []
        for near, far in ((1e-5 * length, 10 * length), (length, 4 * length)):
            camera = camera_for(mesh, azimuth=37.0)
            camera.SetClippingRange(near, far)
            scene = HexScene(mesh, prop, camera, 96)
            scalars = scene.render().GetPointData().GetScalars()
            images.append([scalars.GetTuple4(p) for p in range(scalars.GetNumberOfTuples())])
            self.assertEqual(scene.events.errors, 0)
        self.assertLess(largest_difference(*images), 1e-3)

    def property_and_camera(self, mesh):
        """A ramp at a third of the mesh's size, seen from outside with a near plane in proportion."""
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.3 * mesh.GetLength())
        camera = camera_for(mesh)
        camera.SetClippingRange(0.01 * mesh.GetLength(), 10 * mesh.GetLength())
        return prop, camera

    def assertMatchesReference(self, mesh, prop, camera, size):  # noqa: N802  (unittest's style)
        image, expected = HexScene(mesh, prop, camera, size).render(), reference(mesh, prop, camera, size)
        self.assertLess(rmse(image, expected)[0], 5e-3)
        pixels = [image.GetPointData().GetScalars().GetTuple4(p) for p in range(size * size)]
        wanted = [expected.GetPointData().GetScalars().GetTuple4(p) for p in range(size * size)]
        self.assertLess(largest_difference(pixels, wanted), 0.05)

    def test_meshes_a_millionth_and_a_million_times_the_size(self):
        # The walk's tolerances are in proportion to the ray parameter and the cell: with parts of
        # them absolute, a mesh a millionth the size drew nothing.
        for factor in ("1e-6", "1e6"):
            with self.subTest(factor=factor):
                mesh = stress.place(analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.TWIST),
                                    {"placement": "scale_" + factor})
                prop, camera = self.property_and_camera(mesh)
                error, _ = rmse(HexScene(mesh, prop, camera, 48).render(), reference(mesh, prop, camera, 48))
                self.assertLess(error, 5e-3)

    def test_curved_faces_a_billionth_and_a_trillion_times_the_size(self):
        # A curved face's ray quadratic has coefficients of a squared length and a discriminant of
        # its fourth power, which underflows (a billionth) or overflows (a trillion) in float, as did
        # a normal's orientation test: twisted and wedge/pyramid faces lost rays there.
        for name, source in (("twisted", analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.TWIST)),
                             ("hex-dominant", hex_dominant(5))):
            for factor in ("1e-9", "1e12"):
                with self.subTest(mesh=name, factor=factor):
                    mesh = stress.place(source, {"placement": "scale_" + factor})
                    self.assertMatchesReference(mesh, *self.property_and_camera(mesh), 32)

    def test_a_medium_opaque_within_a_billionth_shows_its_front_layer(self):
        # A unit distance of 1e-9 on a unit mesh: all the light comes from a front layer far thinner
        # than the spacing of the Gauss nodes over equal sub-pieces, which drew black.
        mesh = analytic_hexahedra(4, distortion=vtkAnalyticMeshSource.TWIST)
        prop, camera = self.property_and_camera(mesh)
        prop.SetScalarOpacityUnitDistance(1e-9)
        self.assertMatchesReference(mesh, prop, camera, 24)

    def test_delaunay_slivers_on_the_boundary(self):
        # A flat boundary tetrahedron's centre lies in its face's plane up to rounding: turning the
        # face's normal away from it pointed it inwards at random, and the rays entering there were lost.
        mesh = stress.delaunay_slivers()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for camera in (camera_for(mesh), camera_for(mesh, parallel=True)):
            self.assertMatchesReference(mesh, prop, camera, 24)

    def test_rays_cross_collapsed_layers(self):
        # Every other layer of points moved onto the one below: the cells between are flat, their
        # faces coincide pairwise with their neighbours', and their points with the layer below's.
        # Joining faces through coincident points made four faces of each key there, cut the mesh
        # in two and lost the rays crossing upwards; joined by id, the walk crosses the flat cells,
        # entering and leaving at one ray parameter, with no inverse map to step through them.
        mesh = stress.collapse_layers(analytic_hexahedra(4))
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.3 * mesh.GetLength())
        camera = vtkCamera()  # inside, below the flat layer z = 0, looking along it
        camera.SetPosition(-0.6, 0.03, -0.1)
        camera.SetFocalPoint(1.0, 0.03, -0.1)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(60)
        camera.SetClippingRange(0.01, 10)
        with self.subTest(mesh="hexahedra"):
            self.assertMatchesReference(mesh, prop, camera, 32)
        mesh = stress.collapse_layers(analytic(6))
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.3 * mesh.GetLength())
        with self.subTest(mesh="tetrahedra"):
            self.assertMatchesReference(mesh, prop, stress.make_camera(mesh, {"camera": "inside"}), 17)

    def test_rays_through_an_edge_beside_a_hole(self):
        # Stress case 1094 of seed 2026: NaN points leave holes; the middle column's rays run along
        # a line of edges. Leaving a cell through such an edge, the walk took the first face in its
        # order, a hole's, and stopped; the next peel's entry faces, which fold at the edge, gave
        # the pixel to none of them (too little alpha against the reference). Now a tied face with
        # a neighbour wins, and the walk goes on inside.
        case = {"mesh": "inverted_hexahedra", "scalars": "some_nan", "camera": "outside", "function": "ramp"}
        mesh = stress.apply_scalars(stress.build_mesh(case), case)
        self.assertMatchesReference(mesh, stress.make_property(mesh, case), stress.make_camera(mesh, case), 17)

    def test_a_flat_sliver_on_a_hole_does_not_end_the_ray(self):
        # Stress case 1098 of seed 2026 (with NaN instead of Inf): a ray touches a flat Delaunay
        # sliver on the boundary and leaves it at once into a hole. The next peel entered the sliver
        # again by another of its faces, which coincide, at the same parameter, and looped there
        # until the walk's bound ended the ray: pixels drawn empty. The next peel now skips the
        # cell the walk left the mesh from, at the parameter it left it.
        case = {"mesh": "slivers", "scalars": "some_nan", "camera": "outside", "function": "ramp"}
        mesh = stress.apply_scalars(stress.build_mesh(case), case)
        self.assertMatchesReference(mesh, stress.make_property(mesh, case), stress.make_camera(mesh, case), 48)

    def test_delaunay_slivers_a_millionth_and_a_trillion_times_the_size(self):
        # A sliver's centre lies in its faces' planes up to rounding, and a ray can cross it within
        # the walk's tolerance: its exit faces are oriented by their corners' order, and a ray leaves
        # where it entered when no face lies beyond that tolerance.
        for factor in ("1e-6", "1e12"):
            with self.subTest(factor=factor):
                mesh = stress.place(stress.delaunay_slivers(), {"placement": "scale_" + factor})
                self.assertMatchesReference(mesh, *self.property_and_camera(mesh), 32)

    def test_one_sided_limits_differ_only_where_a_ray_has_no_one_value(self):
        # stress.py takes a failing image against the nearest of the reference's one-sided limits
        # (the camera moved by NUDGE of the mesh's size). A collapsed layer seen edge-on: the field
        # jumps across the layer's plane, and the middle row's rays lie in it; the limits must
        # differ there, and nowhere else, or the comparison would forgive real errors.
        case = {"mesh": "flat_tetrahedra", "scalars": "int64", "camera": "grazing", "function": "all_opaque"}
        mesh = stress.apply_scalars(stress.build_mesh(case), case)
        prop, camera, size = stress.make_property(mesh, case), stress.make_camera(mesh, case), 17
        cameras = [camera] + stress.nudged_cameras(camera, stress.NUDGE * mesh.GetLength())
        limits = [reference(mesh, prop, moved, size).GetPointData().GetScalars() for moved in cameras]
        ambiguous = {(p % size, p // size) for p in range(size * size)
                     if max(abs(a.GetTuple4(p)[k] - b.GetTuple4(p)[k]) for a in limits for b in limits
                            for k in range(4)) > 0.05}
        self.assertTrue(ambiguous)
        self.assertEqual({y for _, y in ambiguous}, {size // 2})

    def test_rasteriser_band_forgives_only_pixels_on_a_projected_edge(self):
        # stress.py forgives up to BAND_PIXELS pixels within 1/16 pixel of a projected edge (the
        # contract of test_routes.SubPixelCoverage). One pixel changed on a projected edge is forgiven;
        # the same change at a pixel half a pixel from every edge, or on too many pixels, is not.
        mesh = analytic_hexahedra(2)  # seen along an axis, its middle edges run through pixel centres
        case = {"scalars": "smooth", "camera": "axis_aligned", "function": "ramp"}
        mesh = stress.apply_scalars(mesh, case)
        prop, camera, size = stress.make_property(mesh, case), stress.make_camera(mesh, case), 17
        expected = reference(mesh, prop, camera, size)
        edges = stress.projected_edges(mesh, camera, size)
        alpha = expected.GetPointData().GetScalars()
        covered = [p for p in range(size * size) if alpha.GetTuple4(p)[3] > 0.1]
        near = [p for p in covered if stress.within_band(p, size, edges)]
        far = [p for p in covered if p not in near]
        self.assertTrue(near and far)

        def changed(pixels):
            image = copy_image(expected)
            for p in pixels:
                image.GetPointData().GetScalars().SetTuple4(p, 0.0, 0.0, 0.0, 0.0)
            return image
        self.assertIsNotNone(stress.rasteriser_band(changed(near[:1]), expected, mesh, camera, size))
        self.assertIsNone(stress.rasteriser_band(changed(far[:1]), expected, mesh, camera, size))
        self.assertIsNone(stress.rasteriser_band(changed(near[:stress.BAND_PIXELS + 1]), expected, mesh, camera,
                                                 size))

    def test_coincident_cells_add_their_media(self):
        # Every cell twice on the same points, as a mesh appended twice: the optical model adds the
        # copies' media. Four faces of one key joined none of them, and the walk entered one copy
        # per peel until the peels ran out (stress, "coincident cells drawn once"). The copies now
        # merge into one cell of twice the density. Cell data too: an averaged cell value is the
        # same for both copies.
        for mesh_kind, scalars in (("hexahedra", "smooth"), ("hexahedra", "cell_data"), ("tetrahedra", "smooth")):
            with self.subTest(mesh=mesh_kind, scalars=scalars):
                base = analytic_hexahedra(4) if mesh_kind == "hexahedra" else analytic(4)
                case = {"mesh": mesh_kind, "scalars": scalars, "camera": "outside", "function": "ramp"}
                mesh = stress.apply_scalars(stress.every_cell_twice(base), case)
                self.assertMatchesReference(mesh, stress.make_property(mesh, case), stress.make_camera(mesh, case), 32)

    def stress_case_error(self, size, **choices):
        """RMSE and covered pixels missed of a stress-suite case made of `choices`, against the reference."""
        case = dict(stress.choose(2026, 0), **choices)
        mesh = stress.place(stress.apply_scalars(stress.build_mesh(case), case), case)
        prop, camera = stress.make_property(mesh, case), stress.make_camera(mesh, case)
        scene = HexScene(mesh, prop, camera, size)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        return stress.accuracy_against(image, reference(mesh, prop, camera, size))

    def test_eye_on_a_curved_corner(self):
        # The eye on a corner of a twisted grid: the boundary faces through it are curved, and each of
        # their two triangles through the eye projects to a line, so no pixel tested them and rays
        # that leave the corner outside the mesh and enter it further on were lost (stress, "eye on
        # a curved boundary"). The entry pass draws the other diagonal's triangles too where a face
        # is not flat.
        for scalars in ("smooth", "int8"):
            with self.subTest(scalars=scalars):
                error, missed = self.stress_case_error(17, mesh="twisted_hexahedra", scalars=scalars,
                                                       placement="scale_1e-9", camera="on_vertex", function="ramp")
                self.assertLess(error, 1e-3)
                self.assertEqual(missed, 0)

    def test_near_plane_points_beyond_a_hole(self):
        # Cells on points of their own, holes where a NaN leaves cells out, the eye on a vertex in a
        # hole: the cell holding the near plane's centre could not reach many rays' near-plane points
        # inside the mesh (the walk there stopped at the hole), and those rays started at the next
        # boundary face where they enter, losing the cells before it. Such a ray now starts from the
        # nearest boundary face it crosses: walked back from where it leaves the mesh to its point.
        for function, camera in (("all_opaque", "on_vertex"), ("single_node", "on_vertex")):
            with self.subTest(function=function, camera=camera):
                error, missed = self.stress_case_error(
                    48 if function == "all_opaque" else 17, mesh="duplicate_points_tetrahedra", scalars="some_nan",
                    placement="scale_1e-6" if function == "all_opaque" else "offset_1e9", camera=camera,
                    function=function)
                self.assertLess(error, 0.01)

    def test_tangled_hexahedron_is_told_and_rendered_finite(self):
        mesh = single_hexahedron([0.1, 0.9, 0.4, 0.6, 0.8, 0.2, 1.0, 0.3])
        mesh.GetPoints().SetPoint(6, -0.2, -0.2, -1.0)  # corner 6 pushed through the opposite face
        scene = HexScene(mesh, uvrender.volume_property((0, 1)), camera_for(mesh, distance=1.5), 64)
        image = scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))
        self.assertEqual(statistic(scene.mapper, "TangledCells"), 1)
        self.assertTrue(finite_image(image))

    def test_nearly_degenerate_hexahedra(self):
        mesh = analytic_hexahedra(4)
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            if abs(z - 0.0) < 1e-9:
                points.SetPoint(i, x, y, 0.5 - 1e-6)  # a layer of cells 1e-6 thin
        points.Modified()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = HexScene(mesh, prop, camera_for(mesh), 64)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertTrue(finite_image(image))


class FoldedCellTests(SceneTestCase):
    def test_folded_cells_against_the_reference(self):
        # A ray may cross a folded cell's curved faces several times, and their normals do not tell
        # where it enters the cell and where it leaves. The walk takes such a cell's parts as the
        # reference does (the stretches between its face hits whose middles Newton from the centre
        # maps into the cell), and the entry pass lets a ray into it by any crossing. Before, whole
        # stretches of these cells were lost or added, far past both bounds.
        # Where different cells overlap (the second layer reaching down through the folded first),
        # the walk adds its overlap partners' media, and rays enter through the faces that a fold
        # pushed out of the mesh. Before, those rays lost the second layer's cells: 0.92 off.
        prop = uvrender.volume_property((0, 1))
        prop.SetScalarOpacityUnitDistance(0.5)
        for columns, depth, layers, tangled, pairs in ((1, -0.4, 1, 1, 0), (4, -0.5, 1, 4, 0), (4, -0.5, 2, 4, 4)):
            mesh = folded_slab(columns, depth, layers)
            for azimuth, elevation in ((30, 25), (120, -20), (250, 60), (0, 89), (10, -80)):
                with self.subTest(columns=columns, layers=layers, azimuth=azimuth, elevation=elevation):
                    camera = camera_for(mesh, azimuth, elevation, distance=1.8)
                    scene = HexScene(mesh, prop, camera, 96)
                    image, exact = scene.render(), reference(mesh, prop, camera, 96)
                    error, worst = rmse(image, exact)
                    print(f"\n  RMSE {error:.3g}, max {worst:.3g}", end="")
                    self.assertEqual(scene.events.errors, 0)
                    self.assertLess(error, 3e-3)
                    self.assertEqual(statistic(scene.mapper, "TangledCells"), tangled)
                    self.assertEqual(statistic(scene.mapper, "OverlappingPairs"), pairs)
                    # The rim of a fold, where a ray grazes the crease, may leave a pixel or two.
                    drawn, exact = image.GetPointData().GetScalars(), exact.GetPointData().GetScalars()
                    off = sum(1 for p in range(drawn.GetNumberOfTuples())
                              if max(abs(x - y) for x, y in zip(drawn.GetTuple4(p), exact.GetTuple4(p))) > 0.05)
                    self.assertLessEqual(off, 2)


class ReservoirGridTests(SceneTestCase):
    """Corner-point grids (corner_point.py): layers pinching out into hexahedra with repeated ids and
    flat cells, a fault whose faces do not match across it, left-handed cells, UTM coordinates."""

    def test_the_generator_makes_what_reservoir_grids_have(self):
        mesh = corner_point.corner_point_grid()
        uses = corner_point.face_use_counts(mesh)
        self.assertGreater(corner_point.repeated_id_cells(mesh), 20)
        self.assertGreater(sum(1 for count in uses.values() if count > 2), 10)  # pinched layers
        self.assertEqual(set(corner_point.corner_jacobian_signs(mesh)), {-1})  # left-handed
        self.assertGreater(mesh.GetBounds()[2], 7e6)  # UTM northing
        unfaulted = corner_point.corner_point_grid(fault=False)
        self.assertGreater(mesh.GetNumberOfPoints(), unfaulted.GetNumberOfPoints())  # fault nodes twice

    def check(self, mesh, camera, scalars="cells"):
        if scalars == "points":
            mesh.GetCellData().SetActiveScalars(None)
            mesh.GetPointData().SetActiveScalars("PRESSURE")
        values = mesh.GetCellData().GetScalars() or mesh.GetPointData().GetScalars()
        prop = uvrender.volume_property(values.GetRange())
        prop.SetScalarOpacityUnitDistance(0.1 * mesh.GetLength())
        scene = HexScene(mesh, prop, camera, 96)
        image = scene.render()
        error, worst = rmse(image, reference(mesh, prop, camera, 96))
        print(f"\n  RMSE {error:.3g}, largest {worst:.3g}", end="")
        self.assertEqual(scene.events.errors, 0)
        # Before: flat pinched cells made four faces of one key and cut the mesh; boundary faces a
        # cell apart tied in the entry pass's window depth and the nearer lost (a fault's far side
        # drawn alone).
        self.assertLess(error, 2e-4)
        self.assertLess(worst, 0.02)

    def test_pinched_layers_and_a_fault_against_the_reference(self):
        for pinch, fault in ((True, False), (False, True), (True, True)):
            mesh = corner_point.corner_point_grid(pinch=pinch, fault=fault)
            for azimuth, elevation in ((30, 35), (100, 10), (-60, 60)):
                with self.subTest(pinch=pinch, fault=fault, azimuth=azimuth):
                    self.check(mesh, camera_for(mesh, azimuth, elevation))

    def test_point_data_and_right_handed_cells(self):
        for left_handed in (True, False):
            with self.subTest(left_handed=left_handed):
                mesh = corner_point.corner_point_grid(left_handed=left_handed)
                self.check(mesh, camera_for(mesh, -60, 60), scalars="points")


class RealMeshTests(BaselineTestCase):
    """The public meshes of ../shared/data (skipped when absent): accuracy against the reference at
    128x128, then a 256x256 baseline with and without isosurfaces."""

    def load(self, loader, scalar):
        mesh = load_shared(self, loader)
        mesh.GetPointData().SetActiveScalars(scalar)
        return mesh

    def check(self, mesh, unit_fraction, bound, baseline, isovalue_fractions=(), camera=None):
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacityUnitDistance(unit_fraction * mesh.GetLength())
        prop.SetAmbient(0.25)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.3)
        camera = camera or camera_for(mesh, 30, 25, distance=1.6)
        scene = HexScene(mesh, prop, camera, 128)
        error, worst = rmse(scene.render(), reference(mesh, prop, camera, 128))
        print(f"\n  RMSE {error:.3g}, max {worst:.3g} (bound {bound}), {statistic(scene.mapper, 'Peels')} peels", end="")
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(error, bound)
        for suffix, fractions in (("", ()), ("_isosurfaces", isovalue_fractions)):
            if suffix and not fractions:
                continue
            scene = HexScene(mesh, prop, camera, 256)
            scene.renderer.SetBackground(0.1, 0.1, 0.12)
            scene.renderer.SetBackgroundAlpha(1.0)
            for fraction, rgba in zip(fractions, ((1.0, 0.85, 0.3, 0.9), (0.3, 0.8, 1.0, 0.5))):
                scene.mapper.AddIsosurface(low + fraction * (high - low), *rgba)
            scene.render()
            self.assertEqual(scene.events.errors, 0)
            self.compare(scene.window, f"{baseline}{suffix}.png")
        return scene

    def test_blunt_fin(self):
        # Curvilinear hexahedra with collapsed cells.
        self.check(self.load(shared_data.bluntfin, "Density"), 0.01, 1e-3, "hexahedral_blunt_fin", (0.55,))

    def test_disk_out_ref(self):
        # Non-convex (a hole down the middle): two peels.
        self.check(self.load(shared_data.disk_out_ref, "Temp"), 0.05, 1e-3, "hexahedral_disk_out_ref", (0.4, 0.8))

    def test_can(self):
        # The crushed can: 51 of its 4800 hexahedra are tangled (Jacobian of both signs). The walk
        # takes their parts as the reference does (FoldedCellTests), and where cells of the crushed
        # wall overlap it adds their media; each of the two steps cut this error to under half.
        mesh = self.load(shared_data.can, "DISPL_magnitude")
        scene = self.check(mesh, 0.05, 4e-4, "hexahedral_can", (0.5,))
        self.assertEqual(statistic(scene.mapper, "TangledCells"), 51)
        self.assertGreater(statistic(scene.mapper, "OverlappingPairs"), 51)
        self.assertEqual(scene.events.warnings, 1)


class BaselineTests(BaselineTestCase):
    def render(self, mesh, prop, camera):
        scene = HexScene(mesh, prop, camera, 256)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.renderer.SetBackgroundAlpha(1.0)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        return scene

    def test_twisted_grid(self):
        mesh = analytic_hexahedra(10, distortion=vtkAnalyticMeshSource.TWIST)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.compare(self.render(mesh, prop, camera_for(mesh, distance=1.7)).window, "hexahedral_twisted_grid.png")

    def test_twisted_grid_with_isosurfaces(self):
        mesh = analytic_hexahedra(10, distortion=vtkAnalyticMeshSource.TWIST)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetAmbient(0.2)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.4)
        prop.SetSpecularPower(20)
        scene = HexScene(mesh, prop, camera_for(mesh, distance=1.7), 256)
        scene.mapper.AddIsosurface(low + 0.3 * (high - low), 0.2, 0.5, 1.0, 0.5)
        scene.mapper.AddIsosurface(low + 0.75 * (high - low), 1.0, 0.4, 0.2, 1.0)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.renderer.SetBackgroundAlpha(1.0)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.compare(scene.window, "hexahedral_twisted_isosurfaces.png")

    def test_rotated_grid(self):
        mesh = analytic_hexahedra(8, distortion=vtkAnalyticMeshSource.ROTATE_45)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.compare(self.render(mesh, prop, camera_for(mesh, 25, 20, distance=1.8)).window,
                     "hexahedral_rotated_grid.png")


if __name__ == "__main__":
    unittest.main()
