#include "vtkUnstructuredVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredVolumeMapper.h"
#include "vtkVolumeProperty.h"

vtkUnstructuredVolumeRepresentation::vtkUnstructuredVolumeRepresentation() = default;

vtkUnstructuredVolumeRepresentation::~vtkUnstructuredVolumeRepresentation()
{
  // The superclass still holds the mapper here.
  if (this->PinnedMapper)
  {
    this->PinnedMapper->RemoveObserver(this->ProgressObserver);
  }
}

void vtkUnstructuredVolumeRepresentation::PinMapper(const char* name, vtkUnstructuredVolumeMapper* mapper)
{
  this->MapperName = name;
  this->PinnedMapper = mapper;
  this->ProgressObserver = mapper->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkUnstructuredVolumeRepresentation::ForwardMapperProgress);
  this->AddVolumeMapper(name, mapper);
  this->Superclass::SetActiveVolumeMapper(name);
}

void vtkUnstructuredVolumeRepresentation::ForwardMapperProgress(vtkObject*, unsigned long, void* progress)
{
  this->UpdateProgress(*static_cast<double*>(progress));
}

void vtkUnstructuredVolumeRepresentation::SetUseOwnLevelOfDetail(bool own)
{
  if (this->UseOwnLevelOfDetail != own)
  {
    this->UseOwnLevelOfDetail = own;
    this->MarkModified();
  }
}

int vtkUnstructuredVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (request == vtkPVView::REQUEST_UPDATE_LOD() && this->UseOwnLevelOfDetail)
  {
    // No LOD geometry to build: an empty one is delivered, never drawn, and the interactive frames
    // are drawn where the data is (a client would hold only the LOD geometry).
    if (!this->vtkVolumeRepresentation::ProcessViewRequest(request, inInfo, outInfo))
    {
      return 0;
    }
    vtkNew<vtkPolyData> nothing;
    vtkPVView::SetPieceLOD(inInfo, this, nothing);
    vtkPVRenderView::SetRequiresDistributedRenderingLOD(inInfo, this, true);
    return 1;
  }
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_RENDER())
  {
    const bool levelOfDetail = inInfo->Has(vtkPVRenderView::USE_LOD()) != 0;
    this->PinnedMapper->SetAutoAdjustSampleDistances(levelOfDetail && this->UseOwnLevelOfDetail);
    if (this->UseOwnLevelOfDetail)
    {
      this->Actor->SetEnableLOD(0);
    }
  }
  return 1;
}

void vtkUnstructuredVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper(this->MapperName.c_str());
}

int vtkUnstructuredVolumeRepresentation::FillInputPortInformation(int port, vtkInformation* info)
{
  // Any dataset (the superclass takes unstructured grids and composites only).
  this->Superclass::FillInputPortInformation(port, info);
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
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

void vtkUnstructuredVolumeRepresentation::SetProjectionRoute(int route)
{
  this->PinnedMapper->SetProjectionRoute(route);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetSkipInvisibleCells(int skip)
{
  this->PinnedMapper->SetSkipInvisibleCells(skip != 0);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetTransferFunctionTolerance(double tolerance)
{
  this->PinnedMapper->SetTransferFunctionTolerance(tolerance);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetSegmentIntegration(int integration)
{
  this->PinnedMapper->SetSegmentIntegration(integration);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetVisibilityOrder(int order)
{
  this->PinnedMapper->SetVisibilityOrder(order);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetGradientMode(int mode)
{
  this->PinnedMapper->SetGradientMode(mode);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetOpacityThreshold(double threshold)
{
  this->PinnedMapper->SetOpacityThreshold(threshold);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::SetImageSampleDistance(double distance)
{
  this->PinnedMapper->SetImageSampleDistance(distance);
  this->MarkModified();
}

void vtkUnstructuredVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  // The mappers integrate one scalar along each ray (colour and opacity are functions of it); a
  // second, independent opacity field has no place in that integral. Said once, not ignored silently.
  if (this->UseSeparateOpacityArray && !this->SeparateOpacityWarned)
  {
    vtkWarningMacro(<< "Volume (" << this->MapperName << "): \"Use Separate Opacity Array\" is not supported "
                    << "(the ray integral takes one scalar); colour and opacity both follow the coloring array.");
  }
  this->SeparateOpacityWarned = this->UseSeparateOpacityArray;
  // Isosurfaces take the colour map's colour at their value, like ParaView's contours coloured by
  // the same array.
  this->PinnedMapper->RemoveAllIsosurfaces();
  vtkColorTransferFunction* colors = this->Property->GetRGBTransferFunction(0);
  for (double value : this->Isovalues)
  {
    double rgb[3] = { 1.0, 1.0, 1.0 };
    if (colors)
    {
      colors->GetColor(value, rgb);
    }
    this->PinnedMapper->AddIsosurface(value, rgb[0], rgb[1], rgb[2], this->IsosurfaceOpacity);
  }
}

void vtkUnstructuredVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->MapperName << "\n";
  os << indent << "Isovalues: " << this->Isovalues.size() << "\n";
  os << indent << "IsosurfaceOpacity: " << this->IsosurfaceOpacity << "\n";
}
