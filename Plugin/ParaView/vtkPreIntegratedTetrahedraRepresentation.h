/**
 * @class vtkPreIntegratedTetrahedraRepresentation
 * @brief "Volume (Pre-integrated Tetrahedra)": ParaView's volume representation drawn by
 * vtkPreIntegratedTetrahedraMapper.
 *
 * Structured and image data, and other linear cells, reach the mapper as tetrahedra (ParaView's
 * volume preprocessing splits them), as for ParaView's own unstructured volume mappers.
 */
#ifndef vtkPreIntegratedTetrahedraRepresentation_h
#define vtkPreIntegratedTetrahedraRepresentation_h

#include "vtkNew.h" // for vtkNew
#include "vtkUnstructuredVolumeParaViewModule.h" // for export macro
#include "vtkUnstructuredVolumeRepresentation.h"

class vtkPreIntegratedTetrahedraMapper;

class VTKUNSTRUCTUREDVOLUMEPARAVIEW_EXPORT vtkPreIntegratedTetrahedraRepresentation
  : public vtkUnstructuredVolumeRepresentation
{
public:
  static vtkPreIntegratedTetrahedraRepresentation* New();
  vtkTypeMacro(vtkPreIntegratedTetrahedraRepresentation, vtkUnstructuredVolumeRepresentation);

  ///@{
  /// Forwarded to vtkPreIntegratedTetrahedraMapper.
  void SetIntegrationMode(int mode);
  void SetRenderMode(int mode);
  ///@}

protected:
  vtkPreIntegratedTetrahedraRepresentation();
  ~vtkPreIntegratedTetrahedraRepresentation() override;

  vtkNew<vtkPreIntegratedTetrahedraMapper> PreIntegratedMapper;

private:
  vtkPreIntegratedTetrahedraRepresentation(const vtkPreIntegratedTetrahedraRepresentation&) = delete;
  void operator=(const vtkPreIntegratedTetrahedraRepresentation&) = delete;
};

#endif
