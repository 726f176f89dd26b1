/**
 * @class vtkBarycentricShellRepresentation
 * @brief "Volume (Barycentric Shells)": ParaView's volume representation drawn by
 * vtkBarycentricShellMapper.
 *
 * Structured and image data, and other linear cells, reach the mapper as tetrahedra (ParaView's
 * volume preprocessing splits them). The mapper needs no preprocessing of its own, so time series
 * whose points move cost what a static mesh does.
 */
#ifndef vtkBarycentricShellRepresentation_h
#define vtkBarycentricShellRepresentation_h

#include "vtkNew.h" // for vtkNew
#include "vtkUnstructuredVolumeParaViewModule.h" // for export macro
#include "vtkUnstructuredVolumeRepresentation.h"

class vtkBarycentricShellMapper;

class VTKUNSTRUCTUREDVOLUMEPARAVIEW_EXPORT vtkBarycentricShellRepresentation
  : public vtkUnstructuredVolumeRepresentation
{
public:
  static vtkBarycentricShellRepresentation* New();
  vtkTypeMacro(vtkBarycentricShellRepresentation, vtkUnstructuredVolumeRepresentation);

  ///@{
  /// Forwarded to vtkBarycentricShellMapper.
  void SetRenderMode(int mode);
  void SetSampleDistance(double distance);
  void SetAutomaticSamplesAcross(int samples);
  void SetSlicesPerShell(int slices);
  void SetIsosurfaceLayers(int layers);
  ///@}

protected:
  vtkBarycentricShellRepresentation();
  ~vtkBarycentricShellRepresentation() override;

  vtkNew<vtkBarycentricShellMapper> ShellMapper;

private:
  vtkBarycentricShellRepresentation(const vtkBarycentricShellRepresentation&) = delete;
  void operator=(const vtkBarycentricShellRepresentation&) = delete;
};

#endif
