"""vtkBarycentricShellMapper: accuracy against the reference renderer (shells: error falls with the
sample distance; cell projection: exact), deformation, isosurfaces, image baselines, what it skips,
bad input and stress cases. Run by ctest under Xvfb with /usr/bin/python3."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import uvrender  # noqa: E402
from fixtures import (ML, STEINER, BaselineTestCase, Scene, SceneTestCase, TetrahedralInputChecks,  # noqa: E402
                      analytic, camera_for, check_geometry_shown_later, check_order_across_a_gap, copy_image,
                      covered_colour_error, finite_image, inside_camera, opaque_sphere, plane_scene_setup, reference, rmse,
                      spike_property, statistic, thin_shell_property, transparent_property)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Stress"))
import stress  # noqa: E402  (its generated degenerate meshes)
from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper,  # noqa: E402
                                vtkVolumeImageErrorMetrics)
from vtkmodules.vtkCommonCore import vtkDoubleArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkCamera  # noqa: E402

SHELLS, CELL_PROJECTION = vtkBarycentricShellMapper.SHELLS, vtkBarycentricShellMapper.CELL_PROJECTION
VERTEX, CELL = vtkBarycentricShellMapper.VERTEX_GRADIENTS, vtkBarycentricShellMapper.CELL_GRADIENTS


def shell_scene(mesh, prop, camera, size=128, props=(), **settings):
    return Scene(mesh, prop, camera, size, props, mapper_class=vtkBarycentricShellMapper, **settings)


class AccuracyTests(SceneTestCase):
    """Against the exact reference, on the float image before it is quantised into the window."""

    def error(self, mesh, prop, camera, size=128, **settings):
        scene = shell_scene(mesh, prop, camera, size, **settings)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.window_events.errors, 0)
        self.assertTrue(finite_image(image))
        return rmse(image, reference(mesh, prop, camera, size))[0], scene

    def test_shell_error_falls_with_the_sample_distance(self):
        # Without early termination (whose threshold leaves an error floor of its own), the sampling
        # error alone.
        mesh = analytic(12)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        expected = reference(mesh, prop, camera, 128)
        errors = []
        for distance in (0.1, 0.05, 0.02, 0.01):
            scene = shell_scene(mesh, prop, camera, SampleDistance=distance, OpacityThreshold=1.0)
            errors.append(rmse(scene.render(), expected)[0])
            self.assertEqual(scene.events.errors, 0)
        print("\n  RMSE at sample distance 0.1, 0.05, 0.02, 0.01: " + ", ".join(f"{e:.3g}" for e in errors), end="")
        for coarse, fine in zip(errors, errors[1:]):
            self.assertLess(fine, 0.8 * coarse)
        self.assertLess(errors[-1], errors[0] / 10)
        # Where the ray enters or leaves the mesh between two samples, the slice outside records how far
        # off the boundary is and the scalar there; a silhouette ray's whole stretch between two samples
        # is integrated from an entry and an exit record. Without the scalar and the whole stretches
        # (records of the distance only) the finest error was well over this bound.
        self.assertLess(errors[-1], 6e-5)

    def test_default_sample_distance(self):
        # Automatic: 128 samples across the bounding box diagonal (early termination included). Before
        # silhouette stretches between two samples were integrated, the error was well over the bound.
        mesh = analytic(12)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        error, scene = self.error(mesh, prop, camera_for(mesh))
        print(f"\n  RMSE {error:.3g} at sample distance {statistic(scene.mapper, 'SampleDistance'):.3g}", end="")
        self.assertAlmostEqual(statistic(scene.mapper, "SampleDistance"), mesh.GetLength() / 128, 9)
        self.assertLess(error, 4e-4)

    def test_cell_projection_is_exact(self):
        # The whole segment per tetrahedron, cut at the nodes and pre-integrated: exact but for rounding.
        # AUTOMATIC reads the table of whole segments instead where its measured error is within the
        # tolerance (per segment; the image is off by far less).
        mesh = analytic(12)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        error, _ = self.error(mesh, prop, camera_for(mesh), RenderMode=CELL_PROJECTION, SegmentIntegration=2)
        self.assertLess(error, 1e-5)
        table, scene = self.error(mesh, prop, camera_for(mesh), RenderMode=CELL_PROJECTION)
        print(f"\n  exact {error:.3g}, table {table:.3g}", end="")
        self.assertLess(table, 1e-4)
        exact_image = copy_image(shell_scene(mesh, prop, camera_for(mesh), 64, RenderMode=CELL_PROJECTION,
                                             SegmentIntegration=2).render())
        table_image = shell_scene(mesh, prop, camera_for(mesh), 64, RenderMode=CELL_PROJECTION).render()
        self.assertGreater(rmse(table_image, exact_image)[0], 0.0)  # the table was read

    def test_cell_projection_face_order_on_a_twisted_mesh(self):
        # Twisted cells: the centroid order is wrong for some pairs of tetrahedra sharing a face; the
        # face order (default) leaves only the integration's error.
        from unstructuredvolume import vtkHexahedraToTetrahedra
        hexes = analytic(6, ML, vtkAnalyticMeshSource.TWIST, vtkAnalyticMeshSource.HEXAHEDRA)
        split = vtkHexahedraToTetrahedra()
        split.SetInputData(hexes)
        split.Update()
        mesh = split.GetOutput()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh, 50, -20, parallel=True)
        face, scene = self.error(mesh, prop, camera, RenderMode=CELL_PROJECTION, SegmentIntegration=2)
        centroid, _ = self.error(mesh, prop, camera, RenderMode=CELL_PROJECTION, SegmentIntegration=2,
                                 VisibilityOrder=0)
        print(f"\n  face order {face:.3g}, centroid order {centroid:.3g}", end="")
        self.assertLess(face, 2e-6)
        self.assertGreater(centroid, 1e-4)
        self.assertEqual(statistic(scene.mapper, "CyclesBroken"), 0)

    def test_cell_projection_face_order_across_the_gap_of_a_non_convex_mesh(self):
        check_order_across_a_gap(self, mapper_class=vtkBarycentricShellMapper, RenderMode=CELL_PROJECTION)

    def test_spike_transfer_function_parallel(self):
        # A thin opaque spike: the samples' segments are pre-integrated across it, so sampling does
        # not miss it.
        mesh = analytic(7, STEINER, vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = spike_property(low, high, 0.05)
        camera = camera_for(mesh, 10, 40, parallel=True)
        shells, _ = self.error(mesh, prop, camera)
        projected, _ = self.error(mesh, prop, camera, RenderMode=CELL_PROJECTION)
        print(f"\n  shells {shells:.3g}, cell projection {projected:.3g}", end="")
        self.assertLess(shells, 1e-2)
        self.assertLess(projected, 5e-5)

    def test_both_routes_draw_the_same_image(self):
        # Vertex pulling (culled faces) and the geometry shader (back faces emitted): same fragments,
        # but for rounding. A boundary's record holds its inside part in levels of 1/2048 of a segment
        # (uvBarycentricShellRecordLib.glsl), so the two may land on neighbouring levels: a pixel
        # apart by that part of one segment's opacity.
        mesh = analytic(6, STEINER, vtkAnalyticMeshSource.JITTER)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for camera in (camera_for(mesh), camera_for(mesh, 50, -20, parallel=True), inside_camera()):
            for mode in (SHELLS, CELL_PROJECTION):
                images = [copy_image(shell_scene(mesh, prop, camera, 64, RenderMode=mode,
                                                       ProjectionRoute=route).render()) for route in (0, 1)]
                self.assertLess(rmse(images[0], images[1])[1], 5e-5)

    def test_camera_inside_the_mesh(self):
        mesh = analytic(6)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        shells, _ = self.error(mesh, prop, inside_camera(), 96)
        projected, _ = self.error(mesh, prop, inside_camera(), 96, RenderMode=CELL_PROJECTION)
        print(f"\n  shells {shells:.3g}, cell projection {projected:.3g}", end="")
        self.assertLess(shells, 1e-2)
        self.assertLess(projected, 5e-3)

    def test_rays_begin_at_the_near_plane(self):
        # A near plane well inside the mesh, parallel and perspective: nothing in front of it counts,
        # as in the reference (the rays began at the eye before, which showed most in parallel).
        mesh = analytic(8)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for parallel in (True, False):
            camera = vtkCamera()
            camera.SetPosition(0.2, 0.05, 0.03)
            camera.SetFocalPoint(2.0, 0.05, 0.03)
            camera.SetViewUp(0, 0, 1)
            camera.SetParallelProjection(parallel)
            camera.SetParallelScale(1.3)
            camera.SetViewAngle(60)
            camera.SetClippingRange(0.3, 10)
            for mode in (0, CELL_PROJECTION):
                with self.subTest(parallel=parallel, mode=mode):
                    error, _ = self.error(mesh, prop, camera, 64, RenderMode=mode)
                    self.assertLess(error, 2e-3)



class OpaqueGeometryTests(SceneTestCase):
    def test_geometry_shown_later_cuts_the_volume_and_hidden_again_does_not(self):
        for mode in (SHELLS, CELL_PROJECTION):
            with self.subTest(mode=mode):
                check_geometry_shown_later(self, mapper_class=vtkBarycentricShellMapper, RenderMode=mode)


class IsosurfaceTests(SceneTestCase):
    def test_position_against_an_opaque_shell_in_the_reference(self):
        # An unlit opaque isosurface is the limit of a thin, very opaque shell of the transfer function
        # around the isovalue: the reference renders that shell. Only rays grazing the surface (its rim)
        # may differ.
        mesh = analytic(8, distortion=vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        value = low + 0.55 * (high - low)
        color = (0.9, 0.6, 0.2)
        camera = camera_for(mesh, 35, 20, distance=1.5)
        expected = reference(mesh, thin_shell_property(low, high, value, color, mesh.GetLength()), camera, 128)
        for mode in (SHELLS, CELL_PROJECTION):
            scene = shell_scene(mesh, transparent_property(color), camera, RenderMode=mode)
            scene.mapper.AddIsosurface(value, *color, 1.0)
            image = scene.render()
            metrics = vtkVolumeImageErrorMetrics()
            metrics.SetChannels(4)
            self.assertTrue(metrics.Compare(image, expected))
            print(f"\n  mode {mode}: RMSE {metrics.GetRMSE():.3g}, 99th percentile "
                  f"{metrics.GetPercentile99Error():.3g}, {metrics.GetNumberOfCoveredPixels()} covered pixels", end="")
            self.assertEqual(scene.events.errors, 0)
            self.assertGreater(metrics.GetNumberOfCoveredPixels(), 1500)
            self.assertLess(metrics.GetRMSE(), 0.03)
            self.assertLess(metrics.GetPercentile99Error(), 1e-3)
            # The volume is transparent everywhere: only the isosurface's cells are drawn, once per layer
            # (shells: one pass per crossing found, and one that finds none).
            passes = statistic(scene.mapper, "DrawnIsosurfaceLayers") + 1 if mode == SHELLS else 1
            self.assertLess(statistic(scene.mapper, "DrawnTetrahedra"), 0.5 * mesh.GetNumberOfCells() * passes)

    def test_translucent_sheets_behind_each_other(self):
        # A translucent isosurface crossed several times by most rays: the shells draw each crossing
        # (one layer each) and agree with cell projection, which integrates every crossing exactly;
        # one layer alone leaves the sheets behind the first out.
        mesh = analytic(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        camera = camera_for(mesh)
        images = {}
        for mode, layers in ((CELL_PROJECTION, 4), (SHELLS, 4), (SHELLS, 1)):
            scene = shell_scene(mesh, transparent_property(), camera, 96, RenderMode=mode, IsosurfaceLayers=layers)
            scene.mapper.AddIsosurface(low + 0.5 * (high - low), 0.9, 0.6, 0.2, 0.4)
            images[(mode, layers)] = copy_image(scene.render())
            self.assertEqual(scene.events.errors, 0)
            if mode == SHELLS:
                self.assertEqual(statistic(scene.mapper, "DrawnIsosurfaceLayers"), layers)
        all_layers = rmse(images[(SHELLS, 4)], images[(CELL_PROJECTION, 4)])[0]
        one_layer = rmse(images[(SHELLS, 1)], images[(CELL_PROJECTION, 4)])[0]
        print(f"\n  against cell projection: 4 layers {all_layers:.3g}, 1 layer {one_layer:.3g}", end="")
        self.assertLess(all_layers, 3e-3)  # a few pixels cross it more than 4 times
        self.assertGreater(one_layer, 10 * all_layers)

    def test_exact_phong_on_a_plane(self):
        # A linear field of position: its isosurface is a plane, its vertex gradients exact, so under a
        # parallel headlight every covered pixel has the same analytic Phong colour, in both modes.
        mesh = analytic(4, distortion=vtkAnalyticMeshSource.JITTER)
        camera = camera_for(mesh, 30, 25, parallel=True)
        color = (0.2, 0.6, 1.0)
        prop, expected = plane_scene_setup(mesh, camera, color)
        for mode, gradients in ((SHELLS, VERTEX), (CELL_PROJECTION, VERTEX), (SHELLS, CELL), (CELL_PROJECTION, CELL)):
            scene = shell_scene(mesh, prop, camera, RenderMode=mode, GradientMode=gradients)
            scene.mapper.AddIsosurface(0.1, *color, 1.0)
            covered, worst = covered_colour_error(scene.render(), expected)
            print(f"\n  mode {mode}, gradients {gradients}: {covered} covered pixels, worst colour error {worst:.3g}",
                  end="")
            self.assertEqual(statistic(scene.mapper, "GradientComputations"), 1 if gradients == VERTEX else 0)
            self.assertEqual(scene.events.errors, 0)
            self.assertGreater(covered, 2000)
            self.assertLess(worst, 2e-3)


class DeformationTests(SceneTestCase):
    def test_each_frame_of_a_deforming_mesh_matches_the_reference(self):
        # A time-varying displacement moves the points in place each frame: the mapper refreshes
        # positions only (no rebuild), and every frame is as accurate as a static mesh's.
        mesh = analytic(8)
        rest = [mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints())]
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        scene = shell_scene(mesh, prop, camera, 96, AutomaticSamplesAcross=256)
        points = mesh.GetPoints()
        for frame in range(4):
            t = 0.5 * frame
            for i, (x, y, z) in enumerate(rest):
                points.SetPoint(i, x + 0.08 * math.sin(3 * y + t), y + 0.05 * math.cos(2 * z - t), z)
            points.Modified()
            image = scene.render()
            error = rmse(image, reference(mesh, prop, camera, 96))[0]
            print(f"\n  frame {frame}: RMSE {error:.3g}", end="")
            self.assertLess(error, 1.5e-3)
        self.assertEqual(statistic(scene.mapper, "MeshBuilds"), 1)
        self.assertEqual(statistic(scene.mapper, "PointRefreshes"), 3)
        # The automatic sample distance, and so the segment table, stay as they were.
        self.assertEqual(statistic(scene.mapper, "SegmentTableBuilds"), 1)
        self.assertEqual(scene.events.errors, 0)


    def test_isosurfaces_on_a_deforming_mesh(self):
        # Vertex gradients follow the mesh (one computation per frame that moved it); the cells' own
        # gradients need none, and light the surface the same way up to faceting.
        mesh = analytic(8)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        camera = camera_for(mesh)
        scenes = {g: shell_scene(mesh, transparent_property(), camera, 64, GradientMode=g) for g in (VERTEX, CELL)}
        for scene in scenes.values():
            scene.mapper.AddIsosurface(low + 0.5 * (high - low), 0.9, 0.6, 0.2, 1.0)
            scene.mapper.SetKeepFloatImage(True)
        points = mesh.GetPoints()
        for frame in range(3):
            for i in range(points.GetNumberOfPoints()):
                x, y, z = points.GetPoint(i)
                points.SetPoint(i, x + 0.01 * (frame + 1) * y, y, z)
            points.Modified()
            images = {g: copy_image(scene.render()) for g, scene in scenes.items()}
            self.assertLess(rmse(images[VERTEX], images[CELL])[0], 0.05)
        self.assertEqual(statistic(scenes[VERTEX].mapper, "GradientComputations"), 3)
        self.assertEqual(statistic(scenes[CELL].mapper, "GradientComputations"), 0)
        self.assertEqual(statistic(scenes[CELL].mapper, "MeshBuilds"), 1)


def linear_image_and_mesh(gradient=(0.3, -0.5, 0.8)):
    """A 17^3 image of a linear field on [-1, 1]^3, and a jittered tetrahedral mesh of the same cube
    carrying texture coordinates into it and the same field as its point scalar."""
    from vtkmodules.vtkCommonDataModel import vtkImageData
    image = vtkImageData()
    image.SetDimensions(17, 17, 17)
    image.SetOrigin(-1, -1, -1)
    image.SetSpacing(0.125, 0.125, 0.125)
    values = vtkDoubleArray()
    values.SetName("field")
    for i in range(image.GetNumberOfPoints()):
        values.InsertNextValue(sum(g * x for g, x in zip(gradient, image.GetPoint(i))))
    image.GetPointData().SetScalars(values)
    mesh = analytic(6, distortion=vtkAnalyticMeshSource.JITTER)
    field = vtkDoubleArray()
    field.SetName("field")
    coordinates = vtkDoubleArray()
    coordinates.SetName("coordinates")
    coordinates.SetNumberOfComponents(3)
    for i in range(mesh.GetNumberOfPoints()):
        x = mesh.GetPoint(i)
        field.InsertNextValue(sum(g * c for g, c in zip(gradient, x)))
        coordinates.InsertNextTuple3(*[(c + 1.0) / 2.0 for c in x])
    mesh.GetPointData().SetScalars(field)
    mesh.GetPointData().SetTCoords(coordinates)
    return image, mesh


class TextureTests(SceneTestCase):
    def test_an_image_through_texture_coordinates(self):
        # A linear field read trilinearly from the image equals the mesh's own linear scalar; after the
        # mesh is deformed the image moves with it (the field stays attached to the points).
        image, mesh = linear_image_and_mesh()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(mesh)
        # The textured mesh shares the points but carries another scalar, which must not be drawn.
        carrier = vtkUnstructuredGrid()
        carrier.ShallowCopy(mesh)
        other = vtkDoubleArray()
        other.SetNumberOfTuples(mesh.GetNumberOfPoints())
        other.Fill(0.0)
        carrier.GetPointData().SetScalars(other)
        carrier.GetPointData().SetTCoords(mesh.GetPointData().GetTCoords())
        textured = shell_scene(carrier, prop, camera, 96, SampleDistance=0.02)
        textured.mapper.SetTextureImage(image)
        plain = shell_scene(mesh, prop, camera, 96, SampleDistance=0.02)
        first = copy_image(textured.render())
        error = rmse(first, plain.render())[0]
        print(f"\n  image against the mesh's own scalar: RMSE {error:.3g}", end="")
        self.assertLess(error, 1e-3)
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            points.SetPoint(i, x + 0.15 * math.sin(2.0 * y), y, z + 0.1 * x * y)
        points.Modified()
        carrier.Modified()
        moved = textured.render()
        self.assertGreater(rmse(moved, first)[0], 1e-2)  # the picture changed
        error = rmse(moved, plain.render())[0]
        print(f", deformed {error:.3g}", end="")
        self.assertLess(error, 1e-3)
        self.assertEqual(statistic(textured.mapper, "MeshBuilds"), 1)
        self.assertEqual(textured.events.errors + textured.events.warnings, 0)

    def test_what_an_image_cannot_do_is_a_warning(self):
        image, mesh = linear_image_and_mesh()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = shell_scene(mesh, prop, camera_for(mesh), 48, RenderMode=CELL_PROJECTION)
        scene.mapper.SetTextureImage(image)
        scene.mapper.AddIsosurface(0.2, 1, 1, 1, 1)
        self.assertTrue(finite_image(scene.render()))
        scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))
        # Without texture coordinates on the input: an error, nothing drawn.
        mesh.GetPointData().SetTCoords(None)
        scene = shell_scene(mesh, prop, camera_for(mesh), 48)
        scene.mapper.SetTextureImage(image)
        scene.render()
        self.assertEqual(scene.events.errors, 1)


class ShellBaselineTests(BaselineTestCase):
    def scene(self, mesh, prop, camera, size=256, props=(), **settings):
        return super().scene(mesh, prop, camera, size, props, mapper_class=vtkBarycentricShellMapper, **settings)

    def test_default_dataset(self):
        mesh = analytic(16, ML, vtkAnalyticMeshSource.TWIST)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = self.scene(mesh, prop, camera_for(mesh, distance=1.7))
        self.compare(scene.window, "barycentric_shells_twisted_perspective.png")

    def test_cell_projection(self):
        # Shaded volume (cell projection lights it with the vertex gradients) and a translucent
        # isosurface, every crossing of which is drawn in this mode.
        mesh = analytic(10, ML, vtkAnalyticMeshSource.JITTER)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.ShadeOn()
        prop.SetSpecular(0.3)
        prop.SetSpecularPower(16)
        scene = Scene(mesh, prop, camera_for(mesh, 20, 30), 256, mapper_class=vtkBarycentricShellMapper,
                      RenderMode=CELL_PROJECTION)
        scene.mapper.AddIsosurface(low + 0.4 * (high - low), 0.3, 0.9, 0.5, 0.35)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.mapper.SetKeepFloatImage(False)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.compare(scene.window, "barycentric_cell_projection_shaded.png")

    def test_isosurfaces_opaque_sphere_parallel(self):
        mesh = analytic(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetAmbient(0.2)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.4)
        prop.SetSpecularPower(20)
        actor = opaque_sphere(0.45, (0.4, -0.4, 0.3), 32, (0.8, 0.8, 0.3))
        scene = shell_scene(mesh, prop, camera_for(mesh, parallel=True), 256, (actor,))
        scene.mapper.AddIsosurface(low + 0.3 * (high - low), 0.2, 0.5, 1.0, 0.6)
        scene.mapper.AddIsosurface(low + 0.75 * (high - low), 1.0, 0.4, 0.2, 1.0)
        scene.renderer.SetBackground(0.1, 0.1, 0.12)
        scene.mapper.SetKeepFloatImage(False)
        scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.compare(scene.window, "barycentric_shells_isosurfaces_opaque_parallel.png")

    def test_super_phoenix(self):
        mesh = self.legacy(os.path.join("spx", "spx.vtk"), None)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
        scene = self.scene(mesh, prop, camera_for(mesh, 40, 20, distance=2.4))
        self.compare(scene.window, "barycentric_shells_spx_perspective.png")


class SkippingTests(SceneTestCase):
    def test_invisible_cells_are_in_no_shell(self):
        mesh = analytic(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        # Zero opacity over the lower 70%: those tetrahedra are in no shell, and the image is the same
        # as when they are drawn.
        opacity = prop.GetScalarOpacity()
        opacity.RemoveAllPoints()
        opacity.AddPoint(low + 0.7 * (high - low), 0.0)
        opacity.AddPoint(high, 0.8)
        scene = shell_scene(mesh, prop, camera_for(mesh), 96)
        skipped = copy_image(scene.render())
        drawn_visible = statistic(scene.mapper, "DrawnTetrahedra")
        scene.mapper.SkipInvisibleCellsOff()
        everything = scene.render()
        print(f"\n  tetrahedra drawn {drawn_visible} of {statistic(scene.mapper, 'DrawnTetrahedra')}", end="")
        self.assertLess(drawn_visible, 0.6 * statistic(scene.mapper, "DrawnTetrahedra"))
        # Where a visible cell meets a skipped one, the samples in the skipped one read as outside: a
        # half segment at the visible end instead of the pre-integrated whole (zero opacity there).
        self.assertLess(rmse(everything, skipped)[0], 2e-3)
        self.assertEqual(scene.events.errors, 0)

    def test_cell_projection_sorts_only_when_the_view_or_points_change(self):
        mesh = analytic(5)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = shell_scene(mesh, prop, camera_for(mesh), 48, RenderMode=CELL_PROJECTION)
        first = copy_image(scene.render())
        scene.render()
        self.assertEqual(statistic(scene.mapper, "Sorts"), 1)
        self.assertLess(rmse(scene.render(), first)[1], 1e-7)
        scene.renderer.GetActiveCamera().Azimuth(10)
        scene.render()
        self.assertEqual(statistic(scene.mapper, "Sorts"), 2)
        mesh.GetPoints().Modified()  # touched, not changed: the mapper compares content
        scene.render()
        self.assertEqual(statistic(scene.mapper, "Sorts"), 2)
        x, y, z = mesh.GetPoint(7)
        mesh.GetPoints().SetPoint(7, x + 0.01, y, z)
        mesh.GetPoints().Modified()
        scene.render()
        self.assertEqual(statistic(scene.mapper, "Sorts"), 3)

    def test_empty_shells_between_two_blobs_are_skipped(self):
        # Two small meshes far apart along the view: the shells between them hold nothing.
        from vtkmodules.vtkFiltersCore import vtkAppendFilter
        from vtkmodules.vtkCommonTransforms import vtkTransform
        from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
        near = analytic(4)
        shift = vtkTransform()
        shift.Translate(0, 20, 0)
        far = vtkTransformFilter()
        far.SetInputData(analytic(4))
        far.SetTransform(shift)
        append = vtkAppendFilter()
        append.AddInputData(near)
        append.AddInputConnection(far.GetOutputPort())
        append.Update()
        mesh = append.GetOutput()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        camera = camera_for(near, 0, 0)
        camera.SetClippingRange(0.01, 100)
        scene = shell_scene(mesh, prop, camera, 64, SampleDistance=0.05)
        scene.render()
        print(f"\n  shells drawn {statistic(scene.mapper, 'Shells')}, skipped {statistic(scene.mapper, 'SkippedShells')}",
              end="")
        self.assertGreater(statistic(scene.mapper, "SkippedShells"), statistic(scene.mapper, "Shells"))
        self.assertEqual(scene.events.errors, 0)

    def test_early_ray_termination(self):
        # Threshold 0: every pixel with any opacity is masked after its first shell, so less is drawn;
        # 0.99 (default) stays within a hundredth of no termination at all.
        mesh = analytic(10)
        low, high = mesh.GetPointData().GetScalars().GetRange()
        prop = uvrender.volume_property((low, high))
        prop.SetScalarOpacityUnitDistance(0.02)
        camera = camera_for(mesh)
        images = {}
        for threshold in (0.0, 0.99, 1.0):
            scene = shell_scene(mesh, prop, camera, 96, OpacityThreshold=threshold)
            images[threshold] = copy_image(scene.render())
            self.assertEqual(scene.events.errors, 0)
        self.assertLess(rmse(images[0.99], images[1.0])[1], 0.011)
        self.assertGreater(rmse(images[0.0], images[1.0])[1], 0.05)


class ChangeTrackingTests(SceneTestCase):
    def test_sample_distance_change_on_a_micrometre_mesh_rebuilds_the_segment_table(self):
        # A mesh a few micrometres across samples at distances of hundredths of a micrometre: the
        # segment table must follow a change of SampleDistance however small the distances are (it was
        # keyed by the distance printed to six decimals, 0.000000 for both, and kept integrating
        # segments of the old length).
        from vtkmodules.vtkCommonTransforms import vtkTransform
        from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
        scale = 1e-6
        shrink = vtkTransform()
        shrink.Scale(scale, scale, scale)
        tiny = vtkTransformFilter()
        tiny.SetInputData(analytic(6))
        tiny.SetTransform(shrink)
        tiny.Update()
        mesh = tiny.GetOutput()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        prop.SetScalarOpacityUnitDistance(0.2 * scale)
        camera = camera_for(mesh)
        camera.SetClippingRange(0.1 * mesh.GetLength(), 20 * mesh.GetLength())
        coarse, fine = mesh.GetLength() / 64, mesh.GetLength() / 128
        scene = shell_scene(mesh, prop, camera, 64, SampleDistance=coarse, SegmentIntegration=1)
        before = copy_image(scene.render())
        scene.mapper.SetSampleDistance(fine)
        changed = copy_image(scene.render())
        fresh = shell_scene(mesh, prop, camera, 64, SampleDistance=fine, SegmentIntegration=1).render()
        self.assertEqual(statistic(scene.mapper, "SegmentTableBuilds"), 2)
        self.assertGreater(rmse(before, fresh)[1], 1e-4)  # the distance matters to the image
        self.assertLess(rmse(changed, fresh)[1], 1e-6)  # the same as a mapper made for it
        self.assertEqual(scene.events.errors + scene.events.warnings, 0)


class ViewportTests(unittest.TestCase):
    def test_a_renderer_beside_another_in_the_window(self):
        # The mapper's passes clip to rectangles of its own image; the final blend into a renderer
        # whose viewport is not at the window's origin must land there, whole.
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkVolume, vtkWindowToImageFilter
        mesh = analytic(5)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())

        def grab(width, viewport):
            window = vtkRenderWindow()
            window.SetOffScreenRendering(1)
            window.SetMultiSamples(0)
            window.SetSize(width, 64)
            renderer = vtkRenderer()
            renderer.SetViewport(*viewport)
            renderer.SetBackground(0.2, 0.2, 0.2)
            mapper = vtkBarycentricShellMapper()
            mapper.SetInputData(mesh)
            volume = vtkVolume()
            volume.SetMapper(mapper)
            volume.SetProperty(prop)
            renderer.AddVolume(volume)
            renderer.SetActiveCamera(camera_for(mesh))
            window.AddRenderer(renderer)
            window.Render()
            capture = vtkWindowToImageFilter()
            capture.SetInput(window)
            capture.ReadFrontBufferOff()
            capture.Update()
            pixels = vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars()).reshape(64, width, -1)
            mapper.ReleaseGraphicsResources(window)
            return pixels[:, :, :3].astype(int)

        alone = grab(64, (0.0, 0.0, 1.0, 1.0))
        beside = grab(128, (0.5, 0.0, 1.0, 1.0))
        self.assertGreater(int((alone != 51).any(axis=2).sum()), 500)  # the volume covers pixels
        self.assertLessEqual(int(abs(beside[:, 64:] - alone).max()), 2)
        self.assertEqual(int(beside[:, :64].max() - beside[:, :64].min()), 0)  # nothing drawn left of it


class InputTests(TetrahedralInputChecks, SceneTestCase):
    def scene(self, mesh, prop=None, **settings):
        prop = prop or uvrender.volume_property((0.0, 1.0))
        return shell_scene(mesh, prop, camera_for(analytic(2)), 48, **settings)

    def test_hexahedra_are_split_with_one_warning(self):
        hexes = analytic(4, ML, 0, vtkAnalyticMeshSource.HEXAHEDRA)
        scene = self.scene(hexes, uvrender.volume_property(hexes.GetPointData().GetScalars().GetRange()))
        image = scene.render()
        scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))
        self.assertTrue(finite_image(image))

    def test_nan_scalars_leave_out_their_tetrahedra(self):
        mesh = analytic(4)
        scalars = mesh.GetPointData().GetScalars()
        scalars.SetValue(30, float("nan"))
        for mode in (SHELLS, CELL_PROJECTION):
            scene = self.scene(mesh, uvrender.volume_property(scalars.GetRange()), RenderMode=mode)
            image = scene.render()
            self.assertEqual(scene.events.errors, 0)
            self.assertEqual(scene.events.warnings, 1)
            self.assertTrue(finite_image(image))


class StressTests(SceneTestCase):
    def finite(self, mesh, prop, camera, size=96, **settings):
        scene = shell_scene(mesh, prop, camera, size, **settings)
        image = scene.render()
        self.assertEqual(scene.events.errors, 0)
        self.assertEqual(scene.window_events.errors, 0)
        self.assertTrue(finite_image(image))
        return image

    def test_slivers_and_flat_tetrahedra(self):
        mesh = analytic(5)
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            if abs(z - 0.2) < 1e-9:
                points.SetPoint(i, x, y, 0.2 + 1e-7 * x)
        points.SetPoint(40, *points.GetPoint(41))
        points.Modified()
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for mode in (SHELLS, CELL_PROJECTION):
            image = self.finite(mesh, prop, camera_for(mesh), RenderMode=mode)
            self.assertLess(rmse(image, reference(mesh, prop, camera_for(mesh), 96))[0], 5e-3)

    def test_edge_on_and_close_views_and_huge_offset(self):
        mesh = analytic(4)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        for camera in (camera_for(mesh, 0, 0), camera_for(mesh, 0, 0, parallel=True),
                       camera_for(mesh, 10, 5, distance=0.52)):
            for mode in (SHELLS, CELL_PROJECTION):
                self.finite(mesh, prop, camera, RenderMode=mode)
        expected = self.finite(mesh, prop, camera_for(mesh))
        points = mesh.GetPoints()
        for i in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(i)
            points.SetPoint(i, x + 1e6, y - 1e6, z + 1e6)
        points.Modified()
        shifted = self.finite(mesh, prop, camera_for(mesh))
        self.assertLess(rmse(shifted, expected)[0], 1e-3)

    def test_coincident_cells_add_their_media(self):
        # Every cell twice, as a mesh appended to itself: the optical model adds the copies' media. A
        # slice keeps one cell's value (MAX blend), so the copies were drawn once (stress,
        # "coincident cells drawn once"). They now merge into one cell of twice
        # the density, by position, so an append that repeats the points merges too. Both segment
        # routes; point and cell data.
        from vtkmodules.vtkFiltersCore import vtkAppendFilter
        for scalars in ("smooth", "cell_data"):
            single = stress.apply_scalars(analytic(4), {"scalars": scalars})
            case = {"function": "ramp", "camera": "outside"}
            prop, camera = stress.make_property(single, case), stress.make_camera(single, case)
            append = vtkAppendFilter()
            append.AddInputData(single)
            append.AddInputData(single)
            append.Update()
            twice = stress.apply_scalars(stress.every_cell_twice(analytic(4)), {"scalars": scalars})
            for doubled in (twice, append.GetOutput()):
                expected = reference(doubled, prop, camera, 48)
                self.assertGreater(rmse(reference(single, prop, camera, 48), expected)[0], 0.05)
                for integration in (1, 2):  # TABLE, EXACT
                    with self.subTest(scalars=scalars, points=doubled.GetNumberOfPoints(), integration=integration):
                        image = self.finite(doubled, prop, camera, 48, SegmentIntegration=integration)
                        self.assertLess(rmse(image, expected)[0], 5e-3)

    def test_eye_inside_a_tangled_hexahedral_grid(self):
        # The held-out check, remade: hexahedra split on the way, every cell twice and the
        # grid's middle node pushed through its neighbours (cells folding over each other), the eye
        # inside. The shells cover every pixel the reference covers, within the shells' sampling error.
        from fixtures import analytic_hexahedra
        mesh = analytic_hexahedra(5)
        bounds, points = mesh.GetBounds(), mesh.GetPoints()
        centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
        middle = min(range(points.GetNumberOfPoints()),
                     key=lambda i: sum((points.GetPoint(i)[a] - centre[a]) ** 2 for a in range(3)))
        x, y, z = points.GetPoint(middle)
        points.SetPoint(middle, x + 1.2 * (bounds[1] - bounds[0]) / 5, y, z)
        case = {"scalars": "smooth", "camera": "inside", "function": "ramp"}
        mesh = stress.apply_scalars(stress.every_cell_twice(mesh), case)
        prop, camera = stress.make_property(mesh, case), stress.make_camera(mesh, case)
        expected = reference(mesh, prop, camera, 48)
        scene = shell_scene(mesh, prop, camera, 48)
        image = scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))  # the split's warning
        truth, drawn = expected.GetPointData().GetScalars(), image.GetPointData().GetScalars()
        covered = [p for p in range(48 * 48) if truth.GetTuple4(p)[3] > 0.2]
        self.assertEqual([p for p in covered if drawn.GetTuple4(p)[3] < 0.1], [])
        self.assertLess(rmse(image, expected)[0], 5e-3)

    def test_tiny_sample_distance_is_widened_with_a_warning(self):
        mesh = analytic(4)
        prop = uvrender.volume_property(mesh.GetPointData().GetScalars().GetRange())
        scene = shell_scene(mesh, prop, camera_for(mesh), 32, SampleDistance=1e-6)
        image = scene.render()
        self.assertEqual((scene.events.errors, scene.events.warnings), (0, 1))
        self.assertGreater(statistic(scene.mapper, "SampleDistance"), 1e-6)
        self.assertTrue(finite_image(image))


if __name__ == "__main__":
    unittest.main()
