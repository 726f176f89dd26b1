"""vtkPreIntegratedTetrahedraMapper: accuracy against the reference renderer, image baselines, what
it skips, bad input and stress cases. Run by ctest under Xvfb with /usr/bin/python3."""
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(1, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Stress"))
import stress  # noqa: E402  (its generated degenerate meshes and placements)
import uvrender  # noqa: E402
from fixtures import (ML, STEINER, BaselineTestCase, Scene, SceneTestCase, TetrahedralInputChecks,  # noqa: E402
                      analytic, camera_for, check_geometry_shown_later, check_order_across_a_gap, copy_image,
                      finite_image, inside_camera, inside_out, mean_cell_values, opaque_sphere, plate_and_block,
                      reference, rmse, spike_property, statistic)

from unstructuredvolume import vtkAnalyticMeshSource, vtkHexahedraToTetrahedra, vtkHexahedralRayCastMapper  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIdList, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkPiecewiseFunction, vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkCamera  # noqa: E402


def twisted_hexahedra_and_split():
    """Twisted Marschner-Lobb hexahedra (6^3) and vtkHexahedraToTetrahedra's split of them."""
    hexes = analytic(6, ML, vtkAnalyticMeshSource.TWIST, vtkAnalyticMeshSource.HEXAHEDRA)
    split = vtkHexahedraToTetrahedra()
    split.SetInputData(hexes)
    split.Update()
    return hexes, split.GetOutput()


class AccuracyTests(SceneTestCase):
    """Against the exact reference, on the float image before it is quantised into the window."""

    def check(self, mesh, prop, camera, size, bound, **settings):
        scene = Scene(mesh, prop, camera, size, **settings)
        return self.assert_near_reference(scene, mesh, prop, camera, size, bound)[0]

    def test_perspective_marschner_lobb_at_512(self):
        # Exact segments (cut at every node): the integral up to the Psi table and float rounding.
        mesh = analytic(8)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, camera_for(mesh), 512, 2e-5, SegmentIntegration=2)

    def test_faces_far_beyond_the_viewport(self):
        # Zoomed in from outside the mesh (the near plane cuts nothing), faces reach far past the
        # viewport and the clipper cuts them: an attribute interpolated without perspective went
        # wrong at the vertices it made, at both angles, so such frames rebuild the ray.
        mesh = analytic(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for angle in (2.0, 0.05):
            camera = vtkCamera()
            camera.SetPosition(0.31, -1.5, 0.17)
            camera.SetFocalPoint(0.35, 0.0, 0.12)
            camera.SetViewUp(0, 0, 1)
            camera.SetViewAngle(angle)
            camera.SetClippingRange(0.01, 10)
            self.check(mesh, prop, camera, 64, 1e-5, SegmentIntegration=2)

    def test_segment_table_within_its_measured_error(self):
        # AUTOMATIC reads the table of whole segments where its largest error against exact
        # segments, measured when built, is within the tolerance: each segment is then off by at
        # most that, and a pixel by at most the sum over its segments; the image's RMSE stays an
        # order of magnitude under the tolerance on this smooth function.
        mesh = analytic(8)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = Scene(mesh, prop, camera_for(mesh), 256)
        image = scene.render()
        self.assertTrue(statistic(scene.mapper, "UsedSegmentTable"))
        table_error = statistic(scene.mapper, "SegmentTableError")
        self.assertLess(table_error, scene.mapper.GetTransferFunctionTolerance())
        error, worst = rmse(image, reference(mesh, prop, camera_for(mesh), 256))
        print(f"\n  table error {table_error:.3g}; image RMSE {error:.3g}, max {worst:.3g}", end="")
        self.assertLess(error, 1e-4)
        # TABLE forced where it is too coarse (a thin opaque spike): AUTOMATIC refuses it.
        low, high = mesh.GetPointData().GetScalars().GetRange()
        spike = spike_property(low, high, 0.02)
        automatic = Scene(mesh, spike, camera_for(mesh), 64)
        automatic.render()
        self.assertFalse(statistic(automatic.mapper, "UsedSegmentTable"))
        self.assertGreater(statistic(automatic.mapper, "SegmentTableError"), 1e-3)
        forced = Scene(mesh, spike, camera_for(mesh), 64, SegmentIntegration=1)
        forced.render()
        self.assertTrue(statistic(forced.mapper, "UsedSegmentTable"))

    def test_parallel_twisted_mesh_split_on_the_fly(self):
        # Hexahedra in: the mapper splits them (one warning) and renders the tets exactly.
        hexes, tets = twisted_hexahedra_and_split()
        prop = uvrender.volume_property(hexes.GetPointData().GetScalars().GetRange())
        camera = camera_for(hexes, 50, -20, parallel=True)
        scene = Scene(hexes, prop, camera, 128, SegmentIntegration=2)
        image = scene.render()
        self.assertEqual(scene.events.warnings, 1)
        expected = reference(tets, prop, camera, 128)
        error, _ = rmse(image, expected)
        # The twist makes the centroid order wrong for some pairs of tetrahedra; the face order
        # (default) is exact, leaving the exact segments' own error (as on the same mesh untwisted).
        centroid, _ = rmse(Scene(hexes, prop, camera, 128, VisibilityOrder=0, SegmentIntegration=2).render(), expected)
        print(f"\n  face order RMSE {error:.3g}, centroid order {centroid:.3g}", end="")
        self.assertLess(error, 2e-6)
        self.assertGreater(centroid, 1e-4)
        self.assertEqual(statistic(scene.mapper, "CyclesBroken"), 0)

    def test_face_order_across_the_gap_of_a_non_convex_mesh(self):
        # No face joins the block to the plate behind it: the pixels' rays through the boundary
        # faces order them (the centroid order stood there before).
        check_order_across_a_gap(self)

    def test_thin_spike_jittered_mesh(self):
        # A spike 4% of the range wide: cutting at transfer-function nodes keeps it exact.
        mesh = analytic(7, STEINER, vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = spike_property(low, high, 0.05)
        self.check(mesh, prop, camera_for(mesh, 10, 40), 128, 5e-5)

    def test_average_scalar_mode_is_coarser_and_both_routes_agree(self):
        mesh = analytic(6, STEINER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = spike_property(low, high, 0.05)
        camera = camera_for(mesh)
        expected = reference(mesh, prop, camera, 128)
        pre_integrated, _ = rmse(Scene(mesh, prop, camera).render(), expected)
        average, _ = rmse(Scene(mesh, prop, camera, IntegrationMode=0).render(), expected)
        print(f"\n  pre-integrated {pre_integrated:.3g}, average scalar {average:.3g}", end="")
        self.assertGreater(average, 20 * pre_integrated)
        # The routes find the segment's ends two ways (barycentric crossings from a face, values
        # interpolated over the fan): they agree to float rounding.
        pulled = Scene(mesh, prop, camera).render()
        geometry = Scene(mesh, prop, camera, ProjectionRoute=1).render()
        self.assertLess(rmse(pulled, geometry)[1], 1e-4)

    def test_orders_longer_than_one_index_batch(self):
        # Vertex pulling draws from one fixed pattern of face indices, offset per chunk of 16,384
        # tetrahedra: a longer order must draw what the geometry-shader route draws. (RMSE, not the
        # largest error: at a few pixels whose rays graze faces the routes differ visibly, on
        # either side of the reference, which vtkLocatorRayMarcher confirms there.)
        mesh = analytic(24)
        self.assertGreater(mesh.GetNumberOfCells(), 4 * 16384)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        # Back to front (threshold 1): one draw of the whole order, not the masked batches.
        pulled = copy_image(Scene(mesh, prop, camera, 64, OpacityThreshold=1.0).render())
        geometry = Scene(mesh, prop, camera, 64, OpacityThreshold=1.0, ProjectionRoute=1).render()
        self.assertLess(rmse(pulled, geometry)[0], 5e-4)

    def test_camera_inside_the_mesh(self):
        # Tetrahedra around the eye cannot be projected; their fragments intersect the ray instead.
        mesh = analytic(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = inside_camera()
        # Tetrahedra crossing the near plane are ray-cast from that plane, where the reference's rays
        # begin (they began at the eye, over the whole screen, before). With exact segments and the
        # face order only the integration's error is left; the centroid order of the large
        # tetrahedra around the eye is wrong for some, and the table of whole segments (default)
        # reads segments as long as these within its tolerance.
        self.check(mesh, prop, camera, 96, 1e-5, SegmentIntegration=2)
        self.check(mesh, prop, camera, 96, 5e-4)
        centroid = Scene(mesh, prop, camera, 96, VisibilityOrder=0, SegmentIntegration=2).render()
        self.assertGreater(rmse(centroid, reference(mesh, prop, camera, 96))[0], 3e-4)

    def test_inside_out_tetrahedra_around_the_eye(self):
        # The pulled faces cull by winding: each tetrahedron is wound by its own orientation, so the
        # same cells in the opposite orientation keep their back faces where the near plane cuts them.
        mesh = inside_out(analytic(6))
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, inside_camera(), 96, 1e-5, SegmentIntegration=2)

    def test_parallel_camera_inside_the_mesh(self):
        # Parallel projection with the near plane cutting the mesh: what lies before the plane is not
        # seen (it was, projected whole: more pixels covered than the reference covers). Exact
        # segments leave only the integration's rounding; with 'noperspective' attributes Mesa's
        # clipper gave wrong front and back values along the viewport's border.
        mesh = analytic(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = vtkCamera()
        camera.ParallelProjectionOn()
        camera.SetParallelScale(0.8)
        camera.SetPosition(0.3, -0.2, 0.4)
        camera.SetFocalPoint(0.8, 0.9, 0.1)
        camera.SetViewUp(0, 0, 1)
        camera.SetClippingRange(0.2, 10)
        self.check(mesh, prop, camera, 96, 1e-5, SegmentIntegration=2)
        self.check(mesh, prop, camera, 96, 3e-4)


def unshared_halves(mesh):
    """The same tetrahedra with the points of the cells whose first point has x > 0 repeated: two
    halves that touch along a seam without sharing a point (a mesh written in blocks)."""
    copy = vtkUnstructuredGrid()
    points = vtkPoints()
    values = vtkFloatArray()
    values.SetName(mesh.GetPointData().GetScalars().GetName())
    scalars = mesh.GetPointData().GetScalars()
    for p in range(mesh.GetNumberOfPoints()):
        points.InsertNextPoint(mesh.GetPoint(p))
        values.InsertNextValue(scalars.GetValue(p))
    repeated = {}
    ids = vtkIdList()
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        corners = [ids.GetId(k) for k in range(4)]
        if mesh.GetPoint(corners[0])[0] > 0:
            for k, p in enumerate(corners):
                if p not in repeated:
                    repeated[p] = points.InsertNextPoint(mesh.GetPoint(p))
                    values.InsertNextValue(scalars.GetValue(p))
                corners[k] = repeated[p]
        copy.InsertNextCell(VTK_TETRA, 4, corners)
    copy.SetPoints(points)
    copy.GetPointData().SetScalars(values)
    return copy


class RayCastingTests(SceneTestCase):
    """RenderMode RAY_CASTING: rays walk the tetrahedra by adjacency. Against the exact reference
    (which intersects every ray with every tetrahedron, independently of the walk)."""

    def check(self, mesh, prop, camera, size, bound, peels=None, **settings):
        # Threshold 1: no early termination (its error, at most 1 - OpacityThreshold, is checked below).
        settings.setdefault("OpacityThreshold", 1.0)
        scene = Scene(mesh, prop, camera, size, RenderMode=1, **settings)
        self.assert_near_reference(scene, mesh, prop, camera, size, bound)
        print(f", {statistic(scene.mapper, 'Peels'):.0f} peels", end="")
        self.assertTrue(statistic(scene.mapper, "UsedRayCasting"))
        if peels is not None:
            self.assertEqual(statistic(scene.mapper, "Peels"), peels)
        return scene

    def test_exact_segments_perspective_and_parallel(self):
        # A convex mesh: one walk per ray, the integration's own error left.
        mesh = analytic(8)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        self.check(mesh, prop, camera_for(mesh), 128, 2e-5, peels=1, SegmentIntegration=2)
        parallel = camera_for(mesh, 50, -20, parallel=True)
        exact = copy_image(self.check(mesh, prop, parallel, 128, 2e-5, peels=1, SegmentIntegration=2).render())
        # Rays stop at the default OpacityThreshold (0.999): pixels change by at most 1 - 0.999.
        stopped = Scene(mesh, prop, parallel, 128, RenderMode=1, SegmentIntegration=2).render()
        worst = rmse(stopped, exact)[1]
        self.assertGreater(worst, 1e-4)
        self.assertLessEqual(worst, 1e-3 + 1e-6)

    def test_jittered_mesh_with_a_thin_spike_and_the_segment_table(self):
        mesh = analytic(7, STEINER, vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        self.check(mesh, spike_property(low, high, 0.05), camera_for(mesh, 10, 40), 128, 5e-5)
        prop = uvrender.volume_property((low, high))
        self.check(mesh, prop, camera_for(mesh), 128, 1e-4)

    def test_non_convex_mesh_across_its_gap(self):
        # Rays through the block leave the mesh and enter the plate behind: a second peel.
        mesh, _ = plate_and_block()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(1.0)
        # From beyond the plate's far end (its fixture camera stands above the plate, where the near
        # plane cuts the mesh's bounds and frames are projected).
        camera = vtkCamera()
        camera.SetPosition(14, 0.5, 6)
        camera.SetFocalPoint(1.5, 0.5, 0.7)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(30)
        camera.SetClippingRange(0.5, 30)
        self.check(mesh, prop, camera, 96, 1e-6, peels=2, SegmentIntegration=2)

    def test_seam_of_repeated_points_is_crossed(self):
        # Faces are matched by position: the seam between the halves is no boundary, one walk per
        # ray (matched by point id it took two peels) and the same image as the joined mesh.
        joined = analytic(6)
        halves = unshared_halves(joined)
        self.assertGreater(halves.GetNumberOfPoints(), joined.GetNumberOfPoints())
        prop = uvrender.volume_property(joined.GetPointData().GetScalars().GetRange())
        camera = camera_for(joined, 80, 10)
        self.check(halves, prop, camera, 96, 1e-5, peels=1, SegmentIntegration=2)

    def test_twisted_mesh_split_on_the_fly(self):
        # Twisted hexahedra split into tetrahedra whose boundary faces fold: where rays leave and
        # enter again the walk peels; no order to get wrong.
        hexes, tets = twisted_hexahedra_and_split()
        prop = uvrender.volume_property(hexes.GetPointData().GetScalars().GetRange())
        self.check(tets, prop, camera_for(hexes, 50, -20, parallel=True), 128, 2e-6,
                   SegmentIntegration=2)

    def test_isosurfaces_and_shading(self):
        # Gradients at each segment's ends come from the walk's barycentric weights.
        mesh = analytic(7, STEINER, vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.ShadeOn()
        scene = Scene(mesh, prop, camera_for(mesh), 96, RenderMode=1)
        scene.mapper.AddIsosurface(low + 0.6 * (high - low), 0.9, 0.8, 0.2, 0.5)
        image = copy_image(scene.render())
        self.assertTrue(statistic(scene.mapper, "UsedRayCasting"))
        projected = Scene(mesh, prop, camera_for(mesh), 96, RenderMode=0)
        projected.mapper.AddIsosurface(low + 0.6 * (high - low), 0.9, 0.8, 0.2, 0.5)
        error, worst = rmse(image, projected.render())
        print(f"\n  against projection: RMSE {error:.3g}, max {worst:.3g}", end="")
        self.assertLess(error, 1e-4)

    def test_cell_scalar_is_constant_in_each_tetrahedron(self):
        mesh = mean_cell_values(analytic(6, STEINER, vtkAnalyticMeshSource.JITTER))
        prop = uvrender.volume_property(mesh.GetCellData().GetScalars().GetRange())
        self.check(mesh, prop, camera_for(mesh), 96, 1e-5, peels=1, SegmentIntegration=2)

    def test_opaque_geometry_ends_the_rays(self):
        check_geometry_shown_later(self, RenderMode=1)

    def test_near_plane_in_the_mesh_is_projected_and_automatic_chooses_by_size(self):
        mesh = analytic(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        inside = Scene(mesh, prop, inside_camera(), 64, RenderMode=1)
        inside.render()
        self.assertFalse(statistic(inside.mapper, "UsedRayCasting"))
        # AUTOMATIC (default): 1,296 tetrahedra on 128^2 pixels are projected, 82,944 on 64^2 cast.
        small = Scene(mesh, prop, camera_for(mesh), 128)
        small.render()
        self.assertFalse(statistic(small.mapper, "UsedRayCasting"))
        large_mesh = analytic(24)
        large = Scene(large_mesh, prop, camera_for(large_mesh), 64)
        large.render()
        self.assertTrue(statistic(large.mapper, "UsedRayCasting"))


class OpaqueGeometryTests(SceneTestCase):
    def test_geometry_shown_later_cuts_the_volume_and_hidden_again_does_not(self):
        check_geometry_shown_later(self)

    def test_segments_cut_by_a_sphere_against_the_hexahedral_walk(self):
        # An opaque sphere inside the mesh ends the rays; the projected segments are cut where it
        # lies. The hexahedral mapper's walk cuts its rays there by its own code: both exact, no
        # early stop, so they differ by rounding (most on the sphere's silhouette pixels); a cut
        # moved by 0.01 in eye depth fails the bound.
        mesh = analytic(8)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())

        for parallel in (False, True):
            with self.subTest(parallel=parallel):
                camera = camera_for(mesh, parallel=parallel)
                alone = copy_image(Scene(mesh, prop, camera, 128, SegmentIntegration=2, RenderMode=0).render())
                projected = Scene(mesh, prop, camera, 128, (opaque_sphere(0.45, (0.3, -0.2, 0.2), 48),),
                                  SegmentIntegration=2, RenderMode=0, OpacityThreshold=1.0)
                image = copy_image(projected.render())
                walked = Scene(mesh, prop, camera, 128, (opaque_sphere(0.45, (0.3, -0.2, 0.2), 48),),
                               mapper_class=vtkHexahedralRayCastMapper, OpacityThreshold=1.0,
                               DelegateTetrahedralMeshes=False).render()  # its own walk
                error, worst = rmse(image, walked)
                print(f"\n  parallel {parallel}: RMSE {error:.3g}, max {worst:.3g}", end="")
                self.assertGreater(rmse(image, alone)[0], 0.01)  # the sphere hides what lies behind it
                self.assertLess(error, 3e-5)
                self.assertFalse(statistic(projected.mapper, "UsedRayCasting"))
                self.assertEqual(projected.events.errors, 0)


class HostMemoryTests(SceneTestCase):
    def test_host_bytes_per_tetrahedron(self):
        # Kept between frames, per tetrahedron: 4 point ids (16 B), its scalar range (8), its place in
        # the drawn list (4) and, projected, the order (4) and its 4 face neighbours for the face order
        # (16), or, ray-cast, its 4 face neighbours for the walk (16) and no order; per point a
        # recentred position and scalar (16); ray-cast, per boundary face its record (4). Sort keys and
        # the exact order's state live only while sorting, centroids are computed when sorting. The
        # issue's aim: at most 100 B per tetrahedron.
        mesh = analytic(16)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        tets, points = mesh.GetNumberOfCells(), mesh.GetNumberOfPoints()
        boundary = 6 * 16 * 16 * 2  # two triangles per square of the cube's surface
        for mode, expected in ((0, 48 + 16 * points / tets), (1, 44 + (16 * points + 4 * boundary) / tets)):
            scene = Scene(mesh, prop, camera_for(mesh), 64, RenderMode=mode)
            scene.render()
            self.assertEqual(statistic(scene.mapper, "UsedRayCasting"), mode == 1)
            per_tet = scene.mapper.GetHostMemoryInBytes() / tets
            print(f"\n  mode {mode}: {per_tet:.1f} B per tetrahedron kept on the host (itemised {expected:.1f})",
                  end="")
            self.assertEqual(scene.events.errors, 0)
            self.assertGreaterEqual(per_tet, expected)  # every item counted
            self.assertLessEqual(per_tet, expected + 1.0)
            self.assertLessEqual(per_tet, 100.0)


class BaselineTests(BaselineTestCase):
    def test_default_dataset(self):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(uvrender.ROOT, "Data", "marschner_lobb_twisted_hex.vtu"))
        reader.Update()
        mesh = reader.GetOutput()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = self.scene(mesh, prop, camera_for(mesh, distance=1.7))
        self.compare(scene.window, "preintegrated_default_perspective.png")

    def test_isosurfaces_opaque_sphere_parallel(self):
        # Two lit isosurfaces over the volume, an opaque sphere cutting into it, parallel projection.
        mesh = analytic(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.ShadeOff()
        prop.SetAmbient(0.2)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.4)
        prop.SetSpecularPower(20)
        actor = opaque_sphere(0.45, (0.4, -0.4, 0.3), 32, (0.8, 0.8, 0.3))
        scene = Scene(mesh, prop, camera_for(mesh, parallel=True), 256, (actor,))
        scene.mapper.AddIsosurface(low + 0.3 * (high - low), 0.2, 0.5, 1.0, 0.6)
        scene.mapper.AddIsosurface(low + 0.75 * (high - low), 1.0, 0.4, 0.2, 1.0)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.mapper.SetKeepFloatImage(False)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(statistic(scene.mapper, "GradientComputations"), 1)
        self.compare(scene.window, "preintegrated_isosurfaces_opaque_parallel.png")

    def test_super_phoenix(self):
        mesh = self.legacy(os.path.join("spx", "spx.vtk"), None)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
        scene = self.scene(mesh, prop, camera_for(mesh, 40, 20, distance=2.4))
        self.compare(scene.window, "preintegrated_spx_perspective.png")

    def test_lox_post_isosurface(self):
        mesh = self.legacy(os.path.join("lox_post", "post.vtk"), "Pressure")
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
        scene = Scene(mesh, prop, camera_for(mesh, 120, 30, parallel=True), 256)
        scene.mapper.AddIsosurface(low + 0.6 * (high - low), 0.9, 0.9, 0.3, 0.8)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.mapper.SetKeepFloatImage(False)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.compare(scene.window, "preintegrated_lox_isosurface_parallel.png")


class SkippingTests(SceneTestCase):
    def test_work_is_not_repeated(self):
        mesh = analytic(5)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        scene = Scene(mesh, prop, camera_for(mesh), 64)
        scene.render()
        scene.render()
        m = scene.mapper
        self.assertEqual((statistic(m, "Sorts"), statistic(m, "MeshUploads"), statistic(m, "TransferFunctionUploads")),
                         (1, 1, 1))
        self.assertEqual(statistic(m, "GradientComputations"), 0)  # nothing lit: no gradients
        scene.renderer.GetActiveCamera().Azimuth(5)
        scene.render()
        self.assertEqual(statistic(m, "Sorts"), 2)
        # An edit that keeps the zero-opacity set: one upload, no new visible list.
        builds = statistic(m, "VisibleListBuilds")
        prop.GetScalarOpacity().AddPoint(high, 0.9)
        scene.render()
        self.assertEqual(statistic(m, "TransferFunctionUploads"), 2)
        self.assertEqual(statistic(m, "VisibleListBuilds"), builds)
        # Zero opacity over the lower 70%: those tetrahedra are left out.
        drawn_all = statistic(m, "DrawnTetrahedra")
        prop.GetScalarOpacity().RemoveAllPoints()
        prop.GetScalarOpacity().AddPoint(low + 0.7 * (high - low), 0.0)
        prop.GetScalarOpacity().AddPoint(high, 0.8)
        image = scene.render()
        self.assertEqual(statistic(m, "VisibleListBuilds"), builds + 1)
        self.assertLess(statistic(m, "DrawnTetrahedra"), 0.6 * drawn_all)
        # Skipping changes nothing in the image (no pixel is opaque enough to stop being shaded).
        kept = copy_image(image)
        self.assertLess(max_alpha(image), m.GetOpacityThreshold())
        m.SkipInvisibleCellsOff()
        self.assertLess(rmse(scene.render(), kept)[1], 1e-6)
        self.assertEqual(statistic(m, "DrawnTetrahedra"), drawn_all)
        # Shading on: gradients once, then cached.
        prop.ShadeOn()
        scene.render()
        scene.render()
        self.assertEqual(statistic(m, "GradientComputations"), 1)
        self.assertEqual(scene.events.errors, 0)


def max_alpha(image):
    alphas = image.GetPointData().GetScalars()
    return max(alphas.GetComponent(i, 3) for i in range(alphas.GetNumberOfTuples()))


class EarlyTerminationTests(SceneTestCase):
    """With skipping on, the order is composited front to back in batches under an opacity mask
    (pseudo early ray termination) where the last frame left at least a quarter of the covered pixels
    opaque, and in the first frame. 24,576 tetrahedra: six batches, five mask refreshes."""

    def scene(self, unit_distance, **settings):
        mesh = analytic(16)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(unit_distance)
        camera = camera_for(mesh)
        # Projected (the ray caster stops each ray itself): the subject is the masked batches.
        return mesh, prop, camera, Scene(mesh, prop, camera, 96, CountShadedFragments=True, RenderMode=0, **settings)

    def render_both_ways(self, scene, refreshes=5):
        """The image and shaded fragments with skipping on, then off (back to front, no mask)."""
        m = scene.mapper
        on = copy_image(scene.render())
        self.assertTrue(statistic(m, "DrewFrontToBack"))
        self.assertEqual(statistic(m, "OpacityMaskRefreshes"), refreshes)
        shaded_on = statistic(m, "ShadedFragments")
        m.SkipInvisibleCellsOff()
        off = copy_image(scene.render())
        self.assertFalse(statistic(m, "DrewFrontToBack"))
        self.assertEqual(statistic(m, "OpacityMaskRefreshes"), 0)
        m.SkipInvisibleCellsOn()
        self.assertEqual(scene.events.errors, 0)
        return on, shaded_on, off, statistic(m, "ShadedFragments")

    def test_front_to_back_sums_what_back_to_front_does(self):
        # Translucent: no pixel reaches the threshold, so nothing is culled and the two orders
        # composite the same terms; they differ only by float rounding.
        for route in (0, 1):
            mesh, prop, camera, scene = self.scene(1.0, ProjectionRoute=route)
            on, shaded_on, off, shaded_off = self.render_both_ways(scene)
            self.assertLess(max_alpha(on), 0.999)
            self.assertEqual(shaded_on, shaded_off)
            self.assertGreater(shaded_on, 0)
            self.assertLess(rmse(on, off)[1], 1e-6, route)
            # Nothing was opaque: after a frame that measures it again (skipping was off), the next
            # frames go back to front, with the same image.
            scene.render()
            self.assertTrue(statistic(scene.mapper, "DrewFrontToBack"))
            scene.render()
            self.assertFalse(statistic(scene.mapper, "DrewFrontToBack"))
            self.assertEqual(statistic(scene.mapper, "OpaquePixelShare"), 0.0)
            self.assertLess(rmse(copy_image(scene.render()), off)[1], 1e-6, route)

    def test_opaque_pixels_stop_being_shaded(self):
        # Nearly opaque matter: most fragments lie behind pixels that are already opaque.
        mesh, prop, camera, scene = self.scene(0.01)
        on, shaded_on, off, shaded_off = self.render_both_ways(scene)
        culled = 1.0 - shaded_on / shaded_off
        error, worst = rmse(on, reference(mesh, prop, camera, 96))
        print(f"\n  {100 * culled:.0f}% of fragments culled; against the reference RMSE {error:.2g}, max {worst:.2g}",
              end="")
        self.assertGreater(culled, 0.3)
        # What a stopped pixel leaves out weighs at most 1 - threshold.
        self.assertLessEqual(rmse(on, off)[1], 1.0 - scene.mapper.GetOpacityThreshold() + 1e-6)
        self.assertLess(error, 1e-3)
        # Most covered pixels are opaque: the next frames stay front to back.
        scene.render()
        self.assertGreater(statistic(scene.mapper, "OpaquePixelShare"), 0.25)
        scene.render()
        self.assertTrue(statistic(scene.mapper, "DrewFrontToBack"))

    def test_camera_inside_with_isosurfaces_both_routes(self):
        # Tetrahedra crossing the near plane (ray-cast over their rectangles) and lit isosurfaces in
        # front-to-back batches: within the threshold's bound of back to front, on either route.
        mesh = analytic(12)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacityUnitDistance(0.02)
        for route in (0, 1):
            scene = Scene(mesh, prop, inside_camera(), 96, ProjectionRoute=route)
            scene.mapper.AddIsosurface(low + 0.6 * (high - low), 1.0, 0.8, 0.3, 0.7)
            on, _, off, _ = self.render_both_ways(scene, refreshes=2)
            self.assertGreater(max_alpha(on), 0.999)
            self.assertLessEqual(rmse(on, off)[1], 1.0 - scene.mapper.GetOpacityThreshold() + 1e-6, route)

    def test_a_share_far_under_the_choice_is_measured_every_eighth_frame(self):
        # Translucent: nothing is opaque, so the share is measured again only on the eighth frame
        # after; made nearly opaque meanwhile, the frames stay back to front until that measure.
        mesh, prop, camera, scene = self.scene(1.0)
        scene.render()
        self.assertEqual(statistic(scene.mapper, "OpaquePixelShare"), 0.0)
        prop.SetScalarOpacityUnitDistance(0.01)
        frames = 0
        while statistic(scene.mapper, "OpaquePixelShare") == 0.0 and frames < 20:
            scene.render()
            frames += 1
            self.assertFalse(statistic(scene.mapper, "DrewFrontToBack"))
        self.assertEqual(frames, 8)
        self.assertGreater(statistic(scene.mapper, "OpaquePixelShare"), 0.25)
        scene.render()
        self.assertTrue(statistic(scene.mapper, "DrewFrontToBack"))
        self.assertEqual(scene.events.errors, 0)

    def test_threshold_one_keeps_back_to_front(self):
        mesh, prop, camera, scene = self.scene(0.01, OpacityThreshold=1.0)
        scene.render()
        self.assertFalse(statistic(scene.mapper, "DrewFrontToBack"))
        self.assertEqual(statistic(scene.mapper, "OpacityMaskRefreshes"), 0)
        self.assertEqual(statistic(scene.mapper, "OpaquePixelShare"), -1.0)


class IsovalueNormalisationTests(SceneTestCase):
    def test_isosurfaces_follow_a_new_scalar_range(self):
        # The isovalues are uploaded normalised by the scalar's range: when the data change it, the
        # surfaces must stay at their values (the image equals a fresh mapper's).
        mesh = analytic(6)
        scalars = mesh.GetPointData().GetScalars()
        low, high = scalars.GetRange()
        prop = uvrender.volume_property((low, 3 * high))
        camera = camera_for(mesh)
        scene = Scene(mesh, prop, camera, 64)
        scene.mapper.AddIsosurface(low + 0.5 * (high - low), 1.0, 1.0, 1.0, 1.0)
        scene.render()
        for i in range(scalars.GetNumberOfTuples()):
            scalars.SetValue(i, 2.0 * scalars.GetValue(i))
        scalars.Modified()
        changed = copy_image(scene.render())
        fresh = Scene(mesh, prop, camera, 64)
        fresh.mapper.AddIsosurface(low + 0.5 * (high - low), 1.0, 1.0, 1.0, 1.0)
        # The changed mesh keeps a widened normalisation of its own (a time step's, so that the next
        # steps need no new tables) where the fresh one normalises exactly: rounding apart, the same.
        self.assertLess(rmse(changed, fresh.render())[1], 1e-5)


class InputTests(TetrahedralInputChecks, SceneTestCase):
    def scene(self, mesh, prop=None):
        prop = prop or uvrender.volume_property((0.0, 1.0))
        return Scene(mesh, prop, camera_for(analytic(2)), 48)

    def test_multi_component_scalars_render_their_first_component(self):
        # ParaView's "Use Separate Opacity Array" hands over "<array>_and_opacity" (2 components);
        # the first is rendered, shading's gradients included, with no error.
        mesh = analytic(3)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.ShadeOn()
        single = copy_image(self.scene(mesh, prop).render())
        scalars = mesh.GetPointData().GetScalars()
        pair = scalars.NewInstance()  # the same precision as the single-component render
        pair.SetName("pair")
        pair.SetNumberOfComponents(2)
        pair.SetNumberOfTuples(scalars.GetNumberOfTuples())
        pair.CopyComponent(0, scalars, 0)
        pair.FillComponent(1, 0.5)
        two = vtkUnstructuredGrid()
        two.ShallowCopy(mesh)
        two.GetPointData().SetScalars(pair)
        scene = self.scene(two, prop)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(rmse(image, single)[1], 1e-6)

    def test_nan_scalars_leave_out_their_tetrahedra(self):
        mesh = analytic(4)
        scalars = mesh.GetPointData().GetScalars()
        scalars.SetValue(30, float("nan"))
        scene = self.scene(mesh, uvrender.volume_property(scalars.GetRange()))
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.events.warnings, 1)
        self.assertLess(statistic(scene.mapper, "DrawnTetrahedra"), mesh.GetNumberOfCells())
        self.assertTrue(finite_image(image))


class StressTests(SceneTestCase):
    """Degenerate geometry and extreme views: finite output, no error (GL errors are reported as
    errors by the mapper)."""

    def finite(self, mesh, prop, camera, size=96):
        scene = Scene(mesh, prop, camera, size)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.window_events.errors, 0)
        self.assertTrue(finite_image(image))
        return image, scene

    def test_coincident_tetrahedra_keep_the_face_order(self):
        # Every tetrahedron twice on the same ids: each face joins four, so the face order found no
        # neighbour anywhere and fell back on centroids, wrong close to an eye on the boundary (under
        # an opaque function, a whole image of one cell's colour). Each set of copies is ordered by
        # one of its members' faces now, its copies drawn next to it. Cell projection sorts the same.
        from unstructuredvolume import vtkBarycentricShellMapper
        case = {"scalars": "cell_data", "placement": "scale_1e-6", "camera": "on_boundary_face",
                "function": "all_opaque"}
        mesh = stress.place(stress.apply_scalars(stress.every_cell_twice(analytic(4)), case), case)
        prop, camera = stress.make_property(mesh, case), stress.make_camera(mesh, case)
        expected = reference(mesh, prop, camera, 17)
        for name, scene in (("projection", Scene(mesh, prop, camera, 17, RenderMode=0)),
                            ("cell projection", Scene(mesh, prop, camera, 17, mapper_class=vtkBarycentricShellMapper,
                                                      RenderMode=1))):
            with self.subTest(mapper=name):
                self.assertLess(rmse(scene.render(), expected)[0], 1e-3)
                self.assertEqual(scene.events.errors, 0)

    def test_slivers_and_flat_tetrahedra(self):
        mesh = analytic(5)
        points = mesh.GetPoints()
        # Flatten every tetrahedron around one grid point onto a plane, and squash a layer to 1e-7.
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            if abs(z - 0.2) < 1e-9:
                points.SetPoint(i, x, y, 0.2 + 1e-7 * x)
        points.SetPoint(40, *points.GetPoint(41))
        points.Modified()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        image, _ = self.finite(mesh, prop, camera_for(mesh))
        error, _ = rmse(image, reference(mesh, prop, camera_for(mesh), 96))
        self.assertLess(error, 1e-3)

    def test_edge_on_and_close_views(self):
        mesh = analytic(4)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for camera in (camera_for(mesh, 0, 0), camera_for(mesh, 0, 0, parallel=True),
                       camera_for(mesh, 10, 5, distance=0.52)):
            self.finite(mesh, prop, camera)

    def test_huge_coordinate_offset(self):
        mesh = analytic(5)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        expected, _ = self.finite(mesh, prop, camera_for(mesh))
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            points.SetPoint(i, x + 1e6, y - 1e6, z + 1e6)
        points.Modified()
        mesh.Modified()
        shifted, _ = self.finite(mesh, prop, camera_for(mesh))
        self.assertLess(rmse(shifted, expected)[0], 1e-3)

    def test_constant_scalar_and_single_spike(self):
        mesh = analytic(4)
        mesh.GetPointData().GetScalars().Fill(0.25)
        prop = uvrender.volume_property((0.0, 1.0))
        image, _ = self.finite(mesh, prop, camera_for(mesh))
        self.assertEqual(rmse(image, reference(mesh, prop, camera_for(mesh), 96))[0] < 1e-4, True)
        spiky = analytic(5, STEINER)
        opacity = vtkPiecewiseFunction()
        low, high = spiky.GetPointData().GetScalars().GetRange()
        centre = 0.5 * (low + high)
        opacity.AddPoint(centre - 1e-6 * (high - low), 0.0)
        opacity.AddPoint(centre, 1.0)
        opacity.AddPoint(centre + 1e-6 * (high - low), 0.0)
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacity(opacity)
        self.finite(spiky, prop, camera_for(spiky))


if __name__ == "__main__":
    unittest.main()
