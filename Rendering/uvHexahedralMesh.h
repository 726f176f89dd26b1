// The connectivity of a hexahedral mesh as vtkHexahedralRayCastMapper's passes walk it, free of VTK:
// face adjacency and boundary faces from the cells' point ids, the cells whose map folds, and the cell
// holding a point (where rays start when the eye is inside the mesh). Cells are 8 point ids each in
// VTK's hexahedron order; points are 4 floats each (recentred position, normalised scalar).
#ifndef uvHexahedralMesh_h
#define uvHexahedralMesh_h

#include "uvHexahedronRay.h"
#include "uvLinearCellSplit.h"
#include "uvRayCellGeometry.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace uv
{

/// The corners of hexahedron `cell` in double.
inline void HexahedronCornerPoints(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, std::size_t cell, glm::dvec3 p[8])
{
  for (int k = 0; k < 8; ++k)
  {
    const float* x = &pointData[4 * static_cast<std::size_t>(cellPoints[8 * cell + k])];
    p[k] = glm::dvec3(x[0], x[1], x[2]);
  }
}

/// A face by its sorted point ids, and which cell's local face it is (cell * 8 + face).
struct HexahedronFaceRecord
{
  std::array<std::uint32_t, 4> Key;
  std::uint32_t CellFace;
  bool operator<(const HexahedronFaceRecord& other) const
  {
    return this->Key < other.Key || (this->Key == other.Key && this->CellFace < other.CellFace);
  }
};

struct HexahedralFaces
{
  std::vector<std::int32_t> Neighbours; // 8 per cell (6 used): neighbour * 8 + its local face, or -1
  std::vector<std::int32_t> Boundary;   // 4 per boundary face: cell, local face, 0, 0
};

/// Which cells share each face (uv::HexahedronFaces numbering): a face two cells share joins them;
/// any other (a boundary face, or a non-manifold one, every copy) is a boundary face. Faces are
/// matched by sorting them by their sorted point ids: `parallelFor(count, function(begin, end))` lists
/// them, `sort(begin, end)` orders HexahedronFaceRecords, and `progress(fraction)` is told 0.5 once
/// they are listed and 1 once sorted.
template <typename ParallelFor, typename Sort, typename Progress>
HexahedralFaces MakeHexahedralFaces(
  const std::vector<std::uint32_t>& cellPoints, ParallelFor&& parallelFor, Sort&& sort, Progress&& progress)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  std::vector<HexahedronFaceRecord> faces(6 * cellCount);
  parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      for (int f = 0; f < 6; ++f)
      {
        HexahedronFaceRecord& record = faces[6 * c + f];
        for (int k = 0; k < 4; ++k)
          record.Key[k] = cellPoints[8 * c + HexahedronFaces[f].Vertices[k]];
        std::sort(record.Key.begin(), record.Key.end());
        record.CellFace = static_cast<std::uint32_t>(8 * c + f);
      }
  });
  progress(0.5);
  sort(faces.begin(), faces.end());
  progress(1.0);
  HexahedralFaces result;
  result.Neighbours.assign(8 * cellCount, -1);
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].Key == faces[i].Key)
      ++j;
    if (j - i == 2)
    {
      const std::uint32_t a = faces[i].CellFace, b = faces[i + 1].CellFace;
      result.Neighbours[a] = static_cast<std::int32_t>(b);
      result.Neighbours[b] = static_cast<std::int32_t>(a);
    }
    else
    {
      for (std::size_t k = i; k < j; ++k)
      {
        const std::uint32_t cellFace = faces[k].CellFace;
        result.Boundary.insert(result.Boundary.end(),
          { static_cast<std::int32_t>(cellFace / 8), static_cast<std::int32_t>(cellFace % 8), 0, 0 });
      }
    }
    i = j;
  }
  return result;
}

/// How many cells fold over themselves (uv::IsTangledHexahedron); `parallelFor` as above.
template <typename ParallelFor>
std::size_t CountTangledHexahedra(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, ParallelFor&& parallelFor)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  std::vector<unsigned char> tangled(cellCount, 0);
  parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
    glm::dvec3 p[8];
    for (std::size_t c = begin; c < end; ++c)
    {
      HexahedronCornerPoints(cellPoints, pointData, c, p);
      tangled[c] = IsTangledHexahedron(p) ? 1 : 0;
    }
  });
  return static_cast<std::size_t>(std::count(tangled.begin(), tangled.end(), 1));
}

/// The first cell holding `x` (by its bounding box, then the isoparametric inverse), or -1.
inline int HexahedronHolding(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, const glm::dvec3& x)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    glm::dvec3 p[8];
    HexahedronCornerPoints(cellPoints, pointData, c, p);
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (int k = 0; k < 8; ++k)
    {
      low = glm::min(low, p[k]);
      high = glm::max(high, p[k]);
    }
    if (glm::any(glm::lessThan(x, low)) || glm::any(glm::greaterThan(x, high)))
      continue;
    glm::dvec3 xi(0.5);
    if (InverseTrilinear(p, x, xi) && InUnitCube(xi, 1e-9))
      return static_cast<int>(c);
  }
  return -1;
}

} // namespace uv

#endif
