#include "vtkHexahedraToTetrahedra.h"

#include "uvLinearCellSplit.h"
#include "uvPolyhedronSplit.h"
#include "vtkHigherOrderSubdivision.h"
#include "vtkUnstructuredVolumeCompatibility.h"
#include "vtkuvMeshIntegrity.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkCommand.h"
#include "vtkAbstractArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHexahedraToTetrahedra);

namespace
{
// What happens to each input cell type: a positive tet count, 0 (dropped: not 3D), -1 (error), or
// -2 (polyhedra: counted cell by cell).
constexpr int DroppedCell = 0;
constexpr int UnsupportedCell = -1;
constexpr int VariableCell = -2;

int TetsPerCellType(int cellType, int splitMode)
{
  switch (cellType)
  {
    case VTK_TETRA:
      return 1;
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return splitMode == vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA ? 5 : 6;
    case VTK_WEDGE:
      return 3;
    case VTK_PYRAMID:
      return 2;
    case VTK_PENTAGONAL_PRISM:
      return 9;
    case VTK_HEXAGONAL_PRISM:
      return 12;
    case VTK_POLYHEDRON:
      return VariableCell;
    default:
      return UnsupportedCell;
  }
}

/// Table indexed by cell type, built from the input's distinct cell types.
std::array<int, 256> ClassifyCellTypes(vtkDataSet* input, int splitMode, std::vector<int>& unsupported)
{
  // Distinct cell types by a parallel scan (vtkDataSet::GetCellTypes is deprecated after VTK 9.1).
  vtkSMPThreadLocal<std::array<bool, 256>> threadSeen(std::array<bool, 256>{});
  const vtkIdType numCells = input->GetNumberOfCells();
  input->GetCellType(0); // the first call must come from one thread
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    std::array<bool, 256>& seen = threadSeen.Local();
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      seen[input->GetCellType(cell)] = true;
    }
  });
  std::array<bool, 256> present{};
  for (const std::array<bool, 256>& seen : threadSeen)
  {
    for (int type = 0; type < 256; ++type)
    {
      present[type] = present[type] || seen[type];
    }
  }
  std::array<int, 256> table;
  table.fill(UnsupportedCell);
  vtkNew<vtkGenericCell> probe;
  for (int type = 0; type < 256; ++type)
  {
    if (!present[type])
    {
      continue;
    }
    int tets = TetsPerCellType(type, splitMode);
    if (tets == UnsupportedCell)
    {
      if (type == VTK_EMPTY_CELL)
      {
        tets = DroppedCell;
      }
      else if (type == VTK_LAGRANGE_PYRAMID || type == VTK_BEZIER_PYRAMID ||
        (type >= VTK_HIGHER_ORDER_TETRAHEDRON && type <= VTK_HIGHER_ORDER_HEXAHEDRON))
      {
        unsupported.push_back(type); // 3D, though VTK 9.1's probe would stand an empty cell in
      }
      else
      {
        probe->SetCellType(type);
        if (probe->GetCellDimension() < 3)
        {
          tets = DroppedCell;
        }
        else
        {
          unsupported.push_back(type);
        }
      }
    }
    table[type] = tets;
  }
  return table;
}

/// Writes the tets of one cell given its point ids in VTK order; returns how many.
int SplitCell(int cellType, const vtkIdType* ids, vtkIdType tets[uv::MaxTetsPerCell][4])
{
  int local[uv::MaxTetsPerCell][4];
  const vtkIdType* cornerIds = ids;
  vtkIdType hexIds[8];
  int count = 0;
  switch (cellType)
  {
    case VTK_TETRA:
      std::copy(ids, ids + 4, tets[0]);
      return 1;
    case VTK_VOXEL:
      for (int k = 0; k < 8; ++k)
      {
        hexIds[k] = ids[uv::VoxelToHexahedronOrder[k]];
      }
      cornerIds = hexIds;
      count = uv::SplitHexahedron(cornerIds, local);
      break;
    case VTK_HEXAHEDRON:
      count = uv::SplitHexahedron(cornerIds, local);
      break;
    case VTK_WEDGE:
      count = uv::SplitWedge(cornerIds, local);
      break;
    case VTK_PYRAMID:
      count = uv::SplitPyramid(cornerIds, local);
      break;
    case VTK_PENTAGONAL_PRISM:
      count = uv::SplitPentagonalPrism(cornerIds, local);
      break;
    case VTK_HEXAGONAL_PRISM:
      count = uv::SplitHexagonalPrism(cornerIds, local);
      break;
    default:
      return 0;
  }
  for (int t = 0; t < count; ++t)
  {
    for (int v = 0; v < 4; ++v)
    {
      tets[t][v] = cornerIds[local[t][v]];
    }
  }
  return count;
}

/// Grid dimensions and global parity origin of a structured input, or false.
bool GetStructuredLayout(vtkDataSet* input, int dims[3], int parityOrigin[3])
{
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (auto image = vtkImageData::SafeDownCast(input))
  {
    image->GetExtent(extent);
  }
  else if (auto rectilinear = vtkRectilinearGrid::SafeDownCast(input))
  {
    rectilinear->GetExtent(extent);
  }
  else if (auto structured = vtkStructuredGrid::SafeDownCast(input))
  {
    if (structured->HasAnyBlankCells())
    {
      return false; // blanked cells go through the generic path, which drops them
    }
    structured->GetExtent(extent);
  }
  else
  {
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    dims[d] = extent[2 * d + 1] - extent[2 * d] + 1;
    parityOrigin[d] = extent[2 * d];
    if (dims[d] < 2)
    {
      return false; // a 2D or 1D grid: its cells are dropped by the generic path
    }
  }
  return true;
}

/// Points of the output: shared with a vtkPointSet input, computed otherwise.
vtkSmartPointer<vtkPoints> OutputPoints(vtkDataSet* input)
{
  if (auto pointSet = vtkPointSet::SafeDownCast(input))
  {
    return pointSet->GetPoints();
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  points->SetNumberOfPoints(numPoints);
  double* out = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  double first[3];
  input->GetPoint(0, first); // the first call must come from one thread
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      input->GetPoint(id, out + 3 * id);
    }
  });
  return points;
}

/// Makes every tet positive: a left-handed structured grid or a mirrored cell gives negative
/// combinatorial orientation, which only the coordinates reveal. When all cells are congruent
/// (image data), the first tet's sign holds for all, and one test replaces numTets.
template <typename ConnectivityType, typename CoordinateType>
void OrientTets(
  ConnectivityType* connectivity, vtkIdType numTets, const CoordinateType* xyz, bool congruentCells)
{
  if (congruentCells && numTets > 0)
  {
    const CoordinateType* p[4];
    for (int v = 0; v < 4; ++v)
    {
      p[v] = xyz + 3 * connectivity[v];
    }
    if (uv::SixSignedVolume(p[0], p[1], p[2], p[3]) >= 0.0)
    {
      return;
    }
    vtkSMPTools::For(0, numTets, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        std::swap(connectivity[4 * t + 1], connectivity[4 * t + 2]);
      }
    });
    return;
  }
  vtkSMPTools::For(0, numTets, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      ConnectivityType* tet = connectivity + 4 * t;
      const CoordinateType* p[4];
      for (int v = 0; v < 4; ++v)
      {
        p[v] = xyz + 3 * tet[v];
      }
      if (uv::SixSignedVolume(p[0], p[1], p[2], p[3]) < 0.0)
      {
        std::swap(tet[1], tet[2]);
      }
    }
  });
}

template <typename ConnectivityType>
void OrientTets(ConnectivityType* connectivity, vtkIdType numTets, vtkPoints* points, bool congruentCells)
{
  vtkDataArray* data = points->GetData();
  if (auto doubles = vtkDoubleArray::SafeDownCast(data))
  {
    OrientTets(connectivity, numTets, doubles->GetPointer(0), congruentCells);
  }
  else if (auto floats = vtkFloatArray::SafeDownCast(data))
  {
    OrientTets(connectivity, numTets, floats->GetPointer(0), congruentCells);
  }
  else
  {
    std::vector<double> xyz(3 * static_cast<size_t>(points->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      points->GetPoint(i, xyz.data() + 3 * i);
    }
    OrientTets(connectivity, numTets, xyz.data(), congruentCells);
  }
}

/// Fills connectivity (4 ids per tet) and original cell ids for a structured grid.
template <typename ConnectivityType>
void SplitStructured(const int dims[3], const int parityOrigin[3], bool fiveTets,
  ConnectivityType* connectivity, vtkIdType* originalIds)
{
  const vtkIdType cx = dims[0] - 1, cy = dims[1] - 1, cz = dims[2] - 1;
  const vtkIdType px = dims[0], pxy = static_cast<vtkIdType>(dims[0]) * dims[1];
  const int tetsPerCell = fiveTets ? 5 : 6;
  // Point ids grow with i, j and k, so every cell's smallest corner and face minima sit at the
  // same local places: the six-tet split is the same for all cells, computed once.
  int sixTets[uv::MaxTetsPerCell][4];
  const vtkIdType firstCellCorners[8] = { 0, 1, 1 + px, px, pxy, 1 + pxy, 1 + px + pxy, px + pxy };
  uv::SplitHexahedron(firstCellCorners, sixTets);
  vtkSMPTools::For(0, cx * cy * cz, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      const vtkIdType i = cell % cx, j = (cell / cx) % cy, k = cell / (cx * cy);
      const vtkIdType base = i + j * px + k * pxy;
      const vtkIdType corners[8] = { base, base + 1, base + 1 + px, base + px, base + pxy,
        base + 1 + pxy, base + 1 + px + pxy, base + px + pxy };
      const int(*split)[4] = sixTets;
      if (fiveTets)
      {
        const bool odd = ((i + j + k + parityOrigin[0] + parityOrigin[1] + parityOrigin[2]) & 1) != 0;
        split = uv::FiveTetSplit(odd);
      }
      ConnectivityType* out = connectivity + 4 * tetsPerCell * cell;
      for (int t = 0; t < tetsPerCell; ++t)
      {
        originalIds[tetsPerCell * cell + t] = cell;
        for (int v = 0; v < 4; ++v)
        {
          *out++ = static_cast<ConnectivityType>(corners[split[t][v]]);
        }
      }
    }
  });
}

/// The splits of an input's polyhedra, found before the output is sized: their tet counts vary,
/// and some add a centre point.
struct PolyhedraSplits
{
  std::vector<vtkIdType> Cells; // ascending cell ids of the polyhedra
  std::vector<uv::PolyhedronSplit<vtkIdType>> Splits;
  std::vector<vtkIdType> CentreIds; // output point id of each split's centre, or -1
  vtkIdType NumberOfCentres = 0;

  const uv::PolyhedronSplit<vtkIdType>* Find(vtkIdType cell, vtkIdType& centreId) const
  {
    const auto at = std::lower_bound(this->Cells.begin(), this->Cells.end(), cell);
    const std::size_t index = static_cast<std::size_t>(at - this->Cells.begin());
    centreId = this->CentreIds[index];
    return &this->Splits[index];
  }
};

/// The cells whose entry in `counts` is `count`, ascending.
std::vector<vtkIdType> CellsOfCount(const std::vector<vtkIdType>& counts, vtkIdType count)
{
  std::vector<vtkIdType> cells;
  for (std::size_t cell = 0; cell + 1 < counts.size(); ++cell)
  {
    if (counts[cell] == count)
    {
      cells.push_back(static_cast<vtkIdType>(cell));
    }
  }
  return cells;
}

/// Splits the given polyhedra of `input` (in parallel), then numbers the centres after the input's
/// points, in cell order.
PolyhedraSplits SplitPolyhedra(vtkDataSet* input, std::vector<vtkIdType> cells)
{
  PolyhedraSplits result;
  result.Cells = std::move(cells);
  result.Splits.resize(result.Cells.size());
  auto grid = vtkUnstructuredGrid::SafeDownCast(input);
  vtkPoints* points = grid ? grid->GetPoints() : nullptr;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  // The face streams first, one after another (VTK's face storage differs between versions; see the
  // compatibility header), then the splits in parallel.
  std::vector<std::vector<vtkIdType>> streams(result.Cells.size());
  vtkNew<vtkIdList> stream;
  for (std::size_t i = 0; grid && i < result.Cells.size(); ++i)
  {
    uvcompat::GetPolyhedronFaceStream(grid, result.Cells[i], stream);
    streams[i].assign(stream->begin(), stream->end());
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(result.Cells.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!points || streams[i].empty())
      {
        result.Splits[i].Error = "it has no face stream";
        continue;
      }
      result.Splits[i] = uv::SplitPolyhedron(streams[i].data(), streams[i].size(), numPoints,
        [points](vtkIdType id) {
          std::array<double, 3> p;
          points->GetPoint(id, p.data());
          return p;
        });
    }
  });
  result.CentreIds.assign(result.Cells.size(), -1);
  for (std::size_t i = 0; i < result.Cells.size(); ++i)
  {
    if (result.Splits[i].HasCentre && result.Splits[i].Error.empty())
    {
      result.CentreIds[i] = numPoints + result.NumberOfCentres++;
    }
  }
  return result;
}

/// One line on the polyhedra that could not be split: how many, and the first with its reason.
std::string PolyhedraError(const PolyhedraSplits& polyhedra)
{
  std::size_t failed = 0;
  std::string first;
  for (std::size_t i = 0; i < polyhedra.Cells.size(); ++i)
  {
    if (!polyhedra.Splits[i].Error.empty() && failed++ == 0)
    {
      first = "cell " + std::to_string(polyhedra.Cells[i]) + ": " + polyhedra.Splits[i].Error;
    }
  }
  if (failed == 0)
  {
    return std::string();
  }
  return "Skipped " + std::to_string(failed) + " polyhedra that cannot be split into tetrahedra " +
    "(they give no tets); the first is " + first + ".";
}

/// The output points with the polyhedra's centres appended, or `points` itself when there are none.
vtkSmartPointer<vtkPoints> AppendCentres(vtkPoints* points, const PolyhedraSplits& polyhedra)
{
  if (polyhedra.NumberOfCentres == 0)
  {
    return points;
  }
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataType(points->GetDataType());
  out->DeepCopy(points);
  // Inserted, not set: SetNumberOfPoints would reallocate without keeping the copied points.
  for (std::size_t i = 0; i < polyhedra.Cells.size(); ++i)
  {
    if (polyhedra.CentreIds[i] >= 0)
    {
      out->InsertPoint(polyhedra.CentreIds[i], polyhedra.Splits[i].Centre.data());
    }
  }
  return out;
}

/// Point data of the output: the input's, each array extended by the centres as the mean of the
/// polyhedron's vertices (vtkAbstractArray::InterpolateTuple: integers rounded, non-numeric
/// arrays take the first vertex's value).
void PassPointData(vtkPointData* in, vtkPointData* out, const PolyhedraSplits& polyhedra)
{
  if (polyhedra.NumberOfCentres == 0)
  {
    out->PassData(in);
    return;
  }
  out->DeepCopy(in);
  const vtkIdType numPoints = in->GetNumberOfTuples();
  vtkNew<vtkIdList> vertices;
  std::vector<double> weights;
  for (int a = 0; a < out->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* source = in->GetAbstractArray(a);
    vtkAbstractArray* target = out->GetAbstractArray(a);
    // Grown by the inserts below (ascending ids right after the input's), which keep the copy.
    target->Resize(numPoints + polyhedra.NumberOfCentres);
    for (std::size_t i = 0; i < polyhedra.Cells.size(); ++i)
    {
      if (polyhedra.CentreIds[i] < 0)
      {
        continue;
      }
      const std::vector<vtkIdType>& ids = polyhedra.Splits[i].Vertices;
      vertices->SetNumberOfIds(static_cast<vtkIdType>(ids.size()));
      std::copy(ids.begin(), ids.end(), vertices->GetPointer(0));
      weights.assign(ids.size(), 1.0 / static_cast<double>(ids.size()));
      target->InterpolateTuple(polyhedra.CentreIds[i], vertices, source, weights.data());
    }
  }
}

/// Writes a polyhedron's tets from its split, its centre numbered.
template <typename ConnectivityType>
void CopyPolyhedronTets(const PolyhedraSplits& polyhedra, vtkIdType cell, vtkIdType firstTet,
  ConnectivityType* connectivity, vtkIdType* originalIds)
{
  vtkIdType centreId = -1;
  const uv::PolyhedronSplit<vtkIdType>* split = polyhedra.Find(cell, centreId);
  for (std::size_t t = 0; t < split->Tets.size(); ++t)
  {
    const vtkIdType tet = firstTet + static_cast<vtkIdType>(t);
    originalIds[tet] = cell;
    for (int v = 0; v < 4; ++v)
    {
      const vtkIdType id = split->Tets[t][v];
      connectivity[4 * tet + v] =
        static_cast<ConnectivityType>(id == uv::PolyhedronSplit<vtkIdType>::CentreId ? centreId : id);
    }
  }
}

/// Fills connectivity and original cell ids for any dataset, given each cell's first tet.
template <typename ConnectivityType>
void SplitGeneric(vtkDataSet* input, const std::vector<vtkIdType>& firstTet,
  const PolyhedraSplits& polyhedra, ConnectivityType* connectivity, vtkIdType* originalIds)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  vtkSMPThreadLocalObject<vtkIdList> threadIds;
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = threadIds.Local();
    vtkIdType tets[uv::MaxTetsPerCell][4];
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      if (firstTet[cell + 1] == firstTet[cell])
      {
        continue;
      }
      if (input->GetCellType(cell) == VTK_POLYHEDRON)
      {
        CopyPolyhedronTets(polyhedra, cell, firstTet[cell], connectivity, originalIds);
        continue;
      }
      input->GetCellPoints(cell, ids);
      const int count = SplitCell(input->GetCellType(cell), ids->GetPointer(0), tets);
      for (int t = 0; t < count; ++t)
      {
        const vtkIdType tet = firstTet[cell] + t;
        originalIds[tet] = cell;
        for (int v = 0; v < 4; ++v)
        {
          connectivity[4 * tet + v] = static_cast<ConnectivityType>(tets[t][v]);
        }
      }
    }
  });
}

/// Offsets, connectivity filled by `fill(ValueType*)`, orientation fixed: a single-type cell array.
template <typename ArrayType, typename Fill>
vtkSmartPointer<vtkCellArray> BuildCells(
  vtkIdType numTets, Fill&& fill, vtkPoints* points, bool congruentCells)
{
  using ValueType = typename ArrayType::ValueType;
  vtkNew<ArrayType> offsets;
  vtkNew<ArrayType> connectivity;
  offsets->SetNumberOfValues(numTets + 1);
  connectivity->SetNumberOfValues(4 * numTets);
  ValueType* offsetData = offsets->GetPointer(0);
  vtkSMPTools::For(0, numTets + 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      offsetData[t] = static_cast<ValueType>(4 * t);
    }
  });
  fill(connectivity->GetPointer(0));
  OrientTets(connectivity->GetPointer(0), numTets, points, congruentCells);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}
/// Unstructured input: each cell's first tet (a prefix sum over the tets per cell, firstTet[numCells]
/// the total), the polyhedra's splits, and the messages owed: false with `error` when a 3D cell type
/// cannot be split; otherwise `error` names skipped polyhedra and `warning` dropped non-3D cells.
bool CountUnstructuredTets(vtkDataSet* input, int splitMode, std::vector<vtkIdType>& firstTet,
  PolyhedraSplits& polyhedra, vtkIdType& numTets, std::string& error, std::string& warning)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  std::vector<int> unsupported;
  const std::array<int, 256> tetsPerType = ClassifyCellTypes(input, splitMode, unsupported);
  if (!unsupported.empty())
  {
    error = std::string("Input has 3D cells that cannot be split (first type: ") +
      uvcompat::CellTypeName(unsupported.front()) +
      "). Linear tetrahedra, hexahedra, voxels, wedges, pyramids, pentagonal and hexagonal prisms "
      "and polyhedra are split, and the higher-order cells vtkHigherOrderSubdivision takes are subdivided "
      "first; Lagrange and Bezier pyramids are neither.";
    return false;
  }
  firstTet.resize(numCells + 1);
  input->GetCellType(0); // the first call must come from one thread
  vtkSMPTools::For(0, numCells, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      firstTet[cell] = tetsPerType[input->GetCellType(cell)];
    }
  });
  if (tetsPerType[VTK_POLYHEDRON] == VariableCell)
  {
    polyhedra = SplitPolyhedra(input, CellsOfCount(firstTet, VariableCell));
    error = PolyhedraError(polyhedra);
    for (std::size_t i = 0; i < polyhedra.Cells.size(); ++i)
    {
      firstTet[polyhedra.Cells[i]] = static_cast<vtkIdType>(polyhedra.Splits[i].Tets.size());
    }
  }
  vtkIdType dropped = 0;
  numTets = 0;
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    const vtkIdType count = firstTet[cell];
    dropped += count == 0 && tetsPerType[input->GetCellType(cell)] == DroppedCell ? 1 : 0;
    firstTet[cell] = numTets;
    numTets += count;
  }
  firstTet[numCells] = numTets;
  if (dropped > 0)
  {
    warning = "Dropped " + std::to_string(dropped) + " cells that are not 3D (vertices, lines, polygons or "
      "empty cells).";
  }
  return true;
}

/// Every input cell array copied to the cell's tets (`originalIds`: each tet's input cell).
void PassCellData(vtkCellData* inCellData, vtkCellData* outCellData, const vtkIdType* originalIds, vtkIdType numTets)
{
  if (inCellData->GetNumberOfArrays() == 0 || numTets == 0)
  {
    return;
  }
  outCellData->CopyAllocate(inCellData, numTets);
  vtkNew<vtkIdList> fromIds;
  vtkNew<vtkIdList> toIds;
  fromIds->SetNumberOfIds(numTets);
  toIds->SetNumberOfIds(numTets);
  vtkIdType* fromIdData = fromIds->GetPointer(0);
  vtkIdType* toIdData = toIds->GetPointer(0);
  vtkSMPTools::For(0, numTets, [&](vtkIdType begin, vtkIdType end) {
    std::copy(originalIds + begin, originalIds + end, fromIdData + begin);
    std::iota(toIdData + begin, toIdData + end, begin);
  });
  outCellData->CopyData(inCellData, fromIds, toIds);
}
/// True when the input holds a cell that vtkHigherOrderSubdivision must linearize first.
bool HasHigherOrderCells(vtkDataSet* input)
{
  if (!vtkUnstructuredGrid::SafeDownCast(input))
  {
    return false; // structured data sets hold linear cells only
  }
  const vtkIdType numCells = input->GetNumberOfCells();
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    if (vtkHigherOrderSubdivision::IsSubdividedCellType(input->GetCellType(cell)))
    {
      return true;
    }
  }
  return false;
}

/// Reports an inner filter's error or warning as the outer filter's own (without the inner's prefix).
void ForwardMessage(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<vtkHexahedraToTetrahedra*>(clientData);
  std::string text = callData ? static_cast<const char*>(callData) : "";
  const std::size_t prefix = text.find("): ");
  if (prefix != std::string::npos)
  {
    text = text.substr(prefix + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  if (event == vtkCommand::ErrorEvent)
  {
    vtkErrorWithObjectMacro(self, << text);
  }
  else
  {
    vtkWarningWithObjectMacro(self, << text);
  }
}
} // namespace

vtkHexahedraToTetrahedra::vtkHexahedraToTetrahedra() = default;

vtkHexahedraToTetrahedra::~vtkHexahedraToTetrahedra()
{
  this->SetFieldArrayName(nullptr);
}

int vtkHexahedraToTetrahedra::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

int vtkHexahedraToTetrahedra::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  output->Initialize();
  if (auto* cells = vtkUnstructuredGridBase::SafeDownCast(input))
  {
    const std::string broken = vtkuv::FindBrokenCellsError(cells, "The output is empty.");
    if (!broken.empty())
    {
      vtkErrorMacro(<< broken);
      return 0;
    }
  }
  return HasHigherOrderCells(input) ? this->SubdivideAndSplit(input, output) : this->SplitLinear(input, output);
}

int vtkHexahedraToTetrahedra::SubdivideAndSplit(vtkDataSet* input, vtkUnstructuredGrid* output)
{
  vtkNew<vtkHigherOrderSubdivision> subdivision;
  subdivision->SetFieldTolerance(this->FieldTolerance);
  subdivision->SetChordTolerance(this->ChordTolerance);
  subdivision->SetMaximumLevel(this->MaximumLevel);
  subdivision->SetLevel(this->Level);
  subdivision->SetFieldArrayName(this->FieldArrayName);
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback(ForwardMessage);
  subdivision->AddObserver(vtkCommand::ErrorEvent, forward);
  subdivision->AddObserver(vtkCommand::WarningEvent, forward);
  auto copy = vtkSmartPointer<vtkDataSet>::Take(input->NewInstance());
  copy->ShallowCopy(input); // the filter's own input stays out of the inner pipeline
  subdivision->SetInputData(copy);
  subdivision->Update();
  vtkUnstructuredGrid* linear = subdivision->GetOutput();
  if (linear->GetNumberOfCells() == 0)
  {
    return 1; // nothing 3D, or cells the subdivision refused (it said why)
  }
  // The subdivision's ids name the input's cells; the split's name the subdivision's.
  vtkNew<vtkIdTypeArray> inputIds;
  inputIds->DeepCopy(linear->GetCellData()->GetArray("vtkOriginalCellIds"));
  linear->GetCellData()->RemoveArray("vtkOriginalCellIds");
  if (!this->SplitLinear(linear, output))
  {
    return 0;
  }
  auto ids = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("vtkOriginalCellIds"));
  vtkIdType* idData = ids->GetPointer(0);
  const vtkIdType* inputIdData = inputIds->GetPointer(0);
  vtkSMPTools::For(0, ids->GetNumberOfValues(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      idData[t] = inputIdData[idData[t]];
    }
  });
  return 1;
}

int vtkHexahedraToTetrahedra::SplitLinear(vtkDataSet* input, vtkUnstructuredGrid* output)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  if (numCells == 0 || input->GetNumberOfPoints() == 0)
  {
    return 1; // empty in, empty out
  }

  int dims[3], parityOrigin[3];
  const bool structured = GetStructuredLayout(input, dims, parityOrigin);
  int splitMode = this->SplitMode;
  if (splitMode == FIVE_TETRAHEDRA && !structured)
  {
    vtkWarningMacro("The five-tetrahedra split needs a structured 3D input (vtkImageData, "
                    "vtkRectilinearGrid or an unblanked vtkStructuredGrid); using six tetrahedra.");
    splitMode = SIX_TETRAHEDRA;
  }

  // Tets per cell, then each cell's first tet by a prefix sum.
  std::vector<vtkIdType> firstTet;
  PolyhedraSplits polyhedra;
  vtkIdType numTets = 0;
  if (structured)
  {
    numTets = numCells * (splitMode == FIVE_TETRAHEDRA ? 5 : 6);
  }
  else
  {
    std::string error, warning;
    if (!CountUnstructuredTets(input, splitMode, firstTet, polyhedra, numTets, error, warning))
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
    }
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning);
    }
  }
  this->UpdateProgress(0.2);

  vtkSmartPointer<vtkPoints> points = AppendCentres(OutputPoints(input), polyhedra);
  this->UpdateProgress(0.4);

  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("vtkOriginalCellIds");
  originalIds->SetNumberOfValues(numTets);
  vtkIdType* originalIdData = originalIds->GetPointer(0);

  // Image data cells are translates of one another (whatever spacing or direction), so one sign
  // test orients them all.
  const bool congruentCells = vtkImageData::SafeDownCast(input) != nullptr;
  auto fill = [&](auto* connectivity) {
    if (structured)
    {
      SplitStructured(dims, parityOrigin, splitMode == FIVE_TETRAHEDRA, connectivity, originalIdData);
    }
    else
    {
      SplitGeneric(input, firstTet, polyhedra, connectivity, originalIdData);
    }
  };
  // 32-bit connectivity halves memory and bandwidth whenever the ids fit.
  const vtkIdType int32Max = std::numeric_limits<vtkTypeInt32>::max();
  vtkSmartPointer<vtkCellArray> cells =
    (points->GetNumberOfPoints() <= int32Max && 4 * numTets <= int32Max)
    ? BuildCells<vtkTypeInt32Array>(numTets, fill, points, congruentCells)
    : BuildCells<vtkTypeInt64Array>(numTets, fill, points, congruentCells);
  this->UpdateProgress(0.8);

  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  PassPointData(input->GetPointData(), output->GetPointData(), polyhedra);
  output->GetFieldData()->PassData(input->GetFieldData());
  PassCellData(input->GetCellData(), output->GetCellData(), originalIdData, numTets);
  output->GetCellData()->AddArray(originalIds);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHexahedraToTetrahedra::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SplitMode: " << (this->SplitMode == FIVE_TETRAHEDRA ? "FiveTetrahedra" : "SixTetrahedra")
     << "\n";
  os << indent << "FieldTolerance: " << this->FieldTolerance << "\n";
  os << indent << "ChordTolerance: " << this->ChordTolerance << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "FieldArrayName: " << (this->FieldArrayName ? this->FieldArrayName : "(every array)") << "\n";
  os << indent << "Level: " << this->Level << "\n";
}
