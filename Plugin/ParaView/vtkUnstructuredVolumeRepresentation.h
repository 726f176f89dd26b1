/**
 * @class vtkUnstructuredVolumeRepresentation
 * @brief ParaView's unstructured-grid volume representation, rendering with one of this project's
 * mappers.
 *
 * A vtkUnstructuredGridVolumeRepresentation (so: the same colour map and opacity editor, scalar
 * selection, "Use Separate Opacity Array", shading properties, multiblock handling, conversion of
 * structured and image data to tetrahedra, and ordered compositing in parallel) whose active mapper
 * is fixed to this project's vtkPreIntegratedTetrahedraMapper. Adding a mapper later means one more
 * representation proxy in Plugin/UnstructuredVolumeRepresentations.xml and one more case in
 * CreateMapper().
 */
#ifndef vtkUnstructuredVolumeRepresentation_h
#define vtkUnstructuredVolumeRepresentation_h

#include "vtkUnstructuredGridVolumeRepresentation.h"
#include "vtkUnstructuredVolumeParaViewModule.h" // for export macro

#include <vector> // for std::vector

class vtkPreIntegratedTetrahedraMapper;

class VTKUNSTRUCTUREDVOLUMEPARAVIEW_EXPORT vtkUnstructuredVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkUnstructuredVolumeRepresentation* New();
  vtkTypeMacro(vtkUnstructuredVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The inherited "SelectMapper" property must not switch away from this project's mapper.
  void SetActiveVolumeMapper(const char*) override;

  ///@{
  /// Forwarded to vtkPreIntegratedTetrahedraMapper.
  void SetIntegrationMode(int mode);
  void SetProjectionRoute(int route);
  void SetSkipInvisibleCells(int skip);
  ///@}

  ///@{
  /// Isosurfaces: values (any number), coloured by the colour map at their value, one opacity.
  void AddIsovalue(double value);
  void RemoveAllIsovalues();
  void SetIsosurfaceOpacity(double opacity);
  ///@}

protected:
  vtkUnstructuredVolumeRepresentation();
  ~vtkUnstructuredVolumeRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void UpdateMapperParameters() override;

  vtkPreIntegratedTetrahedraMapper* PreIntegratedMapper;
  std::vector<double> Isovalues;
  double IsosurfaceOpacity = 1.0;

private:
  vtkUnstructuredVolumeRepresentation(const vtkUnstructuredVolumeRepresentation&) = delete;
  void operator=(const vtkUnstructuredVolumeRepresentation&) = delete;
};

#endif
