#include "vtkPreIntegratedTetrahedraRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPreIntegratedTetrahedraMapper.h"

vtkStandardNewMacro(vtkPreIntegratedTetrahedraRepresentation);

vtkPreIntegratedTetrahedraRepresentation::vtkPreIntegratedTetrahedraRepresentation()
{
  this->PinMapper("Pre-integrated tetrahedra", this->PreIntegratedMapper);
}

vtkPreIntegratedTetrahedraRepresentation::~vtkPreIntegratedTetrahedraRepresentation() = default;

void vtkPreIntegratedTetrahedraRepresentation::SetIntegrationMode(int mode)
{
  this->PreIntegratedMapper->SetIntegrationMode(mode);
  this->MarkModified();
}

void vtkPreIntegratedTetrahedraRepresentation::SetRenderMode(int mode)
{
  this->PreIntegratedMapper->SetRenderMode(mode);
  this->MarkModified();
}
