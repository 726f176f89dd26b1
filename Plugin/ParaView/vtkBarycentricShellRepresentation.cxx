#include "vtkBarycentricShellRepresentation.h"

#include "vtkBarycentricShellMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkBarycentricShellRepresentation);

vtkBarycentricShellRepresentation::vtkBarycentricShellRepresentation()
{
  this->PinMapper("Barycentric shells", this->ShellMapper);
}

vtkBarycentricShellRepresentation::~vtkBarycentricShellRepresentation() = default;

void vtkBarycentricShellRepresentation::SetRenderMode(int mode)
{
  this->ShellMapper->SetRenderMode(mode);
  this->MarkModified();
}

void vtkBarycentricShellRepresentation::SetSampleDistance(double distance)
{
  this->ShellMapper->SetSampleDistance(distance);
  this->MarkModified();
}

void vtkBarycentricShellRepresentation::SetAutomaticSamplesAcross(int samples)
{
  this->ShellMapper->SetAutomaticSamplesAcross(samples);
  this->MarkModified();
}

void vtkBarycentricShellRepresentation::SetSlicesPerShell(int slices)
{
  this->ShellMapper->SetSlicesPerShell(slices);
  this->MarkModified();
}

void vtkBarycentricShellRepresentation::SetIsosurfaceLayers(int layers)
{
  this->ShellMapper->SetIsosurfaceLayers(layers);
  this->MarkModified();
}
