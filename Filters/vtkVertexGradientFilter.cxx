#include "vtkVertexGradientFilter.h"

#include "uvCellGradient.h"
#include "uvLinearCellSplit.h"
#include "uvVertexCellLinks.h"

#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkVertexGradientFilter);

namespace
{
/// Corners of the linear 3D cells that carry a gradient; 0 for every other type.
int GradientCellCorners(int cellType)
{
  switch (cellType)
  {
    case VTK_TETRA:
      return 4;
    case VTK_PYRAMID:
      return 5;
    case VTK_WEDGE:
      return 6;
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return 8;
    default:
      return 0;
  }
}

/// Gradient of one cell from its corner positions and values (VTK order); weight 0 when unusable.
uv::CellGradient GradientOfCell(int cellType, const vtkIdType* ids, const std::vector<glm::dvec3>& points,
  const std::vector<double>& values)
{
  glm::dvec3 p[8];
  double f[8];
  const int numCorners = GradientCellCorners(cellType);
  for (int k = 0; k < numCorners; ++k)
  {
    const vtkIdType id = cellType == VTK_VOXEL ? ids[uv::VoxelToHexahedronOrder[k]] : ids[k];
    p[k] = points[id];
    f[k] = values[id];
    if (!std::isfinite(f[k]))
    {
      return {};
    }
  }
  switch (cellType)
  {
    case VTK_TETRA:
      return uv::TetrahedronGradient(p, f);
    case VTK_PYRAMID:
      return uv::PyramidGradient(p, f);
    case VTK_WEDGE:
      return uv::WedgeGradient(p, f);
    default:
      return uv::HexahedronGradient(p, f);
  }
}
} // namespace

vtkVertexGradientFilter::vtkVertexGradientFilter()
{
  this->SetResultArrayName("Gradients");
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkVertexGradientFilter::~vtkVertexGradientFilter()
{
  this->SetResultArrayName(nullptr);
}

int vtkVertexGradientFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkDataSet* output = vtkDataSet::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType numCells = input->GetNumberOfCells();
  if (numPoints == 0)
  {
    return 1; // empty in, empty out
  }

  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector, association);
  if (!scalars)
  {
    vtkErrorMacro("No point scalar array to differentiate: the input has no active point scalars "
                  "and no array was named with SetInputArrayToProcess.");
    return 0;
  }
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("Array '" << (scalars->GetName() ? scalars->GetName() : "")
                            << "' is not a point array; a point scalar is needed.");
    return 0;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("Array '" << (scalars->GetName() ? scalars->GetName() : "") << "' has "
                            << scalars->GetNumberOfComponents()
                            << " components; a single-component scalar is needed.");
    return 0;
  }
  if (!this->ResultArrayName || !*this->ResultArrayName)
  {
    vtkErrorMacro("ResultArrayName is empty.");
    return 0;
  }

  // Values and positions in double, read once in parallel.
  std::vector<double> values(numPoints);
  std::vector<glm::dvec3> points(numPoints);
  double first[3];
  input->GetPoint(0, first); // the first call must come from one thread
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      values[id] = scalars->GetComponent(id, 0);
      input->GetPoint(id, &points[id].x);
    }
  });
  this->UpdateProgress(0.2);

  // Flat connectivity of the cells that can carry a gradient (others keep an empty row).
  std::vector<vtkIdType> cellOffsets(numCells + 1, 0);
  if (numCells > 0)
  {
    input->GetCellType(0); // the first call must come from one thread
  }
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      cellOffsets[cell + 1] = GradientCellCorners(input->GetCellType(cell));
    }
  });
  vtkIdType ignored = 0;
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    ignored += cellOffsets[cell + 1] == 0 && input->GetCellType(cell) != VTK_EMPTY_CELL ? 1 : 0;
    cellOffsets[cell + 1] += cellOffsets[cell];
  }
  if (ignored > 0)
  {
    vtkWarningMacro("Ignored " << ignored
                               << " cells that are not linear 3D cells (tetrahedron, hexahedron, "
                                  "voxel, wedge, pyramid).");
  }
  std::vector<vtkIdType> connectivity(cellOffsets[numCells]);
  std::vector<uv::CellGradient> cellGradients(numCells);
  vtkSMPThreadLocalObject<vtkIdList> threadIds;
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = threadIds.Local();
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      if (cellOffsets[cell + 1] == cellOffsets[cell])
      {
        continue;
      }
      input->GetCellPoints(cell, ids);
      std::copy(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds(),
        connectivity.begin() + cellOffsets[cell]);
      cellGradients[cell] = GradientOfCell(input->GetCellType(cell), ids->GetPointer(0), points, values);
    }
  });
  this->UpdateProgress(0.6);

  const uv::VertexCellLinks links = uv::BuildVertexCellLinks(numPoints, cellOffsets, connectivity);
  this->UpdateProgress(0.8);

  vtkSmartPointer<vtkDataArray> gradients;
  if (scalars->GetDataType() == VTK_DOUBLE)
  {
    gradients = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    gradients = vtkSmartPointer<vtkFloatArray>::New();
  }
  gradients->SetName(this->ResultArrayName);
  gradients->SetNumberOfComponents(3);
  gradients->SetNumberOfTuples(numPoints);
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType vertex = begin; vertex < end; ++vertex)
    {
      glm::dvec3 sum(0.0);
      double weight = 0.0;
      for (std::int64_t k = links.Offsets[vertex]; k < links.Offsets[vertex + 1]; ++k)
      {
        const uv::CellGradient& cell = cellGradients[links.Cells[k]];
        sum += cell.Weight * cell.Gradient;
        weight += cell.Weight;
      }
      const glm::dvec3 mean =
        weight > 0.0 ? sum / weight : glm::dvec3(std::numeric_limits<double>::quiet_NaN());
      gradients->SetTuple(vertex, &mean.x);
    }
  });
  output->GetPointData()->AddArray(gradients);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkVertexGradientFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ResultArrayName: " << (this->ResultArrayName ? this->ResultArrayName : "(none)")
     << "\n";
}
