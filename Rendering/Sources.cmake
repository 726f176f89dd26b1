# Sources of the Rendering half of the UnstructuredVolume module (included by the root CMakeLists.txt).
# One folder per layer; README.md's "Where things are" says what each holds. The GLSL the mappers use
# is embedded from Shaders/ by the root CMakeLists.txt.
set(uv_rendering_folders Core OpenGL Adapters Tetrahedra Hexahedra Shells Verification)

# Wrapped VTK classes: the mapper base, the three mappers and the verification tools.
set(uv_rendering_classes
  vtkUnstructuredVolumeMapper
  vtkUnstructuredVolumeFrameStatistics
  vtkUnstructuredVolumeTetrahedralMapper
  Tetrahedra/vtkPreIntegratedTetrahedraMapper
  Hexahedra/vtkHexahedralRayCastMapper
  Shells/vtkBarycentricShellMapper
  Verification/vtkLocatorRayMarcher
  Verification/vtkUnstructuredVolumeReferenceRenderer
  Verification/vtkVolumeImageErrorMetrics)
set(uv_rendering_sources)
set(uv_rendering_headers)
foreach (class IN LISTS uv_rendering_classes)
  list(APPEND uv_rendering_sources "${CMAKE_CURRENT_LIST_DIR}/${class}.cxx")
  list(APPEND uv_rendering_headers "${CMAKE_CURRENT_LIST_DIR}/${class}.h")
endforeach ()
# The float target has a source file of its own (the other OpenGL-layer classes are header-only).
list(APPEND uv_rendering_sources "${CMAKE_CURRENT_LIST_DIR}/OpenGL/vtkUnstructuredVolumeFloatTarget.cxx")

# Not wrapped: every other header of the layer folders (VTK-free uv*.h, vtkuv*.h adapters, the
# OpenGL layer, each mapper's passes and program catalogue).
set(uv_rendering_private_headers)
foreach (folder IN LISTS uv_rendering_folders)
  file(GLOB folder_headers CONFIGURE_DEPENDS "${CMAKE_CURRENT_LIST_DIR}/${folder}/*.h")
  foreach (header IN LISTS folder_headers)
    if (NOT header IN_LIST uv_rendering_headers)
      list(APPEND uv_rendering_private_headers "${header}")
    endif ()
  endforeach ()
endforeach ()
# The tetrahedral mappers' shared state, beside their base.
list(APPEND uv_rendering_private_headers "${CMAKE_CURRENT_LIST_DIR}/vtkUnstructuredVolumeTetrahedralState.h")
list(TRANSFORM uv_rendering_folders PREPEND "${CMAKE_CURRENT_LIST_DIR}/" OUTPUT_VARIABLE uv_rendering_include_dirs)
list(PREPEND uv_rendering_include_dirs "${CMAKE_CURRENT_LIST_DIR}")
