"""UnstructuredVolume: direct volume rendering of unstructured meshes, for VTK's Python.

    from unstructuredvolume import vtkHexahedraToTetrahedra, vtkVertexGradientFilter
"""
# The wrapped classes derive from VTK's; import what they build on first.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingVolume  # noqa: F401

from .vtkUnstructuredVolume import *  # noqa: F401,F403
