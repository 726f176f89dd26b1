# Sources of the Filters half of the UnstructuredVolume module (included by the root CMakeLists.txt).
set(uv_filters_classes
  vtkAnalyticMeshSource
  vtkHexahedraToTetrahedra
  vtkHigherOrderSubdivision
  vtkVertexGradientFilter)
set(uv_filters_sources)
set(uv_filters_headers)
foreach (class IN LISTS uv_filters_classes)
  list(APPEND uv_filters_sources "${CMAKE_CURRENT_LIST_DIR}/${class}.cxx")
  list(APPEND uv_filters_headers "${CMAKE_CURRENT_LIST_DIR}/${class}.h")
endforeach ()
# VTK-free math, unit-tested on its own.
set(uv_filters_private_headers
  "${CMAKE_CURRENT_LIST_DIR}/uvAnalyticMesh.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvCellFamily.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvCellGradient.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvIsoparametricLattice.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvLinearCellSplit.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvPolyhedronSplit.h"
  "${CMAKE_CURRENT_LIST_DIR}/uvVertexCellLinks.h")
