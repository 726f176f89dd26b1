/**
 * @class vtkHexahedralRayCastRepresentation
 * @brief "Volume (Hexahedral Ray Cast)": ParaView's volume representation drawn by
 * vtkHexahedralRayCastMapper, with the hexahedra kept whole.
 *
 * ParaView's unstructured volume preprocessing splits every cell into tetrahedra; this
 * representation replaces it: unstructured grids pass as they are, structured grids become
 * hexahedra and image/rectilinear data voxels (vtkAppendFilter), and multiblock data is merged
 * (vtkMergeBlocks, coincident points merged so blocks connect). Everything else -- colour map,
 * opacity editor, shading, delivery and ordered compositing in parallel -- is the superclass's.
 */
#ifndef vtkHexahedralRayCastRepresentation_h
#define vtkHexahedralRayCastRepresentation_h

#include "vtkNew.h"          // for vtkNew
#include "vtkUnstructuredVolumeParaViewModule.h" // for export macro
#include "vtkUnstructuredVolumeRepresentation.h"

class vtkHexahedralRayCastMapper;

class VTKUNSTRUCTUREDVOLUMEPARAVIEW_EXPORT vtkHexahedralRayCastRepresentation
  : public vtkUnstructuredVolumeRepresentation
{
public:
  static vtkHexahedralRayCastRepresentation* New();
  vtkTypeMacro(vtkHexahedralRayCastRepresentation, vtkUnstructuredVolumeRepresentation);

  ///@{
  /// Forwarded to vtkHexahedralRayCastMapper.
  void SetIntegrationMode(int mode);
  void SetFixedSteps(int steps);
  void SetMaximumPeels(int peels);
  void SetExactSegmentEnds(int exact);
  ///@}

protected:
  vtkHexahedralRayCastRepresentation();
  ~vtkHexahedralRayCastRepresentation() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkNew<vtkHexahedralRayCastMapper> HexahedralMapper;

private:
  vtkHexahedralRayCastRepresentation(const vtkHexahedralRayCastRepresentation&) = delete;
  void operator=(const vtkHexahedralRayCastRepresentation&) = delete;
};

#endif
