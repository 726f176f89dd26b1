#include "vtkAnalyticMeshSource.h"

#include "uvAnalyticMesh.h"
#include "vtkHexahedraToTetrahedra.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

vtkStandardNewMacro(vtkAnalyticMeshSource);

vtkAnalyticMeshSource::vtkAnalyticMeshSource()
{
  this->SetNumberOfInputPorts(0);
}

namespace
{
/// The hexahedra of a structured grid of cells[0] x cells[1] x cells[2] cells, points in x-fastest
/// order, into `hexahedra`.
void GridHexahedra(const int cells[3], vtkCellArray* hexahedra)
{
  const vtkIdType nx = cells[0] + 1, ny = cells[1] + 1;
  const vtkIdType numCells = static_cast<vtkIdType>(cells[0]) * cells[1] * cells[2];
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(numCells + 1);
  connectivity->SetNumberOfValues(8 * numCells);
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      const vtkIdType i = cell % cells[0], j = (cell / cells[0]) % cells[1],
                      k = cell / (static_cast<vtkIdType>(cells[0]) * cells[1]);
      const vtkIdType base = i + j * nx + k * nx * ny;
      const vtkIdType corners[8] = { base, base + 1, base + 1 + nx, base + nx, base + nx * ny,
        base + 1 + nx * ny, base + 1 + nx + nx * ny, base + nx + nx * ny };
      for (int v = 0; v < 8; ++v)
      {
        connectivity->SetValue(8 * cell + v, corners[v]);
      }
      offsets->SetValue(cell, 8 * cell);
    }
  });
  offsets->SetValue(numCells, 8 * numCells);
  hexahedra->SetData(offsets, connectivity);
}
} // namespace

int vtkAnalyticMeshSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  int cells[3];
  for (int d = 0; d < 3; ++d)
  {
    cells[d] = std::max(1, this->Resolution[d]);
  }
  const vtkIdType nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
  const vtkIdType numPoints = nx * ny * nz;
  const glm::dvec3 spacing(2.0 / cells[0], 2.0 / cells[1], 2.0 / cells[2]);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  double* xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  const char* fieldNames[3] = { "Linear", "MarschnerLobb", "Steiner" };
  const uv::AnalyticField fieldKinds[3] = { uv::AnalyticField::Linear,
    uv::AnalyticField::MarschnerLobb, uv::AnalyticField::Steiner };
  vtkNew<vtkDoubleArray> fields[3];
  for (int f = 0; f < 3; ++f)
  {
    fields[f]->SetName(fieldNames[f]);
    fields[f]->SetNumberOfValues(numPoints);
  }

  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      const vtkIdType i = id % nx, j = (id / nx) % ny, k = id / (nx * ny);
      glm::dvec3 p(-1.0 + i * spacing.x, -1.0 + j * spacing.y, -1.0 + k * spacing.z);
      switch (this->Distortion)
      {
        case TWIST:
          p = uv::Twist(p, this->TwistAngle);
          break;
        case JITTER:
        {
          const bool onBoundary[3] = { i == 0 || i == nx - 1, j == 0 || j == ny - 1,
            k == 0 || k == nz - 1 };
          p = uv::Jitter(p, spacing, static_cast<std::uint64_t>(id),
            static_cast<std::uint64_t>(this->Seed), this->JitterFraction, onBoundary);
          break;
        }
        case ROTATE_45:
          p = uv::Rotate45(p);
          break;
        default:
          break;
      }
      xyz[3 * id] = p.x;
      xyz[3 * id + 1] = p.y;
      xyz[3 * id + 2] = p.z;
      for (int f = 0; f < 3; ++f)
      {
        fields[f]->SetValue(id, uv::EvaluateField(fieldKinds[f], p));
      }
    }
  });

  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(static_cast<int>(nx), static_cast<int>(ny), static_cast<int>(nz));
  grid->SetPoints(points);
  for (int f = 0; f < 3; ++f)
  {
    grid->GetPointData()->AddArray(fields[f]);
  }
  grid->GetPointData()->SetActiveScalars(fieldNames[this->Field]);

  if (this->CellKind == HEXAHEDRA)
  {
    vtkNew<vtkCellArray> hexahedra;
    GridHexahedra(cells, hexahedra);
    output->SetPoints(points);
    output->SetCells(VTK_HEXAHEDRON, hexahedra);
    output->GetPointData()->ShallowCopy(grid->GetPointData());
    return 1;
  }

  vtkNew<vtkHexahedraToTetrahedra> split;
  split->SetSplitMode(this->CellKind == FIVE_TETRAHEDRA ? vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA
                                                        : vtkHexahedraToTetrahedra::SIX_TETRAHEDRA);
  split->SetInputData(grid);
  split->Update();
  output->ShallowCopy(split->GetOutput());
  output->GetCellData()->RemoveArray("vtkOriginalCellIds");
  return 1;
}

void vtkAnalyticMeshSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution[0] << " " << this->Resolution[1] << " "
     << this->Resolution[2] << "\n";
  os << indent << "Field: " << this->Field << "\n";
  os << indent << "Distortion: " << this->Distortion << "\n";
  os << indent << "TwistAngle: " << this->TwistAngle << "\n";
  os << indent << "JitterFraction: " << this->JitterFraction << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "CellKind: " << this->CellKind << "\n";
}
