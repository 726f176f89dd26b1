#include "vtkVertexGradientFilter.h"

#include "uvCellGradient.h"
#include "uvLinearCellSplit.h"
#include "uvVertexCellLinks.h"
#include "vtkuvMeshIntegrity.h"

#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
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
/// The same mean of cell gradients for image data, without links: every voxel is the same affine
/// image of the unit cube, so all weights are equal and J^-T is applied once per vertex.
/// Returns false (and leaves `gradients` alone) for grids that are not 3D.
bool ImageDataVertexGradients(vtkImageData* image, const std::vector<double>& values,
  std::vector<glm::dvec3>& gradients)
{
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    return false;
  }
  const vtkIdType nx = dims[0], nxy = static_cast<vtkIdType>(dims[0]) * dims[1];
  const vtkIdType cx = nx - 1, cy = dims[1] - 1, cz = dims[2] - 1;
  // The voxel Jacobian from real corner positions: spacing, its signs and any direction matrix.
  glm::dvec3 origin, alongX, alongY, alongZ;
  image->GetPoint(0, &origin.x);
  image->GetPoint(1, &alongX.x);
  image->GetPoint(nx, &alongY.x);
  image->GetPoint(nxy, &alongZ.x);
  const glm::dmat3 jacobian(alongX - origin, alongY - origin, alongZ - origin);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  gradients.assign(values.size(), glm::dvec3(nan));
  const uv::CellGradient probe = uv::detail::FromJacobian(jacobian, glm::dvec3(0.0));
  if (probe.Weight <= 0.0)
  {
    return true; // degenerate spacing: no cell carries a gradient
  }
  const glm::dmat3 inverseTranspose = glm::transpose(glm::inverse(jacobian));

  // df/dxi at each voxel's centre; NaN when a corner is not finite.
  std::vector<glm::dvec3> cellDerivatives(cx * cy * cz);
  vtkSMPTools::For(0, cx * cy * cz, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      const vtkIdType i = cell % cx, j = (cell / cx) % cy, k = cell / (cx * cy);
      const double* f = values.data() + i + j * nx + k * nxy;
      const double f000 = f[0], f100 = f[1], f010 = f[nx], f110 = f[nx + 1];
      const double f001 = f[nxy], f101 = f[nxy + 1], f011 = f[nxy + nx], f111 = f[nxy + nx + 1];
      const glm::dvec3 derivative(
        0.25 * ((f100 - f000) + (f110 - f010) + (f101 - f001) + (f111 - f011)),
        0.25 * ((f010 - f000) + (f110 - f100) + (f011 - f001) + (f111 - f101)),
        0.25 * ((f001 - f000) + (f101 - f100) + (f011 - f010) + (f111 - f110)));
      // Any non-finite corner makes a non-finite sum, which marks the cell unusable.
      cellDerivatives[cell] = std::isfinite(derivative.x + derivative.y + derivative.z)
        ? derivative
        : glm::dvec3(nan);
    }
  });
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType vertex = begin; vertex < end; ++vertex)
    {
      const vtkIdType i = vertex % nx, j = (vertex / nx) % dims[1], k = vertex / nxy;
      glm::dvec3 sum(0.0);
      int count = 0;
      for (vtkIdType ck = std::max<vtkIdType>(k - 1, 0); ck <= std::min(k, cz - 1); ++ck)
      {
        for (vtkIdType cj = std::max<vtkIdType>(j - 1, 0); cj <= std::min(j, cy - 1); ++cj)
        {
          for (vtkIdType ci = std::max<vtkIdType>(i - 1, 0); ci <= std::min(i, cx - 1); ++ci)
          {
            const glm::dvec3& derivative = cellDerivatives[ci + cx * (cj + cy * ck)];
            if (!std::isnan(derivative.x))
            {
              sum += derivative;
              ++count;
            }
          }
        }
      }
      if (count > 0)
      {
        gradients[vertex] = inverseTranspose * (sum / static_cast<double>(count));
      }
    }
  });
  return true;
}

/// The points in double, read in parallel.
std::vector<glm::dvec3> PointsOf(vtkDataSet* input)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<glm::dvec3> points(numPoints);
  double first[3];
  input->GetPoint(0, first); // the first call must come from one thread
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
      input->GetPoint(id, &points[id].x);
  });
  return points;
}

/// Offsets of each cell's corners in a flat connectivity holding only the cells that carry a
/// gradient (the others get an empty row). Returns how many non-empty cells were ignored.
vtkIdType GradientCellOffsets(vtkDataSet* input, std::vector<vtkIdType>& cellOffsets)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  cellOffsets.assign(numCells + 1, 0);
  if (numCells > 0)
    input->GetCellType(0); // the first call must come from one thread
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
      cellOffsets[cell + 1] = GradientCellCorners(input->GetCellType(cell));
  });
  vtkIdType ignored = 0;
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    ignored += cellOffsets[cell + 1] == 0 && input->GetCellType(cell) != VTK_EMPTY_CELL ? 1 : 0;
    cellOffsets[cell + 1] += cellOffsets[cell];
  }
  return ignored;
}

/// Each cell's gradient and weight, and the flat connectivity the offsets describe.
std::vector<uv::CellGradient> GradientsOfCells(vtkDataSet* input, const std::vector<vtkIdType>& cellOffsets,
  const std::vector<glm::dvec3>& points, const std::vector<double>& values, std::vector<vtkIdType>& connectivity)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  connectivity.assign(cellOffsets[numCells], 0);
  std::vector<uv::CellGradient> cellGradients(numCells);
  vtkSMPThreadLocalObject<vtkIdList> threadIds;
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = threadIds.Local();
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      if (cellOffsets[cell + 1] == cellOffsets[cell])
        continue;
      input->GetCellPoints(cell, ids);
      std::copy(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds(),
        connectivity.begin() + cellOffsets[cell]);
      cellGradients[cell] = GradientOfCell(input->GetCellType(cell), ids->GetPointer(0), points, values);
    }
  });
  return cellGradients;
}

/// The weighted mean of the gradients of the cells around each vertex (NaN where no cell is).
std::vector<glm::dvec3> AverageAtVertices(
  const uv::VertexCellLinks& links, const std::vector<uv::CellGradient>& cellGradients, vtkIdType numPoints)
{
  std::vector<glm::dvec3> vertexGradients(numPoints);
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
      vertexGradients[vertex] =
        weight > 0.0 ? sum / weight : glm::dvec3(std::numeric_limits<double>::quiet_NaN());
    }
  });
  return vertexGradients;
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
  if (auto* cells = vtkUnstructuredGridBase::SafeDownCast(input))
  {
    const std::string broken = vtkuv::FindBrokenCellsError(cells, "The output is empty.");
    if (!broken.empty())
    {
      vtkErrorMacro(<< broken);
      output->Initialize();
      return 0;
    }
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

  // Values in double, read once in parallel.
  std::vector<double> values(numPoints);
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      values[id] = scalars->GetComponent(id, 0);
    }
  });
  std::vector<glm::dvec3> vertexGradients;
  auto image = vtkImageData::SafeDownCast(input);
  if (image && ImageDataVertexGradients(image, values, vertexGradients))
  {
    this->AddGradientArray(output, scalars, vertexGradients);
    this->UpdateProgress(1.0);
    return 1;
  }

  const std::vector<glm::dvec3> points = PointsOf(input);
  this->UpdateProgress(0.2);

  // Flat connectivity of the cells that can carry a gradient (others keep an empty row).
  std::vector<vtkIdType> cellOffsets;
  const vtkIdType ignored = GradientCellOffsets(input, cellOffsets);
  if (ignored > 0)
  {
    vtkWarningMacro("Ignored " << ignored
                               << " cells that are not linear 3D cells (tetrahedron, hexahedron, "
                                  "voxel, wedge, pyramid).");
  }
  std::vector<vtkIdType> connectivity;
  const std::vector<uv::CellGradient> cellGradients =
    GradientsOfCells(input, cellOffsets, points, values, connectivity);
  this->UpdateProgress(0.6);

  const uv::VertexCellLinks links = uv::BuildVertexCellLinks(numPoints, cellOffsets, connectivity);
  this->UpdateProgress(0.8);

  vertexGradients = AverageAtVertices(links, cellGradients, numPoints);
  this->AddGradientArray(output, scalars, vertexGradients);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkVertexGradientFilter::AddGradientArray(
  vtkDataSet* output, vtkDataArray* scalars, const std::vector<glm::dvec3>& vertexGradients)
{
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
  gradients->SetNumberOfTuples(static_cast<vtkIdType>(vertexGradients.size()));
  vtkSMPTools::For(0, gradients->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType vertex = begin; vertex < end; ++vertex)
    {
      gradients->SetTuple(vertex, &vertexGradients[vertex].x);
    }
  });
  output->GetPointData()->AddArray(gradients);
}

void vtkVertexGradientFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ResultArrayName: " << (this->ResultArrayName ? this->ResultArrayName : "(none)")
     << "\n";
}
