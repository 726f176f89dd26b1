# The ParaView plugin: the UnstructuredVolume module plus its server-manager XML.
# Included from the staged plugin folder (see the root CMakeLists.txt).
paraview_add_plugin(UnstructuredVolume
  VERSION "${PROJECT_VERSION}"
  MODULES UnstructuredVolume::vtkUnstructuredVolume
  MODULE_FILES "${uv_staged_module_dir}/vtk.module"
  SERVER_MANAGER_XML "${UV_SOURCE_DIR}/Plugin/UnstructuredVolumeFilters.xml")
