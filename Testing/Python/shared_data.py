"""Loaders for the real public meshes in ../shared/data (beside the repository), shared by the tests
and the benchmark. Each returns a vtkUnstructuredGrid, or raises FileNotFoundError when its file is
absent (tests skip then)."""
import os

from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkArrayCalculator
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader, vtkXMLUnstructuredGridReader

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.path.abspath(os.path.join(ROOT, "..", "shared", "data"))


def path(*parts):
    found = os.path.join(SHARED, *parts)
    if not os.path.exists(found):
        raise FileNotFoundError(found)
    return found


def bluntfin():
    """NASA's Blunt Fin (PLOT3D), 40 x 32 x 32 points of curvilinear hexahedra; "Density" and more."""
    reader = vtkXMLStructuredGridReader()
    reader.SetFileName(path("bluntfin", "bluntfin.vts"))
    to_grid = vtkAppendFilter()
    to_grid.SetInputConnection(reader.GetOutputPort())
    to_grid.Update()
    return to_grid.GetOutput()


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
    """A legacy .vtk unstructured grid, every scalar and field read."""
    reader = vtkUnstructuredGridReader()
    reader.ReadAllScalarsOn()
    reader.ReadAllFieldsOn()
    reader.SetFileName(path(*parts))
    reader.Update()
    return reader.GetOutput()
