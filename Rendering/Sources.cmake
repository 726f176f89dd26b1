# Sources of the Rendering half of the UnstructuredVolume module (included by the root CMakeLists.txt).
# The GLSL the mappers use is embedded from Shaders/ by the root CMakeLists.txt.
set(uv_rendering_classes
  vtkBarycentricShellMapper
  vtkHexahedralRayCastMapper
  vtkLocatorRayMarcher
  vtkPreIntegratedTetrahedraMapper
  vtkUnstructuredVolumeMapper
  vtkUnstructuredVolumeReferenceRenderer
  vtkVolumeImageErrorMetrics)
set(uv_rendering_sources)
set(uv_rendering_headers)
foreach (class IN LISTS uv_rendering_classes)
  list(APPEND uv_rendering_sources "${CMAKE_CURRENT_LIST_DIR}/${class}.cxx")
  list(APPEND uv_rendering_headers "${CMAKE_CURRENT_LIST_DIR}/${class}.h")
endforeach ()
# Not wrapped: VTK-free math (uv*.h, unit-tested on its own), the VTK-reading helpers the mappers
# share, the OpenGL layer under vtkUnstructuredVolumeMapper (vtkUnstructuredVolume*.h) and each
# mapper's passes and program catalogue (vtkBarycentricShell*.h, vtk*Programs.h).
set(uv_rendering_private_headers)
foreach (header IN ITEMS
    uvBarycentricShell uvCellVisibility uvChebyshevSeries uvCurvedCell uvLatticeBasis uvHexahedralMesh uvHexahedronRay uvVisibleRegion
    uvImageErrorMetrics
    uvIsosurfaceList uvNonConformingFaces uvOpticalModel uvPreIntegration uvProjectedTetrahedron uvRayCellGeometry uvShaderComposer
    uvCoincidentCells uvContentFingerprint uvMeshIntegrity uvFaceAdjacencyOrder uvScalarNormalisation uvScreenRectangle uvShellBuckets uvTetrahedronSegmentTable uvTransferFunctionSimplification uvVisibilitySort
    vtkHexahedralRayCastPrograms vtkPreIntegratedTetrahedraPrograms
    vtkPreIntegratedTetrahedraWalk uvTetrahedralWalk
    vtkBarycentricShellBlendPass vtkBarycentricShellCellDrawer vtkBarycentricShellCellProjectionPass
    vtkBarycentricShellImageTexture vtkBarycentricShellIsosurfacePeelPass vtkUnstructuredVolumeOpacityMask
    vtkBarycentricShellOpaqueDistancePass vtkBarycentricShellPrograms vtkBarycentricShellSegmentTable
    vtkBarycentricShellSlicePass
    vtkUnstructuredVolumeBufferTexture vtkUnstructuredVolumeCompatibility vtkUnstructuredVolumeFloatTarget vtkUnstructuredVolumeFrame
    vtkUnstructuredVolumeHexahedralMesh vtkUnstructuredVolumeIndexBuffer vtkUnstructuredVolumeMeshContent vtkUnstructuredVolumeMeshIntegrity vtkUnstructuredVolumeOpenGL
    vtkUnstructuredVolumePointData vtkUnstructuredVolumeTetrahedralMesh vtkUnstructuredVolumeTexture
    vtkUnstructuredVolumeTexture3D vtkUnstructuredVolumeSegmentLengthTable
    vtkUnstructuredVolumeTransferFunction vtkUnstructuredVolumeTransferFunctionTexture vtkUnstructuredVolumeVertexGradients)
  list(APPEND uv_rendering_private_headers "${CMAKE_CURRENT_LIST_DIR}/${header}.h")
endforeach ()
# The float target has a source file of its own (the other OpenGL-layer classes are header-only).
list(APPEND uv_rendering_sources "${CMAKE_CURRENT_LIST_DIR}/vtkUnstructuredVolumeFloatTarget.cxx")
