#include "vtkUnstructuredVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include "uvPiecePartition.h"

#include <algorithm>
#include <map>
#include <vector>

namespace
{
/// The pieces each of this process's entries keeps where they are, by view. The view orders the
/// ranks by the box around everything kept on each, so an entry keeps its pieces only where those
/// boxes stay apart with its own added (another dataset split along another axis would not).
/// Every rank holds the same table: it is filled from gathered pieces in the same order.
using KeptPiecesByEntry = std::map<const vtkUnstructuredVolumeRepresentation*, std::vector<uv::RankPiece>>;
std::map<const vtkView*, KeptPiecesByEntry>& KeptPieces()
{
  static std::map<const vtkView*, KeptPiecesByEntry> kept;
  return kept;
}

void ForgetKeptPieces(const vtkUnstructuredVolumeRepresentation* entry)
{
  for (auto& view : KeptPieces())
  {
    view.second.erase(entry);
  }
}
}

vtkUnstructuredVolumeRepresentation::vtkUnstructuredVolumeRepresentation() = default;

vtkUnstructuredVolumeRepresentation::~vtkUnstructuredVolumeRepresentation()
{
  ForgetKeptPieces(this);
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

void vtkUnstructuredVolumeRepresentation::SetKeepRankPartitions(bool keep)
{
  if (this->KeepRankPartitions != keep)
  {
    this->KeepRankPartitions = keep;
    this->MarkModified();
  }
}

bool vtkUnstructuredVolumeRepresentation::PiecesFormPartition(vtkInformation* inInfo)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  double local[7] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 0.0 };
  vtkDataObject* piece = vtkPVView::GetPiece(inInfo, this);
  if (piece && vtkMath::AreBoundsInitialized(this->DataBounds))
  {
    std::copy(this->DataBounds, this->DataBounds + 6, local);
    local[6] = static_cast<double>(piece->GetNumberOfElements(vtkDataObject::CELL));
  }
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<double> all(7 * static_cast<std::size_t>(ranks));
  controller->AllGather(local, all.data(), 7);
  std::vector<uv::RankPiece> pieces(static_cast<std::size_t>(ranks));
  for (int rank = 0; rank < ranks; ++rank)
  {
    std::copy(all.begin() + 7 * rank, all.begin() + 7 * rank + 6, pieces[rank].Bounds);
    pieces[rank].Cells = all[7 * rank + 6];
  }
  KeptPiecesByEntry& kept = KeptPieces()[this->GetView()];
  kept.erase(this);
  std::vector<std::vector<uv::RankPiece>> others;
  for (const auto& other : kept)
  {
    others.push_back(other.second);
  }
  if (!uv::PiecesFormPartitionBeside(pieces, others))
  {
    return false;
  }
  kept[this] = pieces;
  return true;
}

bool vtkUnstructuredVolumeRepresentation::RemoveFromView(vtkView* view)
{
  ForgetKeptPieces(this);
  return this->Superclass::RemoveFromView(view);
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
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    // Every rank takes this pass for a visible representation, so the gather in
    // PiecesFormPartition is matched on all of them; a client has one process and skips it.
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    if (!controller || controller->GetNumberOfProcesses() < 2)
    {
      this->RankPartition = SINGLE_RANK;
    }
    else if (this->UseDataPartitions)
    {
      ForgetKeptPieces(this); // the user vouches for these pieces; they are not checked
      this->RankPartition = PIECES_KEPT; // the superclass has told the view
    }
    else if (this->KeepRankPartitions && this->PiecesFormPartition(inInfo))
    {
      vtkPVRenderView::SetOrderedCompositingConfiguration(
        inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION);
      this->RankPartition = PIECES_KEPT;
    }
    else
    {
      ForgetKeptPieces(this);
      this->RankPartition = REDISTRIBUTED;
    }
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
  os << indent << "KeepRankPartitions: " << this->KeepRankPartitions << "\n";
  static const char* const choices[] = { "single rank", "pieces kept", "redistributed" };
  os << indent << "RankPartition: " << choices[this->RankPartition] << "\n";
}
