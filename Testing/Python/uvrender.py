"""Rendering helpers shared by the main job (render_default.py) and the Python image tests."""
import os

from vtkmodules.vtkCommonColor import vtkNamedColors  # noqa: F401  (registers colour names)
from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkCutter
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkDataSetMapper,
                                         vtkRenderWindow, vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL backend)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def volume_property(scalar_range):
    """A cool-to-warm colour map with a ramp of opacity over the scalar range."""
    low, high = scalar_range
    colors = vtkColorTransferFunction()
    colors.AddRGBPoint(low, 0.23, 0.30, 0.75)
    colors.AddRGBPoint(0.5 * (low + high), 0.87, 0.87, 0.87)
    colors.AddRGBPoint(high, 0.71, 0.02, 0.15)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low, 0.0)
    opacity.AddPoint(low + 0.3 * (high - low), 0.05)
    opacity.AddPoint(high, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(colors)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.2)
    prop.SetInterpolationTypeToLinear()
    return prop


def _window(size):
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.12)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    return renderer, window


def _frame(renderer):
    camera = renderer.GetActiveCamera()
    renderer.ResetCamera()
    camera.Azimuth(30)
    camera.Elevation(25)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()


def _boundary_wireframe(grid):
    """The grid's boundary faces as a faint wireframe, to show the mesh around what is drawn."""
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    mapper = vtkDataSetMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(0.15)
    actor.GetProperty().SetRepresentationToWireframe()
    return actor


def _render_scene(props, grid, size, path):
    """Renders the props inside the grid's boundary wireframe from the standard view; writes a PNG."""
    renderer, window = _window(size)
    for prop in props:
        renderer.AddViewProp(prop)
    renderer.AddActor(_boundary_wireframe(grid))
    _frame(renderer)
    window.Render()
    return write_png(window, path)


def write_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    return path


def _render_volume(mapper, mesh, scalar, path, size):
    """Volume-renders `mesh` by `mapper` with the standard property, view and boundary wireframe."""
    mesh.GetPointData().SetActiveScalars(scalar)
    mapper.SetInputData(mesh)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(volume_property(mesh.GetPointData().GetArray(scalar).GetRange()))
    return _render_scene([volume], mesh, size, path)


def render_projected_tetrahedra(tets, scalar, path, size=512):
    """Volume-renders a tetrahedral grid with VTK's vtkProjectedTetrahedraMapper."""
    return _render_volume(vtkProjectedTetrahedraMapper(), tets, scalar, path, size)


def render_preintegrated_tetrahedra(tets, scalar, path, size=512, isovalue=None):
    """Volume-renders a tetrahedral grid with this project's vtkPreIntegratedTetrahedraMapper, with a
    lit isosurface when `isovalue` is given."""
    from unstructuredvolume import vtkPreIntegratedTetrahedraMapper
    tets.GetPointData().SetActiveScalars(scalar)
    mapper = vtkPreIntegratedTetrahedraMapper()
    mapper.SetInputData(tets)
    if isovalue is not None:
        mapper.AddIsosurface(isovalue, 0.95, 0.85, 0.4, 0.7)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    prop = volume_property(tets.GetPointData().GetArray(scalar).GetRange())
    prop.SetSpecular(0.3)
    volume.SetProperty(prop)
    return _render_scene([volume], tets, size, path)


def render_barycentric_shells(tets, scalar, path, size=512):
    """Volume-renders a tetrahedral grid with this project's vtkBarycentricShellMapper (default shells)."""
    from unstructuredvolume import vtkBarycentricShellMapper
    return _render_volume(vtkBarycentricShellMapper(), tets, scalar, path, size)


def render_hexahedral_ray_cast(mesh, scalar, path, size=512):
    """Volume-renders a hexahedral grid with this project's vtkHexahedralRayCastMapper (no split)."""
    from unstructuredvolume import vtkHexahedralRayCastMapper
    return _render_volume(vtkHexahedralRayCastMapper(), mesh, scalar, path, size)


def render_gradient_cut(grid, gradients, path, size=512):
    """A cut through the grid coloured by |gradient|, over the grid's translucent boundary."""
    plane = vtkPlane()
    plane.SetOrigin(grid.GetCenter())
    plane.SetNormal(0.3, -0.4, 1.0)
    cut = vtkCutter()
    cut.SetInputData(grid)
    cut.SetCutFunction(plane)
    cut_mapper = vtkDataSetMapper()
    cut_mapper.SetInputConnection(cut.GetOutputPort())
    cut_mapper.SetScalarModeToUsePointFieldData()
    cut_mapper.SelectColorArray(gradients)
    cut.Update()
    magnitude_range = cut.GetOutput().GetPointData().GetArray(gradients).GetRange(-1)
    cut_mapper.SetScalarRange(magnitude_range)
    cut_mapper.GetLookupTable().SetVectorModeToMagnitude()
    cut_mapper.GetLookupTable().SetHueRange(0.66, 0.0)
    cut_actor = vtkActor()
    cut_actor.SetMapper(cut_mapper)
    return _render_scene([cut_actor], grid, size, path)
