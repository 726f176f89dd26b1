# The ParaView plugin: the UnstructuredVolume module plus its server-manager XML.
# Included from the staged plugin folder (see the root CMakeLists.txt).
# The module UnstructuredVolume::vtkUnstructuredVolumeParaView (Plugin/ParaView) holds the ParaView
# representations over the mappers; it exists only in this build.
paraview_add_plugin(UnstructuredVolume
  VERSION "${PROJECT_VERSION}"
  MODULES UnstructuredVolume::vtkUnstructuredVolume UnstructuredVolume::vtkUnstructuredVolumeParaView
  MODULE_FILES "${uv_staged_module_dir}/vtk.module" "${UV_SOURCE_DIR}/Plugin/ParaView/vtk.module"
  SERVER_MANAGER_XML
    "${UV_SOURCE_DIR}/Plugin/UnstructuredVolumeFilters.xml"
    "${UV_SOURCE_DIR}/Plugin/UnstructuredVolumeRepresentations.xml")
