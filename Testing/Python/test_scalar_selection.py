"""Cell data and multi-component arrays, selected the VTK way, in the reference, the marcher and the
three mappers.

Cell data: the reference against vtkLocatorRayMarcher (told explicitly to sample the cell array; it
shares no selection code with the renderers) on generated meshes and on every real mesh with a cell
array in ../shared/data (skipped when absent), then each mapper against the reference. A cell
scalar is constant in each cell, so the marcher's uniform steps are first-order at the jumps
between cells: its own error is estimated as |I(N/2) - I(N)| and must stay below a quarter of the
bound.

Multi-component: a vector array whose magnitude, or whose component, is a known scalar must render
as that scalar does, in every renderer, when the colour function's vector mode selects it (VTK's
vtkScalarsToColors vector mode and component, which ParaView's "Magnitude" / "X" entries set)."""
import os
import random
import sys
import unittest
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402
import uvrender  # noqa: E402
from fixtures import (HexScene, Scene, SceneTestCase, analytic, analytic_hexahedra, camera_for,  # noqa: E402
                      copy_image, largest_difference, load_shared, march, rmse)

from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper,  # noqa: E402
                                vtkPreIntegratedTetrahedraMapper, vtkUnstructuredVolumeReferenceRenderer)
from vtkmodules.vtkCommonCore import vtkDoubleArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkPointDataToCellData, vtkThreshold  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkMeshQuality  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction  # noqa: E402

from unstructuredvolume import vtkHexahedraToTetrahedra  # noqa: E402

SIZE = 64
PIXELS = 600
STEPS = 8000
REFERENCE_BOUND = 2e-3  # reference against the marcher, largest difference in premultiplied RGBA
# Mappers against the reference (RMSE over the image): the tetrahedra mapper and cell projection
# integrate a constant exactly (their error is float and the visibility order), the hexahedral
# mapper integrates in float and stops rays at 0.999, the shells sample and miss the jumps between
# cells by up to a sample.
MAPPER_BOUNDS = {"preintegrated": 1e-3, "cell projection": 1e-3, "shells": 1e-2, "hexahedral": 2e-3}


def with_cell_data(mesh):
    """The mesh's point scalar averaged to its cells (vtkPointDataToCellData), the point data removed."""
    average = vtkPointDataToCellData()
    average.SetInputData(mesh)
    average.Update()
    cells = vtkUnstructuredGrid()
    cells.CopyStructure(average.GetOutput())
    cells.GetCellData().ShallowCopy(average.GetOutput().GetCellData())
    return cells


def cell_scene(mesh, array):
    prop = uvrender.volume_property(mesh.GetCellData().GetArray(array).GetRange())
    prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
    return prop, camera_for(mesh, 30, 25, distance=1.6)


def cell_reference(mesh, array, prop, camera):
    renderer = vtkUnstructuredVolumeReferenceRenderer()
    renderer.SetInputData(mesh)
    renderer.SetScalarModeToUseCellFieldData()
    renderer.SetScalarArrayName(array)
    renderer.SetVolumeProperty(prop)
    renderer.SetCamera(camera)
    renderer.SetImageSize(SIZE, SIZE)
    assert renderer.Render()
    return copy_image(renderer.GetOutput())


def sampled_pixels(mesh):
    chooser = random.Random(zlib.crc32(f"{mesh.GetNumberOfCells()} {mesh.GetLength():.9g}".encode()))
    return chooser.sample(range(SIZE * SIZE), PIXELS)


def generated_cell_meshes():
    return {"hexahedra": lambda: with_cell_data(analytic_hexahedra(6, distortion=vtkAnalyticMeshSource.TWIST)),
            "tetrahedra": lambda: with_cell_data(analytic(5, distortion=vtkAnalyticMeshSource.TWIST))}


class CellDataReferenceAgainstMarcher(unittest.TestCase):
    def check(self, mesh, array, steps=STEPS):
        prop, camera = cell_scene(mesh, array)
        image = cell_reference(mesh, array, prop, camera).GetPointData().GetScalars()
        pixels = sampled_pixels(mesh)
        fine = march(mesh, prop, camera, SIZE, pixels, steps, array, cells=True)
        coarse = march(mesh, prop, camera, SIZE, pixels, steps // 2, array, cells=True)
        truth = [image.GetTuple4(p) for p in pixels]
        covered = sum(1 for r in truth if r[3] > 1e-3)
        difference, marcher_error = largest_difference(truth, fine), largest_difference(fine, coarse)
        print(f"\n  {covered} of {PIXELS} pixels covered; largest difference {difference:.3g} "
              f"(bound {REFERENCE_BOUND}), marcher's own error {marcher_error:.2g}", end="")
        self.assertGreater(covered, 30)
        self.assertLess(marcher_error, REFERENCE_BOUND / 4)
        self.assertLess(difference, REFERENCE_BOUND)


for _name, _make in generated_cell_meshes().items():
    setattr(CellDataReferenceAgainstMarcher, f"test_{_name}",
            (lambda make: lambda self: self.check(make(), "MarschnerLobb"))(_make))
def untangled(mesh):
    """The hexahedra whose Jacobian keeps its sign (vtkMeshQuality's hexahedral Jacobian > 0). In a
    folded cell a point of space can be inside the cell twice, with two values of the field. Both
    renderers count such a point once per cell (the reference superposes cells, not a cell's
    sheets), but with different preimages: the reference takes the one Newton reaches from the
    cell's centre and misses stretches that end at a fold rather than at a face, the marcher's
    locator finds its own. On the can they differ there and agree without the folded cells, so the
    comparison leaves them out."""
    quality = vtkMeshQuality()
    quality.SetInputData(mesh)
    quality.SetHexQualityMeasureToJacobian()
    keep = vtkThreshold()
    keep.SetInputConnection(quality.GetOutputPort())
    keep.SetInputArrayToProcess(0, 0, 0, 1, "Quality")
    keep.SetThresholdFunction(vtkThreshold.THRESHOLD_UPPER)
    keep.SetUpperThreshold(1e-300)
    keep.Update()
    return keep.GetOutput()


# Per real mesh: what to take of it, and the marcher's steps (the can's thin walls need more).
PREPARE = {"can": (untangled, 2 * STEPS)}
for _name, _loader, _array in shared_data.CELL_DATA_MESHES:
    _prepare, _steps = PREPARE.get(_name, (lambda mesh: mesh, STEPS))
    setattr(CellDataReferenceAgainstMarcher, f"test_{_name}",
            (lambda loader, array, prepare, steps: lambda self: self.check(
                prepare(load_shared(self, loader)), array, steps))(_loader, _array, _prepare, _steps))


def cell_mapper_scene(kind, mesh, prop, camera, array):
    """A scene of one mapper set to render the cell array `array` (SetScalarModeToUseCellFieldData and
    SelectScalarArray, the VTK way)."""
    if kind == "hexahedral":
        scene = HexScene(mesh, prop, camera, SIZE)
    elif kind == "preintegrated":
        scene = Scene(mesh, prop, camera, SIZE, mapper_class=vtkPreIntegratedTetrahedraMapper)
    else:
        scene = Scene(mesh, prop, camera, SIZE, mapper_class=vtkBarycentricShellMapper,
                      RenderMode=(vtkBarycentricShellMapper.CELL_PROJECTION if kind == "cell projection"
                                  else vtkBarycentricShellMapper.SHELLS))
    scene.mapper.SetScalarModeToUseCellFieldData()
    scene.mapper.SelectScalarArray(array)
    return scene


def split(mesh):
    tetrahedra = vtkHexahedraToTetrahedra()
    tetrahedra.SetInputData(mesh)
    tetrahedra.Update()
    return tetrahedra.GetOutput()


class CellDataMappersAgainstReference(SceneTestCase):
    """The hexahedral mapper against the reference on the mesh itself; the tetrahedral mappers against
    the reference on the mesh split into tetrahedra, which is what they draw (on curved hexahedra the
    split's planar faces move the jumps between cells: that is the split's error, not a mapper's)."""

    def check(self, mesh, array, kinds):
        prop, camera = cell_scene(mesh, array)
        tetrahedra = split(mesh)
        expected = {"hexahedral": cell_reference(mesh, array, prop, camera),
                    "tetrahedra": cell_reference(tetrahedra, array, prop, camera)}
        for kind in kinds:
            drawn = "hexahedral" if kind == "hexahedral" else "tetrahedra"
            scene = cell_mapper_scene(kind, mesh if drawn == "hexahedral" else tetrahedra, prop, camera, array)
            error, worst = rmse(scene.render(), expected[drawn])
            print(f"\n  {kind}: RMSE {error:.3g} (bound {MAPPER_BOUNDS[kind]}), largest {worst:.3g}", end="")
            self.assertEqual(scene.events.errors, 0, kind)
            self.assertLess(error, MAPPER_BOUNDS[kind], kind)

    def test_generated_hexahedra(self):
        self.check(generated_cell_meshes()["hexahedra"](), "MarschnerLobb",
                   ["hexahedral", "preintegrated", "shells", "cell projection"])

    def test_generated_tetrahedra(self):
        self.check(generated_cell_meshes()["tetrahedra"](), "MarschnerLobb",
                   ["preintegrated", "shells", "cell projection"])

    def test_openfoam_cavity_pressure(self):
        self.check(load_shared(self, shared_data.openfoam_cavity_cells), "p",
                   ["hexahedral", "preintegrated", "shells", "cell projection"])

    def test_sample_struct_grid_cell_array_beside_a_point_array_of_the_same_name(self):
        mesh = load_shared(self, shared_data.sample_struct_grid)
        self.check(mesh, "scalars", ["hexahedral", "preintegrated", "cell projection"])

    def test_active_cell_scalars_render_without_any_setting(self):
        mesh = generated_cell_meshes()["tetrahedra"]()
        mesh.GetCellData().SetActiveScalars("MarschnerLobb")
        prop, camera = cell_scene(mesh, "MarschnerLobb")
        expected = cell_reference(mesh, "MarschnerLobb", prop, camera)
        scene = Scene(mesh, prop, camera, SIZE)  # default scalar mode: point scalars, else cell scalars
        error, _ = rmse(scene.render(), expected)
        self.assertEqual(scene.events.errors, 0)
        self.assertLess(error, MAPPER_BOUNDS["preintegrated"])

    def test_shells_draw_isosurfaces_of_cell_data_by_cell_projection_and_say_so_once(self):
        # (Every mapper against the reference: test_cell_data_isosurfaces.py.)
        mesh = split(generated_cell_meshes()["hexahedra"]())
        prop, camera = cell_scene(mesh, "MarschnerLobb")
        images = {}
        for kind in ("shells", "cell projection"):
            scene = cell_mapper_scene(kind, mesh, prop, camera, "MarschnerLobb")
            scene.mapper.AddIsosurface(0.5, 1, 1, 1, 0.5)
            images[kind] = copy_image(scene.render())
            scene.render()
            self.assertEqual(scene.events.errors, 0, kind)
            self.assertEqual(scene.events.warnings, 1 if kind == "shells" else 0, kind)
        self.assertLess(rmse(images["shells"], images["cell projection"])[1], 1e-6)
        self.assertGreater(rmse(images["shells"], cell_reference(mesh, "MarschnerLobb", prop, camera))[0], 1e-2)


# Multi-component arrays: "vector" = (0.6 s, 0.8 s, 0) over the scalar s, so |vector| = s, its
# component 0 is 0.6 s and its component 1 is 0.8 s.
def with_vector(mesh):
    scalar = mesh.GetPointData().GetScalars()
    vector = vtkDoubleArray()
    vector.SetName("vector")
    vector.SetNumberOfComponents(3)
    vector.SetNumberOfTuples(scalar.GetNumberOfTuples())
    for i in range(scalar.GetNumberOfTuples()):
        s = scalar.GetValue(i)
        vector.SetTuple3(i, 0.6 * s, 0.8 * s, 0.0)
    mesh.GetPointData().AddArray(vector)
    return mesh


def scaled_property(prop, factor, mode, component=0):
    """A copy of `prop` whose transfer function nodes sit at factor x their scalar, and whose colour
    function selects the magnitude or a component."""
    scaled = uvrender.volume_property((0, 1))
    colours, opacity = prop.GetRGBTransferFunction(0), prop.GetScalarOpacity(0)
    new_colours = vtkColorTransferFunction()
    for i in range(colours.GetSize()):
        node = [0.0] * 6
        colours.GetNodeValue(i, node)
        new_colours.AddRGBPoint(factor * node[0], node[1], node[2], node[3])
    new_opacity = scaled.GetScalarOpacity(0)
    new_opacity.RemoveAllPoints()
    for i in range(opacity.GetSize()):
        node = [0.0] * 4
        opacity.GetNodeValue(i, node)
        new_opacity.AddPoint(factor * node[0], node[1])
    if mode == "magnitude":
        new_colours.SetVectorModeToMagnitude()
    else:
        new_colours.SetVectorModeToComponent()
        new_colours.SetVectorComponent(component)
    scaled.SetColor(new_colours)
    scaled.SetScalarOpacityUnitDistance(prop.GetScalarOpacityUnitDistance())
    return scaled


class MultiComponentArrays(SceneTestCase):
    """Magnitude and component renders equal the scalar's render, within float rounding."""

    BOUND = 2e-5

    def setUp(self):
        self.mesh = with_vector(analytic_hexahedra(5, distortion=vtkAnalyticMeshSource.TWIST))
        self.prop = uvrender.volume_property(self.mesh.GetPointData().GetScalars().GetRange())
        self.prop.SetScalarOpacityUnitDistance(0.1)
        self.camera = camera_for(self.mesh)
        self.selections = {"magnitude": scaled_property(self.prop, 1.0, "magnitude"),
                           "component 1": scaled_property(self.prop, 0.8, "component", 1)}
        # Dependent components (ParaView's separate opacity array): the first is the scalar, whatever
        # the vector mode says.
        dependent = scaled_property(self.prop, 0.6, "magnitude")
        dependent.IndependentComponentsOff()
        self.selections["dependent, first component"] = dependent

    def renderers(self):
        tetrahedra = split(self.mesh)
        return [("hexahedral", self.mesh, lambda m, p: HexScene(m, p, self.camera, SIZE)),
                ("preintegrated", tetrahedra, lambda m, p: Scene(m, p, self.camera, SIZE)),
                ("shells", tetrahedra,
                 lambda m, p: Scene(m, p, self.camera, SIZE, mapper_class=vtkBarycentricShellMapper))]

    def test_every_mapper_renders_the_selected_magnitude_or_component(self):
        for kind, mesh, make in self.renderers():
            mesh.GetPointData().SetActiveScalars("MarschnerLobb")
            expected = copy_image(make(mesh, self.prop).render())
            for selection, prop in self.selections.items():
                scene = make(mesh, prop)
                scene.mapper.SetScalarModeToUsePointFieldData()
                scene.mapper.SelectScalarArray("vector")
                error, worst = rmse(scene.render(), expected)
                self.assertEqual(scene.events.errors, 0, (kind, selection))
                self.assertLess(worst, 10 * self.BOUND, (kind, selection))
                self.assertLess(error, self.BOUND, (kind, selection))

    def test_the_reference_renders_the_selected_magnitude_or_component(self):
        def render(prop, array):
            renderer = vtkUnstructuredVolumeReferenceRenderer()
            renderer.SetInputData(self.mesh)
            renderer.SetScalarArrayName(array)
            renderer.SetVolumeProperty(prop)
            renderer.SetCamera(self.camera)
            renderer.SetImageSize(SIZE, SIZE)
            self.assertTrue(renderer.Render())
            return copy_image(renderer.GetOutput())
        expected = render(self.prop, "MarschnerLobb")
        for selection, prop in self.selections.items():
            self.assertLess(rmse(render(prop, "vector"), expected)[1], 1e-6, selection)

    def test_the_marcher_agrees_with_the_reference_on_a_magnitude(self):
        prop = self.selections["magnitude"]
        renderer = vtkUnstructuredVolumeReferenceRenderer()
        renderer.SetInputData(self.mesh)
        renderer.SetScalarArrayName("vector")
        renderer.SetVolumeProperty(prop)
        renderer.SetCamera(self.camera)
        renderer.SetImageSize(SIZE, SIZE)
        self.assertTrue(renderer.Render())
        image = renderer.GetOutput().GetPointData().GetScalars()
        pixels = sampled_pixels(self.mesh)
        marched = march(self.mesh, prop, self.camera, SIZE, pixels, 2000, "vector", component=-1)
        self.assertLess(largest_difference([image.GetTuple4(p) for p in pixels], marched), REFERENCE_BOUND)

    def test_a_real_vector_array_by_its_magnitude(self):
        # The can's displacement: rendering DISPL by magnitude equals rendering |DISPL|.
        mesh = load_shared(self, shared_data.can)
        prop = uvrender.volume_property(mesh.GetPointData().GetArray("DISPL_magnitude").GetRange())
        prop.SetScalarOpacityUnitDistance(0.05 * mesh.GetLength())
        camera = camera_for(mesh, 30, 25, distance=1.6)
        mesh.GetPointData().SetActiveScalars("DISPL_magnitude")
        expected = copy_image(HexScene(mesh, prop, camera, SIZE).render())
        magnitude = scaled_property(prop, 1.0, "magnitude")
        scene = HexScene(mesh, magnitude, camera, SIZE)
        scene.mapper.SetScalarModeToUsePointFieldData()
        scene.mapper.SelectScalarArray("DISPL")
        self.assertLess(rmse(scene.render(), expected)[0], self.BOUND)


if __name__ == "__main__":
    unittest.main()
