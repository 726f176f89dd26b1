# Sources of the Rendering half of the UnstructuredVolume module (included by the root CMakeLists.txt).
# The GLSL the mappers use is embedded from Shaders/ by the root CMakeLists.txt.
set(uv_rendering_classes
  vtkBarycentricShellMapper
  vtkHexahedralRayCastMapper
  vtkLocatorRayMarcher
  vtkPreIntegratedTetrahedraMapper
  vtkUnstructuredVolumeReferenceRenderer
  vtkVolumeImageErrorMetrics)
set(uv_rendering_sources)
set(uv_rendering_headers)
foreach (class IN LISTS uv_rendering_classes)
  list(APPEND uv_rendering_sources "${CMAKE_CURRENT_LIST_DIR}/${class}.cxx")
  list(APPEND uv_rendering_headers "${CMAKE_CURRENT_LIST_DIR}/${class}.h")
endforeach ()
# VTK-free math, unit-tested on its own, and the one VTK-reading helper the mappers share.
set(uv_rendering_private_headers
  "${CMAKE_CURRENT_LIST_DIR}/uvBarycentricShell.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvChebyshevSeries.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvHexahedronRay.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvImageErrorMetrics.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvIsosurfaceList.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvMapperOpenGL.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvOpticalModel.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvPreIntegration.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvProjectedTetrahedron.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvRayCellGeometry.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvTetrahedralMesh.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvTransferFunctionFromVolumeProperty.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvVisibilitySort.h")
