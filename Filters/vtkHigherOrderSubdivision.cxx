#include "vtkHigherOrderSubdivision.h"
#include "vtkUnstructuredVolumeCompatibility.h"

#include "uvIsoparametricLattice.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkHigherOrderSubdivision);

namespace
{
using Vec3 = std::array<double, 3>;
using Key = uv::LatticeKey<vtkIdType>;

bool FamilyOf(int cellType, uv::CellFamily& family)
{
  switch (cellType)
  {
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
      family = uv::CellFamily::Tetrahedron;
      return true;
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
      family = uv::CellFamily::Hexahedron;
      return true;
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
      family = uv::CellFamily::Wedge;
      return true;
    case VTK_QUADRATIC_PYRAMID:
    case VTK_TRIQUADRATIC_PYRAMID:
      family = uv::CellFamily::Pyramid;
      return true;
    default:
      return false;
  }
}

enum class Role
{
  Linear,      // passes through
  HigherOrder, // subdivided
  Dropped,     // not 3D
  Unsupported  // 3D, but neither linear nor interpolable here
};

Role RoleOf(int cellType, vtkGenericCell* probe)
{
  uv::CellFamily family;
  if (FamilyOf(cellType, family))
  {
    return Role::HigherOrder;
  }
  switch (cellType)
  {
    case VTK_TETRA:
    case VTK_VOXEL:
    case VTK_HEXAHEDRON:
    case VTK_WEDGE:
    case VTK_PYRAMID:
    case VTK_PENTAGONAL_PRISM:
    case VTK_HEXAGONAL_PRISM:
    case VTK_POLYHEDRON:
    case VTK_CONVEX_POINT_SET:
      return Role::Linear;
    case VTK_EMPTY_CELL:
      return Role::Dropped;
    // No VTK 9.1 class interpolates these; vtkGenericCell would stand an empty cell in for them.
    case VTK_LAGRANGE_PYRAMID:
    case VTK_BEZIER_PYRAMID:
    case VTK_HIGHER_ORDER_TETRAHEDRON:
    case VTK_HIGHER_ORDER_WEDGE:
    case VTK_HIGHER_ORDER_PYRAMID:
    case VTK_HIGHER_ORDER_HEXAHEDRON:
      return Role::Unsupported;
    default:
      probe->SetCellType(cellType);
      return probe->GetCellDimension() == 3 ? Role::Unsupported : Role::Dropped;
  }
}

/// One component of a point array that the field tolerance watches, with its range over the input.
struct FieldComponent
{
  vtkDataArray* Array;
  int Component;
  double Range;
};

std::vector<FieldComponent> WatchedComponents(vtkPointData* pointData, const char* name)
{
  std::vector<FieldComponent> components;
  const bool named = name && *name;
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    if (!array || (named && (!array->GetName() || std::string(array->GetName()) != name)))
    {
      continue;
    }
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      double range[2];
      array->GetRange(range, c); // computed here, once, not by the threads
      const double width = range[1] - range[0];
      if (width > 0.0 && std::isfinite(width))
      {
        components.push_back({ array, c, width }); // a constant component cannot be in error
      }
    }
  }
  return components;
}

/// One cell's nodes (position, then the watched components) and its own interpolation.
/// Copyable with no cell yet, so that it can be a thread-local exemplar.
class CellSampler
{
public:
  void Load(vtkDataSet* input, vtkIdType cellId, uv::CellFamily family, const std::vector<FieldComponent>& fields)
  {
    if (!this->Cell)
    {
      this->Cell = vtkSmartPointer<vtkGenericCell>::New();
    }
    input->GetCell(cellId, this->Cell);
    this->Family = family;
    this->Width = 3 + static_cast<int>(fields.size());
    const vtkIdType numNodes = this->Cell->GetNumberOfPoints();
    this->Nodes.resize(static_cast<std::size_t>(numNodes * this->Width));
    this->Weights.resize(static_cast<std::size_t>(numNodes));
    for (vtkIdType n = 0; n < numNodes; ++n)
    {
      double* node = &this->Nodes[static_cast<std::size_t>(n * this->Width)];
      this->Cell->GetPoints()->GetPoint(n, node);
      for (std::size_t f = 0; f < fields.size(); ++f)
      {
        node[3 + f] = fields[f].Array->GetComponent(this->Cell->GetPointId(n), fields[f].Component);
      }
    }
  }

  /// VTK parametrises pyramids two ways: vtkPyramid and vtkQuadraticPyramid collapse the unit
  /// cube's top onto the apex (listed at (0,0,1), above corner 0), while VTK 9.1's
  /// vtkTriQuadraticPyramid maps a straight pyramid (apex listed above the base centre), which is
  /// affine in the lattice's reference position.
  Vec3 ParametricCoords(const Vec3& reference) const
  {
    const double* pc = this->Cell->GetParametricCoords();
    if (this->Family != uv::CellFamily::Pyramid || !pc || (pc[12] == pc[0] && pc[13] == pc[1]))
    {
      return uv::ParametricCoordsOf(this->Family, reference);
    }
    Vec3 result;
    for (int d = 0; d < 3; ++d)
    {
      result[d] = pc[d] + reference[0] * (pc[3 + d] - pc[d]) + reference[1] * (pc[9 + d] - pc[d]) +
        reference[2] * (pc[12 + d] - pc[d]);
    }
    return result;
  }

  /// Position and watched components at a reference position, into out[Width]; fills Weights.
  void Evaluate(const Vec3& reference, double* out)
  {
    Vec3 pcoords = this->ParametricCoords(reference);
    this->Cell->InterpolateFunctions(pcoords.data(), this->Weights.data());
    std::fill(out, out + this->Width, 0.0);
    for (std::size_t n = 0; n < this->Weights.size(); ++n)
    {
      const double* node = &this->Nodes[n * static_cast<std::size_t>(this->Width)];
      for (int w = 0; w < this->Width; ++w)
      {
        out[w] += this->Weights[n] * node[w];
      }
    }
  }

  /// The bounding-box diagonal of the cell's corners.
  double Diameter() const
  {
    Vec3 low = { node(0)[0], node(0)[1], node(0)[2] }, high = low;
    for (int c = 1; c < uv::CornerCount(this->Family); ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        low[d] = std::min(low[d], node(c)[d]);
        high[d] = std::max(high[d], node(c)[d]);
      }
    }
    return std::sqrt((high[0] - low[0]) * (high[0] - low[0]) + (high[1] - low[1]) * (high[1] - low[1]) +
      (high[2] - low[2]) * (high[2] - low[2]));
  }

  /// The node whose weight is 1 (all others 0) after Evaluate, or -1.
  int NodeHit() const
  {
    int hit = -1;
    for (std::size_t n = 0; n < this->Weights.size(); ++n)
    {
      if (std::abs(this->Weights[n] - 1.0) <= 1e-12 && hit < 0)
      {
        hit = static_cast<int>(n);
      }
      else if (std::abs(this->Weights[n]) > 1e-12)
      {
        return -1;
      }
    }
    return hit;
  }

  vtkGenericCell* GetCell() const { return this->Cell; }
  std::vector<double>& GetWeights() { return this->Weights; }
  int GetWidth() const { return this->Width; }

private:
  const double* node(int n) const { return &this->Nodes[static_cast<std::size_t>(n * this->Width)]; }

  vtkSmartPointer<vtkGenericCell> Cell;
  uv::CellFamily Family = uv::CellFamily::Tetrahedron;
  int Width = 3;
  std::vector<double> Nodes;
  std::vector<double> Weights;
};

/// A point where the cell's own value is compared with the linear one: an edge midpoint or a
/// sub-cell centre, in reference coordinates, with the lattice points whose mean is the linear value.
struct Probe
{
  Vec3 Reference;
  int Size;
  std::array<int, 8> Points;
};

struct LevelPlan
{
  LevelPlan(uv::CellFamily family, int level)
    : Lattice(family, level)
  {
    for (const std::array<int, 2>& edge : this->Lattice.Edges())
    {
      this->Add(2, edge.data());
    }
    for (const uv::LatticeSubCell& cell : this->Lattice.SubCells())
    {
      this->Add(cell.Size, cell.Points.data());
    }
  }

  void Add(int size, const int* points)
  {
    Probe probe{ { 0.0, 0.0, 0.0 }, size, {} };
    for (int v = 0; v < size; ++v)
    {
      probe.Points[v] = points[v];
      const Vec3 reference = this->Lattice.Reference(static_cast<std::size_t>(points[v]));
      for (int d = 0; d < 3; ++d)
      {
        probe.Reference[d] += reference[d] / size;
      }
    }
    this->Probes.push_back(probe);
  }

  uv::IsoparametricLattice Lattice;
  std::vector<Probe> Probes;
};

/// The plans of the four families at one level.
using LevelPlans = std::array<std::unique_ptr<LevelPlan>, 4>;

LevelPlans MakePlans(int level)
{
  LevelPlans plans;
  const uv::CellFamily families[4] = { uv::CellFamily::Tetrahedron, uv::CellFamily::Hexahedron,
    uv::CellFamily::Wedge, uv::CellFamily::Pyramid };
  for (int f = 0; f < 4; ++f)
  {
    plans[f] = std::make_unique<LevelPlan>(families[f], level);
  }
  return plans;
}

const LevelPlan& PlanOf(const LevelPlans& plans, uv::CellFamily family)
{
  return *plans[static_cast<std::size_t>(family)];
}

struct Errors
{
  double Field = 0.0;
  double Chord = 0.0;
};

struct MeasureScratch
{
  CellSampler Sampler;
  std::vector<double> Lattice;
  std::vector<double> Values;
  Errors Worst;
};

/// The worst relative field and chord errors of one loaded cell at the plan's level.
void MeasureCell(MeasureScratch& s, const LevelPlan& plan, const std::vector<FieldComponent>& fields)
{
  const std::size_t w = static_cast<std::size_t>(s.Sampler.GetWidth());
  const std::size_t numPoints = plan.Lattice.NumberOfPoints();
  s.Lattice.resize(numPoints * w);
  s.Values.resize(2 * w);
  for (std::size_t p = 0; p < numPoints; ++p)
  {
    s.Sampler.Evaluate(plan.Lattice.Reference(p), &s.Lattice[p * w]);
  }
  const double diameter = s.Sampler.Diameter();
  double* curved = s.Values.data();
  double* linear = curved + w;
  for (const Probe& probe : plan.Probes)
  {
    s.Sampler.Evaluate(probe.Reference, curved);
    std::fill(linear, linear + w, 0.0);
    for (int v = 0; v < probe.Size; ++v)
    {
      const double* corner = &s.Lattice[static_cast<std::size_t>(probe.Points[v]) * w];
      for (std::size_t c = 0; c < w; ++c)
      {
        linear[c] += corner[c] / probe.Size;
      }
    }
    if (diameter > 0.0)
    {
      const double dx = curved[0] - linear[0], dy = curved[1] - linear[1], dz = curved[2] - linear[2];
      s.Worst.Chord = std::max(s.Worst.Chord, std::sqrt(dx * dx + dy * dy + dz * dz) / diameter);
    }
    for (std::size_t f = 0; f < fields.size(); ++f)
    {
      s.Worst.Field = std::max(s.Worst.Field, std::abs(curved[3 + f] - linear[3 + f]) / fields[f].Range);
    }
  }
}

/// The worst errors over the higher-order cells at one level (in parallel).
Errors MeasureLevel(vtkDataSet* input, const std::vector<vtkIdType>& cells, int level,
  const std::vector<FieldComponent>& fields)
{
  const LevelPlans plans = MakePlans(level);
  vtkSMPThreadLocal<MeasureScratch> scratch;
  vtkNew<vtkGenericCell> first;
  input->GetCell(cells.front(), first); // the first call must come from one thread
  vtkSMPTools::For(0, static_cast<vtkIdType>(cells.size()), [&](vtkIdType begin, vtkIdType end) {
    MeasureScratch& s = scratch.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      uv::CellFamily family;
      FamilyOf(input->GetCellType(cells[i]), family);
      s.Sampler.Load(input, cells[i], family, fields);
      MeasureCell(s, PlanOf(plans, family), fields);
    }
  });
  Errors worst;
  for (const MeasureScratch& s : scratch)
  {
    worst.Field = std::max(worst.Field, s.Worst.Field);
    worst.Chord = std::max(worst.Chord, s.Worst.Chord);
  }
  return worst;
}

/// The input's points, unchanged, in a vtkPoints that the new points are appended to.
vtkSmartPointer<vtkPoints> CopyPoints(vtkDataSet* input)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto pointSet = vtkPointSet::SafeDownCast(input);
  if (pointSet && pointSet->GetPoints())
  {
    points->SetDataType(pointSet->GetPoints()->GetDataType());
    points->DeepCopy(pointSet->GetPoints());
    return points;
  }
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(input->GetNumberOfPoints());
  for (vtkIdType id = 0; id < input->GetNumberOfPoints(); ++id)
  {
    points->SetPoint(id, input->GetPoint(id));
  }
  return points;
}

int LinearTypeOf(int size)
{
  return size == 4 ? VTK_TETRA : size == 5 ? VTK_PYRAMID : size == 6 ? VTK_WEDGE : VTK_HEXAHEDRON;
}

/// Writes the output cell by cell, in input order: serial, so that new points are numbered by the
/// first cell creating them.
class OutputBuilder
{
public:
  OutputBuilder(vtkDataSet* input, vtkUnstructuredGrid* output)
    : Input(input)
    , Output(output)
    , Points(CopyPoints(input))
  {
    vtkPointData* outPointData = output->GetPointData();
    outPointData->CopyAllOn(vtkDataSetAttributes::INTERPOLATE); // ids and all: every array everywhere
    outPointData->InterpolateAllocate(input->GetPointData(), input->GetNumberOfPoints());
    outPointData->CopyData(input->GetPointData(), 0, input->GetNumberOfPoints(), 0);
  }

  void AddLinear(vtkIdType cell)
  {
    auto grid = vtkUnstructuredGrid::SafeDownCast(this->Input);
    const int type = this->Input->GetCellType(cell);
    if (type == VTK_POLYHEDRON && grid)
    {
      uvcompat::GetPolyhedronFaceStream(grid, cell, this->Ids);
    }
    else
    {
      this->Input->GetCellPoints(cell, this->Ids);
    }
    this->Output->InsertNextCell(type, this->Ids);
    this->Original.push_back(cell);
  }

  void AddHigherOrder(vtkIdType cell, uv::CellFamily family, const LevelPlan& plan)
  {
    this->Sampler.Load(this->Input, cell, family, {});
    vtkGenericCell* source = this->Sampler.GetCell();
    std::array<vtkIdType, 8> corners{};
    for (int c = 0; c < uv::CornerCount(family); ++c)
    {
      corners[c] = source->GetPointId(c);
    }
    const std::size_t numPoints = plan.Lattice.NumberOfPoints();
    this->LatticeIds.resize(numPoints);
    for (std::size_t p = 0; p < numPoints; ++p)
    {
      auto found = this->Shared.emplace(plan.Lattice.Key(p, corners.data()), -1);
      if (found.second)
      {
        found.first->second = this->NewPoint(plan.Lattice.Reference(p));
      }
      this->LatticeIds[p] = found.first->second;
    }
    vtkIdType ids[8];
    for (const uv::LatticeSubCell& sub : plan.Lattice.SubCells())
    {
      for (int v = 0; v < sub.Size; ++v)
      {
        ids[v] = this->LatticeIds[static_cast<std::size_t>(sub.Points[v])];
      }
      this->Output->InsertNextCell(LinearTypeOf(sub.Size), sub.Size, ids);
      this->Original.push_back(cell);
    }
  }

  vtkPoints* GetPoints() const { return this->Points; }
  const std::vector<vtkIdType>& GetOriginal() const { return this->Original; }

private:
  /// The input node at this lattice point of the loaded cell, or a new interpolated point.
  vtkIdType NewPoint(const Vec3& reference)
  {
    double x[3];
    this->Sampler.Evaluate(reference, x);
    const int node = this->Sampler.NodeHit();
    vtkGenericCell* source = this->Sampler.GetCell();
    if (node >= 0)
    {
      return source->GetPointId(node);
    }
    const vtkIdType id = this->Points->InsertNextPoint(x);
    this->Output->GetPointData()->InterpolatePoint(
      this->Input->GetPointData(), id, source->GetPointIds(), this->Sampler.GetWeights().data());
    return id;
  }

  vtkDataSet* Input;
  vtkUnstructuredGrid* Output;
  vtkSmartPointer<vtkPoints> Points;
  CellSampler Sampler;
  std::unordered_map<Key, vtkIdType, uv::LatticeKeyHash<vtkIdType>> Shared;
  std::vector<vtkIdType> LatticeIds;
  std::vector<vtkIdType> Original;
  vtkNew<vtkIdList> Ids;
};

/// Every input cell array copied to the output cells (`original`: each one's input cell).
void CopyCellData(vtkCellData* in, vtkCellData* out, const std::vector<vtkIdType>& original)
{
  const vtkIdType numCells = static_cast<vtkIdType>(original.size());
  if (in->GetNumberOfArrays() > 0 && numCells > 0)
  {
    out->CopyAllocate(in, numCells);
    vtkNew<vtkIdList> fromIds, toIds;
    fromIds->SetNumberOfIds(numCells);
    toIds->SetNumberOfIds(numCells);
    std::copy(original.begin(), original.end(), fromIds->GetPointer(0));
    std::iota(toIds->GetPointer(0), toIds->GetPointer(0) + numCells, 0);
    out->CopyData(in, fromIds, toIds);
  }
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("vtkOriginalCellIds");
  ids->SetNumberOfValues(numCells);
  std::copy(original.begin(), original.end(), ids->GetPointer(0));
  out->AddArray(ids);
}

bool WithinTolerances(const Errors& errors, double field, double chord)
{
  return errors.Field <= field && errors.Chord <= chord;
}
} // namespace

vtkHigherOrderSubdivision::vtkHigherOrderSubdivision() = default;

vtkHigherOrderSubdivision::~vtkHigherOrderSubdivision()
{
  this->SetFieldArrayName(nullptr);
}

bool vtkHigherOrderSubdivision::IsSubdividedCellType(int cellType)
{
  uv::CellFamily family;
  return FamilyOf(cellType, family);
}

int vtkHigherOrderSubdivision::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

namespace
{
/// Each cell's role, the higher-order cells in order, the count of dropped cells, and the first
/// unsupported type (or -1).
struct Census
{
  std::vector<Role> Roles;
  std::vector<vtkIdType> HigherOrder;
  vtkIdType Dropped = 0;
  int Unsupported = -1;
};

Census TakeCensus(vtkDataSet* input)
{
  Census census;
  std::array<int, 256> roleOfType;
  roleOfType.fill(-1);
  vtkNew<vtkGenericCell> probe;
  const vtkIdType numCells = input->GetNumberOfCells();
  census.Roles.resize(static_cast<std::size_t>(numCells));
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    const int type = input->GetCellType(cell);
    if (roleOfType[type] < 0)
    {
      roleOfType[type] = static_cast<int>(RoleOf(type, probe));
    }
    const Role role = static_cast<Role>(roleOfType[type]);
    census.Roles[cell] = role;
    if (role == Role::HigherOrder)
    {
      census.HigherOrder.push_back(cell);
    }
    census.Dropped += role == Role::Dropped ? 1 : 0;
    if (role == Role::Unsupported && census.Unsupported < 0)
    {
      census.Unsupported = type;
    }
  }
  return census;
}
} // namespace

int vtkHigherOrderSubdivision::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  output->Initialize();
  this->ChosenLevel = 0;
  this->FieldError = this->ChordError = 0.0;
  if (input->GetNumberOfCells() == 0 || input->GetNumberOfPoints() == 0)
  {
    return 1; // empty in, empty out
  }
  const Census census = TakeCensus(input);
  if (census.Unsupported >= 0)
  {
    vtkErrorMacro("Input has 3D cells that cannot be subdivided (first type: "
      << uvcompat::CellTypeName(census.Unsupported)
      << "): VTK 9.1 interpolates no Lagrange or Bezier pyramid.");
    return 0;
  }
  if (census.Dropped > 0)
  {
    vtkWarningMacro("Dropped " << census.Dropped
                               << " cells that are not 3D (vertices, lines, polygons, higher-order surfaces or "
                                  "empty cells).");
  }
  if (!census.HigherOrder.empty())
  {
    this->ChooseLevel(input, census.HigherOrder);
  }
  this->UpdateProgress(0.5);

  OutputBuilder builder(input, output);
  output->Allocate(input->GetNumberOfCells());
  const LevelPlans plans = MakePlans(std::max(this->ChosenLevel, 1));
  for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
  {
    const Role role = census.Roles[cell];
    uv::CellFamily family;
    if (role == Role::Linear)
    {
      builder.AddLinear(cell);
    }
    else if (role == Role::HigherOrder && FamilyOf(input->GetCellType(cell), family))
    {
      builder.AddHigherOrder(cell, family, PlanOf(plans, family));
    }
  }
  output->SetPoints(builder.GetPoints());
  output->GetFieldData()->PassData(input->GetFieldData());
  CopyCellData(input->GetCellData(), output->GetCellData(), builder.GetOriginal());
  output->Squeeze();
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHigherOrderSubdivision::ChooseLevel(vtkDataSet* input, const std::vector<vtkIdType>& cells)
{
  const std::vector<FieldComponent> fields = WatchedComponents(input->GetPointData(), this->FieldArrayName);
  int level = this->Level > 0 ? this->Level : 1;
  Errors errors = MeasureLevel(input, cells, level, fields);
  while (this->Level == 0 && level < this->MaximumLevel &&
    !WithinTolerances(errors, this->FieldTolerance, this->ChordTolerance))
  {
    errors = MeasureLevel(input, cells, ++level, fields);
  }
  if (this->Level == 0 && !WithinTolerances(errors, this->FieldTolerance, this->ChordTolerance))
  {
    vtkWarningMacro("The maximum level " << level << " does not meet the tolerances: worst field error "
                                         << errors.Field << " (tolerance " << this->FieldTolerance
                                         << "), worst chord error " << errors.Chord << " (tolerance "
                                         << this->ChordTolerance << ").");
  }
  this->ChosenLevel = level;
  this->FieldError = errors.Field;
  this->ChordError = errors.Chord;
}

void vtkHigherOrderSubdivision::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldTolerance: " << this->FieldTolerance << "\n";
  os << indent << "ChordTolerance: " << this->ChordTolerance << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "FieldArrayName: " << (this->FieldArrayName ? this->FieldArrayName : "(none)") << "\n";
  os << indent << "ChosenLevel: " << this->ChosenLevel << "\n";
  os << indent << "FieldError: " << this->FieldError << "\n";
  os << indent << "ChordError: " << this->ChordError << "\n";
}
