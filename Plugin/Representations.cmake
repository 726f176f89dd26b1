# The Representation-menu entries, one per representation proxy of
# Plugin/UnstructuredVolumeRepresentations.xml, in menu order. Plugin/Plugin.cmake generates the menu
# from this table and stops the configure step when the table and the proxies disagree.
#
#   PROXY       the proxy's name in the XML
#   MENU        the entry's text in the Representation menu (what scripts assign to Representation)
#   GROUP       the Properties-panel section for the settings only this entry has
#   PROPERTIES  every property of the proxy but Input, in panel order
#   UNSHARED    optional pairs "property name-in-panel" for a property that keeps a name of its own
#
# All entries live on one composite proxy (ParaView's data representation), so a property name
# appears there once: a name several entries list is one setting for all of them (the first entry's
# property, copied to the others), which requires identical definitions in the XML, and it is shown
# in the section UV_SHARED_PANEL_GROUP names. A property with the same name but its own choices or
# default per entry is listed under UNSHARED instead.
set(UV_SHARED_PANEL_GROUP "Unstructured Volume")

uv_representation_entry(
  PROXY PreIntegratedTetrahedraRepresentation
  MENU "Volume (Pre-integrated Tetrahedra)"
  GROUP "Pre-integrated Tetrahedra"
  PROPERTIES IntegrationMode Isovalues IsosurfaceOpacity SkipInvisibleCells TransferFunctionTolerance SegmentIntegration
    VisibilityOrder OpacityThreshold ProjectionRoute RenderMode ImageSampleDistance UseOwnLevelOfDetail
    KeepRankPartitions
  # The shells' RenderMode chooses between shells and cell projection.
  UNSHARED OpacityThreshold TetrahedraOpacityThreshold RenderMode TetrahedraRenderMode)

uv_representation_entry(
  PROXY BarycentricShellRepresentation
  MENU "Volume (Barycentric Shells)"
  GROUP "Barycentric Shells"
  PROPERTIES RenderMode SampleDistance AutomaticSamplesAcross Isovalues IsosurfaceOpacity SkipInvisibleCells
    TransferFunctionTolerance SlicesPerShell OpacityThreshold IsosurfaceLayers SegmentIntegration VisibilityOrder ProjectionRoute
    GradientMode ImageSampleDistance UseOwnLevelOfDetail
    KeepRankPartitions
  # The shells stop at 0.999, the hexahedral rays at 0.99: one shared value would change one default.
  UNSHARED OpacityThreshold ShellOpacityThreshold)

uv_representation_entry(
  PROXY HexahedralRayCastRepresentation
  MENU "Volume (Hexahedral Ray Cast)"
  GROUP "Hexahedral Ray Cast"
  PROPERTIES IntegrationMode FixedSteps Isovalues IsosurfaceOpacity SkipInvisibleCells TransferFunctionTolerance OpacityThreshold MaximumPeels
    ExactSegmentEnds GradientMode ImageSampleDistance UseOwnLevelOfDetail
    KeepRankPartitions
  # Accurate / Fast / Fixed steps, not the tetrahedra's average scalar / partial pre-integration.
  UNSHARED IntegrationMode HexahedralIntegrationMode)
