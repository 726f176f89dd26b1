#include "vtkHexahedralRayCastRepresentation.h"

#include "vtkAppendFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkHexahedralRayCastMapper.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMergeBlocks.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeRepresentationPreprocessor.h"

vtkStandardNewMacro(vtkHexahedralRayCastRepresentation);

vtkHexahedralRayCastRepresentation::vtkHexahedralRayCastRepresentation()
{
  this->PinMapper("Hexahedral ray cast", this->HexahedralMapper);
}

vtkHexahedralRayCastRepresentation::~vtkHexahedralRayCastRepresentation() = default;

int vtkHexahedralRayCastRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Not the superclass's preprocessing, which splits every cell into tetrahedra: its preprocessor
  // runs on an empty grid, and its output then takes the hexahedra (the superclass delivers that
  // output to the view: redistribution and ordered compositing work on the hexahedra).
  vtkMath::UninitializeBounds(this->DataBounds);
  vtkNew<vtkUnstructuredGrid> hexahedra; // this rank's input as one grid, cells unsplit
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    vtkSmartPointer<vtkAlgorithm> convert;
    if (vtkCompositeDataSet::SafeDownCast(input))
    {
      auto merge = vtkSmartPointer<vtkMergeBlocks>::New();
      merge->MergePointsOn(); // blocks sharing a face connect there
      convert = merge;
    }
    else
    {
      convert = vtkSmartPointer<vtkAppendFilter>::New(); // hexahedra and voxels stay whole
    }
    convert->SetInputConnection(this->GetInternalOutputPort());
    convert->Update();
    if (auto* grid = vtkUnstructuredGrid::SafeDownCast(convert->GetOutputDataObject(0)))
    {
      hexahedra->ShallowCopy(grid);
      hexahedra->RemoveGhostCells();
      if (hexahedra->GetNumberOfPoints() > 0)
      {
        hexahedra->GetBounds(this->DataBounds);
      }
      if (this->UseSeparateOpacityArray)
      {
        this->AppendOpacityComponent(hexahedra);
      }
    }
  }
  this->Preprocessor->RemoveAllInputs();
  vtkNew<vtkUnstructuredGrid> placeholder;
  this->Preprocessor->SetInputData(0, placeholder);
  this->Preprocessor->Update();
  vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0))->ShallowCopy(hexahedra);
  // The superclass's superclass: vtkPVDataRepresentation's bookkeeping.
  return this->vtkVolumeRepresentation::RequestData(request, inputVector, outputVector);
}

void vtkHexahedralRayCastRepresentation::SetIntegrationMode(int mode)
{
  this->HexahedralMapper->SetIntegrationMode(mode);
  this->MarkModified();
}

void vtkHexahedralRayCastRepresentation::SetFixedSteps(int steps)
{
  this->HexahedralMapper->SetFixedSteps(steps);
  this->MarkModified();
}

void vtkHexahedralRayCastRepresentation::SetMaximumPeels(int peels)
{
  this->HexahedralMapper->SetMaximumPeels(peels);
  this->MarkModified();
}

void vtkHexahedralRayCastRepresentation::SetExactSegmentEnds(int exact)
{
  this->HexahedralMapper->SetExactSegmentEnds(exact != 0);
  this->MarkModified();
}
