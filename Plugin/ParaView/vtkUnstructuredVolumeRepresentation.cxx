#include "vtkUnstructuredVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPreIntegratedTetrahedraMapper.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(vtkUnstructuredVolumeRepresentation);

namespace
{
constexpr const char* MapperName = "Pre-integrated tetrahedra";
}

vtkUnstructuredVolumeRepresentation::vtkUnstructuredVolumeRepresentation()
{
  this->PreIntegratedMapper = vtkPreIntegratedTetrahedraMapper::New();
  this->AddVolumeMapper(MapperName, this->PreIntegratedMapper);
  this->Superclass::SetActiveVolumeMapper(MapperName);
}

vtkUnstructuredVolumeRepresentation::~vtkUnstructuredVolumeRepresentation()
{
  this->PreIntegratedMapper->Delete();
}

void vtkUnstructuredVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper(MapperName);
}

int vtkUnstructuredVolumeRepresentation::FillInputPortInformation(int port, vtkInformation* info)
{
  // Any dataset: the superclass's preprocessor tetrahedralises structured and image data.
  this->Superclass::FillInputPortInformation(port, info);
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

void vtkUnstructuredVolumeRepresentation::SetIntegrationMode(int mode)
{
  this->PreIntegratedMapper->SetIntegrationMode(mode);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetProjectionRoute(int route)
{
  this->PreIntegratedMapper->SetProjectionRoute(route);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetSkipInvisibleCells(int skip)
{
  this->PreIntegratedMapper->SetSkipInvisibleCells(skip != 0);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::AddIsovalue(double value)
{
  this->Isovalues.push_back(value);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::RemoveAllIsovalues()
{
  this->Isovalues.clear();
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetIsosurfaceOpacity(double opacity)
{
  this->IsosurfaceOpacity = opacity;
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  // Isosurfaces take the colour map's colour at their value, like ParaView's contours coloured by
  // the same array.
  this->PreIntegratedMapper->RemoveAllIsosurfaces();
  vtkColorTransferFunction* colors = this->Property->GetRGBTransferFunction(0);
  for (double value : this->Isovalues)
  {
    double rgb[3] = { 1.0, 1.0, 1.0 };
    if (colors)
    {
      colors->GetColor(value, rgb);
    }
    this->PreIntegratedMapper->AddIsosurface(value, rgb[0], rgb[1], rgb[2], this->IsosurfaceOpacity);
  }
}

void vtkUnstructuredVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Isovalues: " << this->Isovalues.size() << "\n";
  os << indent << "IsosurfaceOpacity: " << this->IsosurfaceOpacity << "\n";
}
