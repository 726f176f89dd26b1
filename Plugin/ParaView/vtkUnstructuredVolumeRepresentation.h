/**
 * @class vtkUnstructuredVolumeRepresentation
 * @brief ParaView's unstructured-grid volume representation, pinned to one of this project's mappers.
 *
 * A vtkUnstructuredGridVolumeRepresentation (so: the same colour map and opacity editor, scalar
 * selection, shading properties, multiblock handling and ordered compositing in parallel) whose
 * active mapper is fixed to the one a subclass pins in its constructor. "Use Separate Opacity
 * Array" draws a warning: the mappers integrate one scalar. Isosurfaces are kept here (values,
 * coloured by the colour map, one opacity) and handed to the mapper before each render.
 *
 * The pinned mapper is a vtkUnstructuredVolumeMapper, so what that base holds (isosurfaces, the
 * projection route) is forwarded here, once for all entries. Adding a mapper to the plugin: a
 * subclass that pins it and forwards its own settings, its proxy in
 * Plugin/UnstructuredVolumeRepresentations.xml and its row in Plugin/Representations.cmake (the
 * menu entries are generated from that table).
 */
#ifndef vtkUnstructuredVolumeRepresentation_h
#define vtkUnstructuredVolumeRepresentation_h

#include "vtkUnstructuredGridVolumeRepresentation.h"
#include "vtkUnstructuredVolumeParaViewModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class vtkUnstructuredVolumeMapper;

class VTKUNSTRUCTUREDVOLUMEPARAVIEW_EXPORT vtkUnstructuredVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  vtkAbstractTypeMacro(vtkUnstructuredVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The inherited "SelectMapper" property must not switch away from the pinned mapper.
  void SetActiveVolumeMapper(const char*) override;

  ///@{
  /// Isosurfaces: values (any number), coloured by the colour map at their value, one opacity.
  void AddIsovalue(double value);
  void RemoveAllIsovalues();
  void SetIsosurfaceOpacity(double opacity);
  ///@}

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetProjectionRoute); the XML exposes it
  /// only where the mapper projects tetrahedra.
  void SetProjectionRoute(int route);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetSkipInvisibleCells).
  void SetSkipInvisibleCells(int skip);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetOpacityThreshold).
  void SetOpacityThreshold(double threshold);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetImageSampleDistance).
  void SetImageSampleDistance(double distance);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetTransferFunctionTolerance).
  void SetTransferFunctionTolerance(double tolerance);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetSegmentIntegration).
  void SetSegmentIntegration(int integration);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetVisibilityOrder).
  void SetVisibilityOrder(int order);

  /// Forwarded to the mapper (vtkUnstructuredVolumeMapper::SetGradientMode).
  void SetGradientMode(int mode);

  ///@{
  /// Where ParaView renders interactively with level of detail (the data above the view's LOD
  /// threshold), draw the entry's own reduced image, sized to the time ParaView allows an
  /// interactive frame (vtkUnstructuredVolumeMapper::AutoAdjustSampleDistances), instead of
  /// ParaView's LOD, the mesh's surface (default on: the benchmark's paraview_interaction.py
  /// compares the two). Below the threshold, and in still renders, the entry draws its full image
  /// either way, so ParaView's LOD threshold keeps its meaning. On, the LOD geometry is not built,
  /// and interactive renders stay on the server.
  void SetUseOwnLevelOfDetail(bool own);
  vtkGetMacro(UseOwnLevelOfDetail, bool);
  ///@}

  ///@{
  /// On several ranks, render the ranks' pieces where they are when they already form a partition:
  /// each in its own box, no two boxes overlapping, none far above the average size, and the boxes
  /// still apart with those of the view's other entries that keep theirs, since the view orders
  /// each rank by the box around all of them (uv::PiecesFormPartitionBeside). ParaView's default
  /// moves cells to a k-d tree of its own on every change of the data, time steps included; pieces
  /// from a partitioned reader or a parallel source seldom need it. Otherwise (overlapping or unbalanced pieces) ParaView redistributes as
  /// before. Default on. The inherited SetUseDataPartitions (not a property of these entries:
  /// ParaView's own Volume holds that name) keeps the pieces whatever they are.
  void SetKeepRankPartitions(bool keep);
  vtkGetMacro(KeepRankPartitions, bool);
  /// What the last update chose: 0 one rank, 1 pieces kept, 2 ParaView redistributes.
  enum RankPartitionChoice
  {
    SINGLE_RANK = 0,
    PIECES_KEPT = 1,
    REDISTRIBUTED = 2
  };
  vtkGetMacro(RankPartition, int);
  ///@}

  /// Also forgets the pieces this entry kept in that view.
  bool RemoveFromView(vtkView* view) override;

  /// ParaView's passes; the superclass's, the ranks' partition and the level of detail above.
  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

protected:
  vtkUnstructuredVolumeRepresentation();
  ~vtkUnstructuredVolumeRepresentation() override;

  /// For subclasses' constructors: the mapper to render with, under a name. Its progress (mesh
  /// preparation) is reported as this representation's, which ParaView's progress bar shows.
  void PinMapper(const char* name, vtkUnstructuredVolumeMapper* mapper);
  void ForwardMapperProgress(vtkObject* mapper, unsigned long event, void* progress);

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void UpdateMapperParameters() override;
  /// Collective over the ranks: whether their pieces form a partition to render where they are.
  bool PiecesFormPartition(vtkInformation* inInfo);

  std::string MapperName;
  vtkUnstructuredVolumeMapper* PinnedMapper = nullptr;
  unsigned long ProgressObserver = 0;
  std::vector<double> Isovalues;
  double IsosurfaceOpacity = 1.0;
  bool SeparateOpacityWarned = false;
  bool UseOwnLevelOfDetail = true;
  bool KeepRankPartitions = true;
  int RankPartition = SINGLE_RANK;

private:
  vtkUnstructuredVolumeRepresentation(const vtkUnstructuredVolumeRepresentation&) = delete;
  void operator=(const vtkUnstructuredVolumeRepresentation&) = delete;
};

#endif
