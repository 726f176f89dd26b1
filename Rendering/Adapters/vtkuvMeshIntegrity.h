// The mesh checks of uvMeshIntegrity.h on a VTK grid: the one error a mapper, the reference or a
// filter gives for a mesh whose ids or coordinates cannot be used, before anything reads through them.
#ifndef vtkuvMeshIntegrity_h
#define vtkuvMeshIntegrity_h

#include "uvMeshIntegrity.h"
#include "vtkUnstructuredVolumeCompatibility.h"

#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridBase.h"

#include <cstdint>
#include <functional>
#include <new>
#include <sstream>
#include <string>

namespace vtkuv
{
namespace integrity
{

inline void ParallelFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
    function(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
  });
}

/// How many points each cell type has: VTK's own cell of that type says, where the number is fixed
/// (a new vtkHexahedron holds 8 ids; a polygon or polyhedron holds none: any number will do). The
/// arbitrary-order types (from VTK_HIGHER_ORDER_EDGE on: Lagrange, Bezier) take any number, whatever
/// their new instances hold.
inline uv::PointCountsByType PointCountsOfTypes()
{
  uv::PointCountsByType counts{};
  for (int type = 1; type < VTK_HIGHER_ORDER_EDGE; ++type)
  {
    vtkCell* instance = vtkGenericCell::InstantiateCell(type);
    if (instance)
    {
      counts[type] = instance->GetNumberOfPoints();
      instance->Delete();
    }
  }
  return counts;
}

/// `array` as a plain array of ArrayT (vtkTypeInt64Array for ids, vtkUnsignedCharArray for types):
/// itself where it is one, else a copy (32-bit ids, VTK 9.6's implicit arrays).
template <typename ArrayT>
vtkSmartPointer<ArrayT> AsPlain(vtkDataArray* array)
{
  if (auto* plain = ArrayT::FastDownCast(array))
    return plain;
  auto copy = vtkSmartPointer<ArrayT>::New();
  copy->DeepCopy(array);
  if (copy->GetNumberOfValues() != array->GetNumberOfValues())
    throw std::bad_alloc(); // VTK reports a failed allocation and leaves the array empty
  return copy;
}

inline uv::BrokenCells FindBrokenCells(vtkUnstructuredGridBase* input)
{
  static const uv::PointCountsByType expected = PointCountsOfTypes();
  const std::int64_t cells = input->GetNumberOfCells(), points = input->GetNumberOfPoints();
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (grid && grid->GetCells() && uvcompat::CellTypesArray(grid))
  {
    vtkCellArray* array = grid->GetCells();
    const auto offsets = AsPlain<vtkTypeInt64Array>(array->GetOffsetsArray());
    const auto ids = AsPlain<vtkTypeInt64Array>(array->GetConnectivityArray());
    const auto types = AsPlain<vtkUnsignedCharArray>(uvcompat::CellTypesArray(grid));
    if (offsets->GetNumberOfValues() < cells + 1 || types->GetNumberOfValues() < cells)
    {
      uv::BrokenCells all;
      all.Count = cells;
      all.FirstCell = 0;
      all.FirstFault = uv::BrokenCells::Fault::Offsets;
      return all;
    }
    const vtkTypeInt64* offset = offsets->GetPointer(0);
    const vtkTypeInt64* id = ids->GetPointer(0);
    const unsigned char* type = types->GetPointer(0);
    return uv::FindBrokenCells(
      cells, points, ids->GetNumberOfValues(), [offset](std::int64_t c) { return offset[c]; },
      [id](std::int64_t k) { return id[k]; }, [type](std::int64_t c) { return type[c]; }, expected, ParallelFor);
  }
  // Another kind of grid hands out its cells one at a time: each cell's ids as an id list of its own.
  uv::BrokenCells found;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    input->GetCellPoints(c, ids);
    const std::int64_t count = ids->GetNumberOfIds();
    const vtkIdType* id = ids->GetPointer(0);
    const int type = input->GetCellType(c);
    found.Merge(uv::FindBrokenCellsIn(
      c, c + 1, points, count, [c, count](std::int64_t cell) { return cell == c ? 0 : count; },
      [id](std::int64_t k) { return id[k]; }, [type](std::int64_t) { return type; }, expected));
  }
  return found;
}

/// The polyhedra whose face streams cannot be read (uv::FaceStreamSound), each counted as a broken
/// cell: VTK's own polyhedron functions read a stream as far as it promises.
inline uv::BrokenCells FindBrokenPolyhedra(vtkUnstructuredGridBase* input)
{
  uv::BrokenCells found;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!grid)
    return found;
  const std::int64_t points = input->GetNumberOfPoints();
  vtkNew<vtkIdList> stream;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) != VTK_POLYHEDRON)
      continue;
    uvcompat::GetPolyhedronFaceStream(grid, c, stream);
    const vtkIdType* ids = stream->GetPointer(0);
    if (uv::FaceStreamSound([ids](std::int64_t k) { return static_cast<std::int64_t>(ids[k]); },
          stream->GetNumberOfIds(), points))
      continue;
    uv::BrokenCells cell;
    cell.Count = 1;
    cell.FirstCell = c;
    cell.FirstFault = uv::BrokenCells::Fault::FaceStream;
    cell.FirstIdCount = stream->GetNumberOfIds();
    found.Merge(cell);
  }
  return found;
}

inline uv::NonFinitePoints FindNonFinitePoints(vtkPoints* points)
{
  vtkDataArray* data = points ? points->GetData() : nullptr;
  if (!data || data->GetNumberOfTuples() == 0)
    return {};
  if (data->GetDataType() == VTK_FLOAT && data->HasStandardMemoryLayout())
    return uv::FindNonFinitePoints(
      static_cast<const float*>(data->GetVoidPointer(0)), data->GetNumberOfTuples(), ParallelFor);
  if (data->GetDataType() == VTK_DOUBLE && data->HasStandardMemoryLayout())
    return uv::FindNonFinitePoints(
      static_cast<const double*>(data->GetVoidPointer(0)), data->GetNumberOfTuples(), ParallelFor);
  return {}; // integer coordinates are finite
}

inline const char* Describe(uv::BrokenCells::Fault fault)
{
  switch (fault)
  {
    case uv::BrokenCells::Fault::Offsets:
      return "its offsets into the connectivity array fall or run past its end";
    case uv::BrokenCells::Fault::PointCount:
      return "it has the wrong number of point ids for its type";
    case uv::BrokenCells::Fault::IdOutOfRange:
      return "it names a point that does not exist";
    case uv::BrokenCells::Fault::FaceStream:
      return "its face stream holds fewer faces than it promises, or names a point that does not exist";
    default:
      return "";
  }
}

} // namespace integrity

/// An error naming the cells whose ids cannot be read or name no point, ending in `consequence`;
/// empty where there are none.
inline std::string FindBrokenCellsError(vtkUnstructuredGridBase* input, const char* consequence)
{
  uv::BrokenCells broken;
  try
  {
    broken = integrity::FindBrokenCells(input);
  }
  catch (const std::bad_alloc&)
  {
    return std::string("host memory ran out checking the input mesh's cells. ") + consequence;
  }
  if (!broken)
    broken = integrity::FindBrokenPolyhedra(input); // their ids are sound: their streams can be read
  if (!broken)
    return std::string();
  std::ostringstream error;
  error << "the input mesh is broken: " << broken.Count << " of " << input->GetNumberOfCells()
        << " cells cannot be read. The first, cell " << broken.FirstCell << " ("
        << uvcompat::CellTypeName(input->GetCellType(broken.FirstCell)) << ", " << broken.FirstIdCount
        << (broken.FirstFault == uv::BrokenCells::Fault::FaceStream ? " face stream entries): " : " point ids): ")
        << integrity::Describe(broken.FirstFault);
  if (broken.FirstFault == uv::BrokenCells::Fault::PointCount)
    error << " (" << broken.FirstExpected << ")";
  if (broken.FirstFault == uv::BrokenCells::Fault::IdOutOfRange)
    error << " (" << broken.FirstBadId << "; the mesh has " << input->GetNumberOfPoints() << " points)";
  error << ". " << consequence;
  return error.str();
}

/// An error naming the points with NaN or infinite coordinates, ending in `consequence`; empty where
/// there are none.
inline std::string FindNonFinitePointsError(vtkUnstructuredGridBase* input, const char* consequence)
{
  const uv::NonFinitePoints nonFinite = integrity::FindNonFinitePoints(input->GetPoints());
  if (!nonFinite)
    return std::string();
  double xyz[3];
  input->GetPoint(nonFinite.First, xyz);
  std::ostringstream error;
  error << "the input mesh has " << nonFinite.Count << " points with NaN or infinite coordinates, the first point "
        << nonFinite.First << " at (" << xyz[0] << ", " << xyz[1] << ", " << xyz[2]
        << "); remove them and their cells. " << consequence;
  return error.str();
}

/// What makes the mesh unusable for rendering (either of the above), or an empty string; `cells` and
/// `points` say which of the two changed since the last check (a time step may move points only).
inline std::string FindMeshIntegrityError(vtkUnstructuredGridBase* input, bool cells = true, bool points = true)
{
  const char* consequence = "Nothing is drawn.";
  std::string error = cells ? FindBrokenCellsError(input, consequence) : std::string();
  return error.empty() && (cells || points) ? FindNonFinitePointsError(input, consequence) : error;
}

/// The error for a mesh whose `count` `what` (a mapper's points, tetrahedra or cells, each addressed
/// by `indicesPerItem` indices) do not fit the GPU programs' 32-bit indices, or an empty string.
inline std::string IndexRangeError(const char* what, std::int64_t count, std::int64_t indicesPerItem)
{
  if (uv::IndicesFitGPU(count, indicesPerItem))
    return std::string();
  std::ostringstream error;
  error << "the mesh has " << count << " " << what << ", more than the " << (uv::LargestGPUIndex + 1) / indicesPerItem
        << " the GPU programs' 32-bit indices address; render it in parts (for example on several ranks). "
           "Nothing is drawn.";
  return error.str();
}

} // namespace vtkuv

#endif
