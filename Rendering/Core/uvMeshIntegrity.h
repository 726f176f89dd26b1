// What a mesh read from a file must satisfy before anything indexes through it: every cell's point
// ids name existing points, a cell of a fixed-size type has that many, the offsets into the id list
// rise and stay inside it, and every point's coordinates are finite. Every later step (bounds,
// sorting, splitting, uploading) reads points by those ids and orders cells by those coordinates, so
// one scan when the cells or points change turns a file's corruption into one error instead of a
// crash, a hang or a silently wrong image. VTK-free.
#ifndef uvMeshIntegrity_h
#define uvMeshIntegrity_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>

namespace uv
{

/// The first broken cell found (the lowest-numbered) and how many there are.
struct BrokenCells
{
  enum class Fault
  {
    None,
    Offsets,      // its offsets fall or leave the id list: its ids cannot be read
    PointCount,   // fewer or more ids than its type has
    IdOutOfRange, // an id outside [0, number of points)
    FaceStream,   // a polyhedron's faces: fewer than promised, or an id outside [0, number of
                  // points)
  };
  std::int64_t Count = 0;
  std::int64_t FirstCell = -1;
  Fault FirstFault = Fault::None;
  std::int64_t FirstIdCount = 0;  // the first broken cell's number of ids
  std::int64_t FirstExpected = 0; // what its type has (PointCount)
  std::int64_t FirstBadId = 0;    // the id out of range (IdOutOfRange)
  explicit operator bool() const { return this->Count > 0; }

  /// Adds another range's findings (ranges may finish in any order).
  void Merge(const BrokenCells& other)
  {
    if (other.Count == 0)
      return;
    if (this->Count == 0 || other.FirstCell < this->FirstCell)
    {
      const std::int64_t count = this->Count;
      *this = other;
      this->Count += count;
      return;
    }
    this->Count += other.Count;
  }
};

/// Point counts per cell type (0: any count), indexed by the type's number.
using PointCountsByType = std::array<std::int64_t, 256>;

/// Checks cells [begin, end) of a cell array: offset(c) .. offset(c + 1) index id(k), k < idCount.
template <typename Offset, typename Id, typename Type>
BrokenCells FindBrokenCellsIn(std::int64_t begin, std::int64_t end, std::int64_t pointCount,
  std::int64_t idCount, const Offset& offset, const Id& id, const Type& type, const PointCountsByType& expected)
{
  BrokenCells found;
  for (std::int64_t c = begin; c < end; ++c)
  {
    const std::int64_t first = offset(c), last = offset(c + 1);
    BrokenCells cell;
    cell.FirstCell = c;
    cell.FirstIdCount = last - first;
    if (first < 0 || last < first || last > idCount)
    {
      cell.FirstFault = BrokenCells::Fault::Offsets;
    }
    else if (expected[type(c) & 0xff] != 0 && last - first != expected[type(c) & 0xff])
    {
      cell.FirstFault = BrokenCells::Fault::PointCount;
      cell.FirstExpected = expected[type(c) & 0xff];
    }
    else
    {
      for (std::int64_t k = first; k < last; ++k)
      {
        const std::int64_t point = id(k);
        if (point < 0 || point >= pointCount)
        {
          cell.FirstFault = BrokenCells::Fault::IdOutOfRange;
          cell.FirstBadId = point;
          break;
        }
      }
    }
    if (cell.FirstFault != BrokenCells::Fault::None)
    {
      cell.Count = 1;
      found.Merge(cell);
    }
  }
  return found;
}

/// Every cell, the ranges split by `parallelFor(count, function(begin, end))`.
template <typename Offset, typename Id, typename Type, typename ParallelFor>
BrokenCells FindBrokenCells(std::int64_t cellCount, std::int64_t pointCount, std::int64_t idCount,
  const Offset& offset, const Id& id, const Type& type, const PointCountsByType& expected, ParallelFor&& parallelFor)
{
  BrokenCells found;
  std::mutex merging;
  parallelFor(static_cast<std::size_t>(cellCount), [&](std::size_t begin, std::size_t end) {
    const BrokenCells part = FindBrokenCellsIn(static_cast<std::int64_t>(begin), static_cast<std::int64_t>(end),
      pointCount, idCount, offset, id, type, expected);
    std::lock_guard<std::mutex> lock(merging);
    found.Merge(part);
  });
  return found;
}

/// Whether a polyhedron's face stream (number of faces, then each face's point count and ids) holds
/// the faces it promises, every id in [0, pointCount): whether it can be read. A readable stream may
/// still not bound a solid (a face of two points, faces that do not close): the split skips those
/// polyhedra with its own error.
template <typename Stream>
bool FaceStreamSound(const Stream& stream, std::int64_t length, std::int64_t pointCount)
{
  if (length < 1 || stream(0) < 0)
    return false;
  std::int64_t at = 1;
  for (std::int64_t f = 0; f < stream(0); ++f)
  {
    if (at >= length)
      return false;
    const std::int64_t count = stream(at++);
    if (count < 0 || at + count > length)
      return false;
    for (std::int64_t k = 0; k < count; ++k, ++at)
      if (stream(at) < 0 || stream(at) >= pointCount)
        return false;
  }
  return at == length;
}

/// The lowest-numbered point with a non-finite coordinate, and how many there are.
struct NonFinitePoints
{
  std::int64_t Count = 0;
  std::int64_t First = -1;
  explicit operator bool() const { return this->Count > 0; }
};

/// Points [0, pointCount) of `coordinates` (x, y, z interleaved, float or double).
template <typename Real, typename ParallelFor>
NonFinitePoints FindNonFinitePoints(const Real* coordinates, std::int64_t pointCount, ParallelFor&& parallelFor)
{
  NonFinitePoints found;
  std::mutex merging;
  parallelFor(static_cast<std::size_t>(pointCount), [&](std::size_t begin, std::size_t end) {
    NonFinitePoints part;
    for (std::size_t p = begin; p < end; ++p)
    {
      const Real* xyz = coordinates + 3 * p;
      if (!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
      {
        part.First = part.Count == 0 ? static_cast<std::int64_t>(p) : part.First;
        ++part.Count;
      }
    }
    std::lock_guard<std::mutex> lock(merging);
    if (part.Count > 0 && (found.Count == 0 || part.First < found.First))
      found.First = part.First;
    found.Count += part.Count;
  });
  return found;
}

/// The GPU programs address points, cells and their texels with GLSL's int (texelFetch's coordinate,
/// gl_VertexID), which is 32-bit and signed: a larger index would wrap and read another cell.
constexpr std::int64_t LargestGPUIndex = std::numeric_limits<std::int32_t>::max();

/// Whether `count` items addressed by `indicesPerItem` consecutive indices each (a tetrahedron's four
/// corner ids, a hexahedron's eight) keep every index within LargestGPUIndex.
constexpr bool IndicesFitGPU(std::int64_t count, std::int64_t indicesPerItem)
{
  return count >= 0 && indicesPerItem > 0 && count <= (LargestGPUIndex + 1) / indicesPerItem;
}

} // namespace uv

#endif
