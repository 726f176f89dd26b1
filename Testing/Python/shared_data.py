"""Loaders for the real public meshes in ../shared/data (beside the repository), shared by the tests
and the benchmark. Each returns a vtkUnstructuredGrid, or raises FileNotFoundError when its file is
absent (tests skip then)."""
import math
import os

from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkArrayCalculator
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkIOGeometry import vtkOpenFOAMReader
from vtkmodules.vtkIOImage import vtkImageReader2, vtkSLCReader
from vtkmodules.vtkIOLegacy import vtkDataSetReader
from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader, vtkXMLUnstructuredGridReader

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.path.abspath(os.path.join(ROOT, "..", "shared", "data"))


def path(*parts):
    found = os.path.join(SHARED, *parts)
    if not os.path.exists(found):
        raise FileNotFoundError(found)
    return found


def _unstructured(algorithm):
    """An algorithm's output as a vtkUnstructuredGrid."""
    to_grid = vtkAppendFilter()
    to_grid.SetInputConnection(algorithm.GetOutputPort())
    to_grid.Update()
    return to_grid.GetOutput()


def bluntfin():
    """NASA's Blunt Fin (PLOT3D), 40 x 32 x 32 points of curvilinear hexahedra; "Density" and more."""
    reader = vtkXMLStructuredGridReader()
    reader.SetFileName(path("bluntfin", "bluntfin.vts"))
    return _unstructured(reader)


def disk_out_ref():
    """ParaView's disk_out_ref (Exodus II) hexahedra, blocks merged; "Temp" and more."""
    reader = vtkExodusIIReader()
    reader.SetFileName(path("disk_out_ref", "disk_out_ref.ex2"))
    reader.UpdateInformation()
    reader.SetAllArrayStatus(vtkExodusIIReader.NODAL, 1)
    reader.Update()
    merge = vtkAppendFilter()
    merge.MergePointsOn()
    iterator = reader.GetOutput().NewTreeIterator()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        merge.AddInputData(iterator.GetCurrentDataObject())
        iterator.GoToNextItem()
    merge.Update()
    return merge.GetOutput()


def can():
    """The crushed can's hexahedra with |DISPL| as the point scalar "DISPL_magnitude"."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path("can", "can.vtu"))
    magnitude = vtkArrayCalculator()
    magnitude.SetInputConnection(reader.GetOutputPort())
    magnitude.AddVectorArrayName("DISPL")
    magnitude.SetFunction("mag(DISPL)")
    magnitude.SetResultArrayName("DISPL_magnitude")
    magnitude.Update()
    return magnitude.GetOutput()


def legacy(*parts):
    """A legacy .vtk file of any dataset type (every scalar and field read) as an unstructured grid."""
    reader = vtkDataSetReader()
    reader.ReadAllScalarsOn()
    reader.ReadAllFieldsOn()
    reader.SetFileName(path(*parts))
    return _unstructured(reader)


def _with_smooth_field(mesh):
    """Meshes that carry no point scalar get a smooth one of position, "field"."""
    low = [mesh.GetBounds()[2 * d] for d in range(3)]
    size = max(mesh.GetLength(), 1e-30)
    field = vtkDoubleArray()
    field.SetName("field")
    for i in range(mesh.GetNumberOfPoints()):
        x, y, z = ((c - o) / size for c, o in zip(mesh.GetPoint(i), low))
        field.InsertNextValue(math.sin(4.0 * x) + math.cos(3.0 * y) + z)
    mesh.GetPointData().AddArray(field)
    return mesh


def office():
    """A curvilinear structured grid (air flow in an office), 7220 hexahedra; "scalars"."""
    return legacy("office", "office.binary.vtk")


def sample_struct_grid():
    """VTK's SampleStructGrid: a curvilinear grid of 21489 hexahedra; "scalars"."""
    return legacy("sample_struct_grid", "SampleStructGrid.vtk")


def _openfoam_cavity(cell_to_point):
    reader = vtkOpenFOAMReader()
    reader.SetFileName(path("openfoam_cavity", "cavity", "case.foam"))
    reader.SetCreateCellToPoint(cell_to_point)
    reader.UpdateInformation()
    steps = reader.GetTimeValues()
    reader.UpdateTimeStep(steps.GetValue(steps.GetNumberOfTuples() - 1))
    reader.Update()
    return reader.GetOutput().GetBlock(0)  # the internal mesh, an unstructured grid


def openfoam_cavity_points():
    """The OpenFOAM cavity's internal mesh (400 hexahedra) at its last time step, its cell data
    averaged to the points by the reader; "p"."""
    return _openfoam_cavity(1)


def openfoam_cavity_cells():
    """The OpenFOAM cavity's internal mesh (400 hexahedra) at its last time step with its data as
    OpenFOAM writes it, per cell; "p" (scalar) and "U" (vector)."""
    return _openfoam_cavity(0)


def bucky():
    """NVIDIA's 32^3 uint8 Bucky ball as 29791 voxels; "density"."""
    return image_as_voxels(bucky_image())


def bucky_image():
    """NVIDIA's 32^3 uint8 Bucky ball as image data; "density"."""
    reader = vtkImageReader2()
    reader.SetFileName(path("bucky", "Bucky_32x32x32_uint8.raw"))
    reader.SetDataScalarTypeToUnsignedChar()
    reader.SetNumberOfScalarComponents(1)
    reader.SetDataExtent(0, 31, 0, 31, 0, 31)
    reader.SetFileDimensionality(3)
    reader.Update()
    reader.GetOutput().GetPointData().GetScalars().SetName("density")
    return reader.GetOutput()


def neghip_image():
    """The negative-potential high-protein volume (SLC), 66^3 uint8 points as image data; "density"."""
    reader = vtkSLCReader()
    reader.SetFileName(path("neghip", "neghip.slc"))
    reader.Update()
    reader.GetOutput().GetPointData().GetScalars().SetName("density")
    return reader.GetOutput()


def image_as_voxels(image):
    """Image data as a vtkUnstructuredGrid of voxels."""
    to_grid = vtkAppendFilter()
    to_grid.SetInputData(image)
    to_grid.Update()
    return to_grid.GetOutput()


def xml_grid(*parts):
    """A .vtu file of ../shared/data."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path(*parts))
    reader.Update()
    return reader.GetOutput()


# Every real mesh the reference renders with a point scalar: name, loader, scalar. The higher-order
# meshes are in HIGHER_ORDER_MESHES, the cell data in CELL_DATA_MESHES.
REFERENCE_MESHES = [
    ("blunt_fin", bluntfin, "Density"),
    ("super_phoenix", lambda: legacy("spx", "spx.vtk"), "scalars"),
    ("lox_post", lambda: legacy("lox_post", "post.vtk"), "Pressure"),
    ("disk_out_ref", disk_out_ref, "Temp"),
    ("can", can, "DISPL_magnitude"),
    ("hexa", lambda: legacy("hexa", "hexa.vtk"), "scalars"),
    ("office", office, "scalars"),
    ("sample_struct_grid", sample_struct_grid, "scalars"),
    ("tetra_mesh", lambda: legacy("tetraMesh", "tetraMesh.vtk"), "scalars"),
    ("ugrid_ex", lambda: legacy("uGridEx", "uGridEx.vtk"), "scalars"),
    ("cylinder_linear", lambda: legacy("quadratic", "CylinderLinear.vtk"), "vel_norm"),
    ("openfoam_cavity", openfoam_cavity_points, "p"),
    ("bucky", bucky, "density"),
] + [(f"mfem_{name}", (lambda name=name: _with_smooth_field(legacy("mfem_small", f"{name}.vtk"))), "field")
     for name in ("beam-hex", "beam-tet", "beam-wedge", "escher", "fichera")]

# Every real mesh with a cell scalar: name, loader, the cell array (SampleStructGrid has a point and a
# cell array both named "scalars").
CELL_DATA_MESHES = [
    ("openfoam_cavity", openfoam_cavity_cells, "p"),
    ("can", can, "EQPS"),
    ("sample_struct_grid", sample_struct_grid, "scalars"),
]

# Every real mesh of higher-order cells: name, loader, point scalar. The triquadratic hexahedra and
# the mixed quadratic Fichera corner carry only a cell array, "material", and get the smooth "field".
HIGHER_ORDER_MESHES = [
    ("cylinder_quadratic", lambda: legacy("quadratic", "CylinderQuadratic.vtk"), "velocity_norm"),
    ("quadratic_tetra", lambda: xml_grid("quadratic", "QuadraticTetra.vtu"), "Polynomial"),
    ("triquadratic_hexahedron", lambda: _with_smooth_field(xml_grid("quadratic", "TriQuadraticHexahedron.vtu")),
     "field"),
    ("fichera_mixed_p2", lambda: _with_smooth_field(legacy("mfem_small", "fichera-mixed-p2.vtk")), "field"),
]
