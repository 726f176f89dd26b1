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

void vtkPreIntegratedTetrahedraRepresentation::SetProjectionRoute(int route)
{
  this->PreIntegratedMapper->SetProjectionRoute(route);
  this->MarkModified();
}

void vtkPreIntegratedTetrahedraRepresentation::SetSkipInvisibleCells(int skip)
{
  this->PreIntegratedMapper->SetSkipInvisibleCells(skip != 0);
  this->MarkModified();
}

void vtkPreIntegratedTetrahedraRepresentation::ClearMapperIsosurfaces()
{
  this->PreIntegratedMapper->RemoveAllIsosurfaces();
}

void vtkPreIntegratedTetrahedraRepresentation::AddMapperIsosurface(double value, const double rgb[3], double opacity)
{
  this->PreIntegratedMapper->AddIsosurface(value, rgb[0], rgb[1], rgb[2], opacity);
}
