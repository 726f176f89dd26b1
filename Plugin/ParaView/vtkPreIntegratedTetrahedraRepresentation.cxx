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

void vtkPreIntegratedTetrahedraRepresentation::SetSkipInvisibleCells(int skip)
{
  this->PreIntegratedMapper->SetSkipInvisibleCells(skip != 0);
  this->MarkModified();
}
